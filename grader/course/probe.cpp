/* probe.cpp: the grader's side of a submission's program. Built with the submission's
   physics.cpp (and its headers, or the project's course API headers), run in the sandbox.

   It reads commands on standard input and answers on standard output, numbers in "%.17g"
   (they read back exactly):
     W <world file text>   the world, in the course's .w format (readWorld's order)
     S <1024 lines x y z>  the state: 512 positions, then 512 velocities, lattice order
     A                     prints the 512 accelerations computeAcceleration gives at the state
     E N / R N             N steps of Euler / RK4
     P                     prints the 512 positions and the 512 velocities
     T N                   N steps of RK4, then prints the microseconds a step took
   It trusts nothing about the submission: output is flushed after every answer, so what was
   answered before a crash stays answered; and what the submission itself prints (a printf left
   from debugging) goes to /dev/null, not into the answers. Exit status 3: a command it could
   not read. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "jello.h"
#include "physics.h"

/* The course's jello.cpp defines the world; a submission may too. */
__attribute__((weak)) struct world jello;

static FILE* answers; /* the grader's end of standard output */

static void refuse(const char* what) {
  fprintf(stderr, "probe: cannot read %s\n", what);
  exit(3);
}

static void readPoints(struct point points[8][8][8], const char* what) {
  for (int i = 0; i < 8; i++)
    for (int j = 0; j < 8; j++)
      for (int k = 0; k < 8; k++) {
        struct point* q = &points[i][j][k];
        if (scanf("%lf %lf %lf", &q->x, &q->y, &q->z) != 3) refuse(what);
      }
}

static void readWorldCommand(void) {
  struct world* w = &jello;
  if (scanf("%9s", w->integrator) != 1) refuse("the integrator");
  if (scanf("%lf %d", &w->dt, &w->n) != 2) refuse("dt n");
  if (scanf("%lf %lf %lf %lf", &w->kElastic, &w->dElastic, &w->kCollision, &w->dCollision) != 4)
    refuse("the spring constants");
  if (scanf("%lf", &w->mass) != 1) refuse("the mass");
  if (scanf("%d", &w->incPlanePresent) != 1) refuse("the plane flag");
  if (w->incPlanePresent == 1 && scanf("%lf %lf %lf %lf", &w->a, &w->b, &w->c, &w->d) != 4)
    refuse("the plane");
  if (scanf("%d", &w->resolution) != 1 || w->resolution < 0 || w->resolution > 64)
    refuse("the resolution");
  free(w->forceField);
  int nodes = w->resolution * w->resolution * w->resolution;
  /* As the course's input code: malloc of the nodes, R = 0 included. */
  w->forceField = (struct point*)malloc(sizeof(struct point) * (size_t)nodes);
  for (int n = 0; n < nodes; n++) {
    struct point* f = &w->forceField[n];
    if (scanf("%lf %lf %lf", &f->x, &f->y, &f->z) != 3) refuse("the field");
  }
  readPoints(w->p, "the positions");
  readPoints(w->v, "the velocities");
}

static void printPoints(struct point points[8][8][8]) {
  for (int i = 0; i < 8; i++)
    for (int j = 0; j < 8; j++)
      for (int k = 0; k < 8; k++)
        fprintf(answers, "%.17g %.17g %.17g\n", points[i][j][k].x, points[i][j][k].y,
                points[i][j][k].z);
}

static long readCount(void) {
  long n = 0;
  if (scanf("%ld", &n) != 1 || n < 0) refuse("a step count");
  return n;
}

static double secondsNow(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static struct point accelerations[8][8][8];

int main(void) {
  char command[4];
  answers = fdopen(dup(1), "w");
  if (!answers || !freopen("/dev/null", "w", stdout)) return 4;
  while (scanf("%3s", command) == 1) {
    if (strcmp(command, "W") == 0) {
      readWorldCommand();
    } else if (strcmp(command, "S") == 0) {
      readPoints(jello.p, "the positions");
      readPoints(jello.v, "the velocities");
    } else if (strcmp(command, "A") == 0) {
      memset(accelerations, 0, sizeof accelerations);
      computeAcceleration(&jello, accelerations);
      printPoints(accelerations);
    } else if (strcmp(command, "E") == 0 || strcmp(command, "R") == 0) {
      long steps = readCount();
      for (long s = 0; s < steps; s++) {
        if (command[0] == 'E')
          Euler(&jello);
        else
          RK4(&jello);
      }
      fprintf(answers, "ok\n");
    } else if (strcmp(command, "P") == 0) {
      printPoints(jello.p);
      printPoints(jello.v);
    } else if (strcmp(command, "T") == 0) {
      long steps = readCount();
      double start = secondsNow();
      for (long s = 0; s < steps; s++) RK4(&jello);
      fprintf(answers, "%.17g\n", steps > 0 ? 1e6 * (secondsNow() - start) / (double)steps : 0.0);
    } else {
      refuse("a command");
    }
    fflush(answers);
  }
  return 0;
}
