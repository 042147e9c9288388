/* showCube.cpp: draws the cube's points and springs, in the course starter's shape. */
#include "jello.h"
#include "showCube.h"

static void drawSpring(struct point a, struct point b)
{
  glBegin(GL_LINES);
  glVertex3f(a.x, a.y, a.z);
  glVertex3f(b.x, b.y, b.z);
  glEnd();
}

void showCube(struct world * jello)
{
  if (viewingMode == 0)
  {
    glDisable(GL_LIGHTING);
    glPointSize(5);
    glBegin(GL_POINTS);
    for (int i = 0; i <= 7; i++)
      for (int j = 0; j <= 7; j++)
        for (int k = 0; k <= 7; k++)
          glVertex3f(jello->p[i][j][k].x, jello->p[i][j][k].y, jello->p[i][j][k].z);
    glEnd();
    for (size_t s = 0; s < springs.size(); s++)
    {
      const Spring & sp = springs[s];
      if (!structural && sp.rest < 0.15) continue;
      drawSpring(jello->p[sp.i1][sp.j1][sp.k1], jello->p[sp.i2][sp.j2][sp.k2]);
    }
    glEnable(GL_LIGHTING);
  }
  else
  {
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    GLfloat diffuse[] = {0.9f, 0.2f, 0.2f, 1.0f};
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
  }
}

void showBoundingBox()
{
  glColor4f(0.6, 0.6, 0.6, 0);
  glBegin(GL_LINES);
  for (int i = -2; i <= 2; i++)
  {
    glVertex3f(i, -2, -2);
    glVertex3f(i, -2, 2);
    glVertex3f(-2, i, -2);
    glVertex3f(2, i, -2);
  }
  glEnd();
}
