/* jello.h: the course's header as students keep it (a fixture of the grader's tests, written
   for this project in the course starter's shape): GL and the picture library first, the
   viewer's globals (among them `int pause`, which clashes with pause(2) of <unistd.h>), the
   course's structs and vector macros, and this student's own spring list. */
#ifndef _JELLO_H_
#define _JELLO_H_

#include "openGL-headers.h"
#include "pic.h"

#include <stdio.h>
#include <stdlib.h>
#include <math.h>
#include <string.h>
#include <vector>

#define pi 3.141592653589793238462643383279

extern double Theta;
extern double Phi;
extern double R;
extern int sprite;
extern int g_vMousePos[2];
extern int g_iLeftMouseButton, g_iMiddleMouseButton, g_iRightMouseButton;

struct point
{
  double x;
  double y;
  double z;
};

extern int shear, bend, structural, pause, viewingMode, saveScreenToFile;

struct world
{
  char integrator[10];
  double dt;
  int n;
  double kElastic;
  double dElastic;
  double kCollision;
  double dCollision;
  double mass;
  int incPlanePresent;
  double a, b, c, d;
  int resolution;
  struct point * forceField;
  struct point p[8][8][8];
  struct point v[8][8][8];
};

extern struct world jello;

/* One spring of the cube: the two lattice points and the rest length. */
struct Spring
{
  int i1, j1, k1, i2, j2, k2;
  double rest;
};
extern std::vector<Spring> springs;
void buildSprings();

#define CROSSPRODUCTp(vector1,vector2,dest)\
  (dest).x = (vector1).y * (vector2).z - (vector2).y * (vector1).z;\
  (dest).y = (vector2).x * (vector1).z - (vector1).x * (vector2).z;\
  (dest).z = (vector1).x * (vector2).y - (vector2).x * (vector1).y

#define pDIFFERENCE(vector1,vector2,dest)\
  (dest).x = (vector1).x - (vector2).x;\
  (dest).y = (vector1).y - (vector2).y;\
  (dest).z = (vector1).z - (vector2).z;

#define pSUM(vector1,vector2,dest)\
  (dest).x = (vector1).x + (vector2).x;\
  (dest).y = (vector1).y + (vector2).y;\
  (dest).z = (vector1).z + (vector2).z;

#define pMULTIPLY(src,scalar,dest)\
  (dest).x = (src).x * (scalar);\
  (dest).y = (src).y * (scalar);\
  (dest).z = (src).z * (scalar);

#endif
