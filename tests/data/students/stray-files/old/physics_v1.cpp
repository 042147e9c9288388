/* physics_v1.cpp: the student's first attempt, kept beside the real one: it defines the same
   functions, and is not part of the program. */
#include "../jello.h"

void computeAcceleration(struct world * jello, struct point a[8][8][8])
{
  for (int i = 0; i <= 7; i++)
    for (int j = 0; j <= 7; j++)
      for (int k = 0; k <= 7; k++)
        a[i][j][k].x = a[i][j][k].y = a[i][j][k].z = 0;
}

void Euler(struct world * jello) {}
void RK4(struct world * jello) {}
