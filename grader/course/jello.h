/* jello.h: the course API of the jello cube assignment, for grading headless.

   The grader builds a submission's physics.cpp against the submission's own jello.h when that
   header compiles without a window system, and against this one otherwise. This header holds
   what a physics.cpp relies on: the layout of struct world and struct point as the course's
   input code fills them, the vector macros with the course's semantics, the global world
   `jello`, and the C headers the course's jello.h brings in. It has no GL.

   Units: metres, seconds, kilograms, newtons. Lattice point p[i][j][k] has index (i,j,k) on
   the axes (x,y,z); the cube at rest has p[i][j][k] = (i,j,k)/7. The force field holds
   resolution^3 nodes, node (i,j,k) at forceField[i*R*R + j*R + k], at
   (-2 + 4i/(R-1), -2 + 4j/(R-1), -2 + 4k/(R-1)). */
#ifndef JELLO_COURSE_JELLO_H
#define JELLO_COURSE_JELLO_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define pi 3.141592653589793238462643383279

struct point {
  double x;
  double y;
  double z;
};

struct world {
  char integrator[10]; /* "RK4" or "Euler" */
  double dt;           /* s */
  int n;               /* steps per drawn frame */
  double kElastic;     /* N/m, cube springs */
  double dElastic;     /* N s/m */
  double kCollision;   /* N/m, walls and plane */
  double dCollision;   /* N s/m */
  double mass;         /* kg, each of the 512 points */
  int incPlanePresent; /* 1: the plane a x + b y + c z + d = 0 exists */
  double a, b, c, d;
  int resolution;           /* R: the field has R^3 nodes; 0: no field */
  struct point* forceField; /* newtons, R^3 nodes */
  struct point p[8][8][8];  /* positions, m */
  struct point v[8][8][8];  /* velocities, m/s */
};

extern struct world jello;

/* The course's vector macros. Each is a sequence of statements, not an expression, exactly as
   students use them: pSUM(a, b, c); sets c = a + b. */
#define CROSSPRODUCT(x1, y1, z1, x2, y2, z2, x, y, z) \
  x = (y1) * (z2) - (y2) * (z1);                      \
  y = (x2) * (z1) - (x1) * (z2);                      \
  z = (x1) * (y2) - (x2) * (y1)

#define CROSSPRODUCTp(vector1, vector2, dest)                                                \
  CROSSPRODUCT((vector1).x, (vector1).y, (vector1).z, (vector2).x, (vector2).y, (vector2).z, \
               (dest).x, (dest).y, (dest).z)

#define pNORMALIZE(dest)                                                       \
  {                                                                            \
    double pNormalizeLength =                                                  \
        sqrt((dest).x * (dest).x + (dest).y * (dest).y + (dest).z * (dest).z); \
    (dest).x /= pNormalizeLength;                                              \
    (dest).y /= pNormalizeLength;                                              \
    (dest).z /= pNormalizeLength;                                              \
  }

#define pCPY(source, dest) \
  (dest).x = (source).x;   \
  (dest).y = (source).y;   \
  (dest).z = (source).z;

#define pSUM(vector1, vector2, dest)    \
  (dest).x = (vector1).x + (vector2).x; \
  (dest).y = (vector1).y + (vector2).y; \
  (dest).z = (vector1).z + (vector2).z;

#define pDIFFERENCE(vector1, vector2, dest) \
  (dest).x = (vector1).x - (vector2).x;     \
  (dest).y = (vector1).y - (vector2).y;     \
  (dest).z = (vector1).z - (vector2).z;

#define pMULTIPLY(src, scalar, dest) \
  (dest).x = (src).x * (scalar);     \
  (dest).y = (src).y * (scalar);     \
  (dest).z = (src).z * (scalar);

#endif
