/* physics.h: the three functions of the course API that the grader calls.

   computeAcceleration writes into a the acceleration (m/s^2) of every point of *jello at its
   positions p and velocities v; Euler and RK4 each advance *jello by one step of jello->dt. */
#ifndef JELLO_COURSE_PHYSICS_H
#define JELLO_COURSE_PHYSICS_H

void computeAcceleration(struct world* jello, struct point a[8][8][8]);
void Euler(struct world* jello);
void RK4(struct world* jello);

#endif
