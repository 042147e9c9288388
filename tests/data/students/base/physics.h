#ifndef _PHYSICS_H_
#define _PHYSICS_H_

void computeAcceleration(struct world * jello, struct point a[8][8][8]);
void Euler(struct world * jello);
void RK4(struct world * jello);

#endif
