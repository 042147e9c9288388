/* physics.cpp: the forces and the integrators, on the spring list jello.cpp's main() builds
   (a fixture of the grader's tests, in the shape of a student's solution). */
#include "jello.h"
#include "physics.h"

static void springForce(double k, double d, double rest, struct point pa, struct point pb,
                        struct point va, struct point vb, struct point * force)
{
  struct point L, dv;
  pDIFFERENCE(pa, pb, L);
  double length = sqrt(L.x * L.x + L.y * L.y + L.z * L.z);
  force->x = force->y = force->z = 0;
  if (length == 0)
    return;
  pDIFFERENCE(va, vb, dv);
  double along = (dv.x * L.x + dv.y * L.y + dv.z * L.z) / length;
  double magnitude = -k * (length - rest) - d * along;
  pMULTIPLY(L, magnitude / length, *force);
}

static void collide(struct world * jello, struct point p, struct point c, struct point v,
                    struct point * f)
{
  struct point L, force;
  pDIFFERENCE(p, c, L);
  double length = sqrt(L.x * L.x + L.y * L.y + L.z * L.z);
  if (length == 0)
    return;
  double along = (v.x * L.x + v.y * L.y + v.z * L.z) / length;
  double magnitude = -jello->kCollision * length - jello->dCollision * along;
  pMULTIPLY(L, magnitude / length, force);
  pSUM(*f, force, *f);
}

static double trilinear(double x, int R, int * cell)
{
  double s = (x + 2.0) * (R - 1) / 4.0;
  *cell = (int)floor(s);
  if (*cell < 0) *cell = 0;
  if (*cell > R - 2) *cell = R - 2;
  return s - *cell;
}

static void fieldForce(struct world * jello, struct point p, struct point * f)
{
  int R = jello->resolution;
  if (R == 0 || fabs(p.x) > 2 || fabs(p.y) > 2 || fabs(p.z) > 2)
    return;
  if (R == 1)
  {
    pSUM(*f, jello->forceField[0], *f);
    return;
  }
  int c[3];
  double t[3] = {trilinear(p.x, R, &c[0]), trilinear(p.y, R, &c[1]), trilinear(p.z, R, &c[2])};
  for (int corner = 0; corner < 8; corner++)
  {
    int di = corner >> 2 & 1, dj = corner >> 1 & 1, dk = corner & 1;
    double w = (di ? t[0] : 1 - t[0]) * (dj ? t[1] : 1 - t[1]) * (dk ? t[2] : 1 - t[2]);
    struct point node = jello->forceField[((c[0] + di) * R + c[1] + dj) * R + c[2] + dk];
    f->x += w * node.x;
    f->y += w * node.y;
    f->z += w * node.z;
  }
}

void computeAcceleration(struct world * jello, struct point a[8][8][8])
{
  static struct point f[8][8][8];
  memset(f, 0, sizeof f);
  for (size_t s = 0; s < springs.size(); s++)
  {
    const Spring & sp = springs[s];
    struct point force;
    springForce(jello->kElastic, jello->dElastic, sp.rest, jello->p[sp.i1][sp.j1][sp.k1],
                jello->p[sp.i2][sp.j2][sp.k2], jello->v[sp.i1][sp.j1][sp.k1],
                jello->v[sp.i2][sp.j2][sp.k2], &force);
    pSUM(f[sp.i1][sp.j1][sp.k1], force, f[sp.i1][sp.j1][sp.k1]);
    pDIFFERENCE(f[sp.i2][sp.j2][sp.k2], force, f[sp.i2][sp.j2][sp.k2]);
  }
  for (int i = 0; i <= 7; i++)
    for (int j = 0; j <= 7; j++)
      for (int k = 0; k <= 7; k++)
      {
        struct point p = jello->p[i][j][k], v = jello->v[i][j][k];
        double coordinate[3] = {p.x, p.y, p.z};
        for (int axis = 0; axis < 3; axis++)
          for (int side = -1; side <= 1; side += 2)
            if (coordinate[axis] * side > 2)
            {
              struct point wall = p;
              if (axis == 0) wall.x = 2.0 * side;
              if (axis == 1) wall.y = 2.0 * side;
              if (axis == 2) wall.z = 2.0 * side;
              collide(jello, p, wall, v, &f[i][j][k]);
            }
        if (jello->incPlanePresent == 1)
        {
          double value = jello->a * p.x + jello->b * p.y + jello->c * p.z + jello->d;
          if (value < 0)
          {
            double norm2 = jello->a * jello->a + jello->b * jello->b + jello->c * jello->c;
            struct point onPlane = {p.x - value / norm2 * jello->a, p.y - value / norm2 * jello->b,
                                    p.z - value / norm2 * jello->c};
            collide(jello, p, onPlane, v, &f[i][j][k]);
          }
        }
        fieldForce(jello, p, &f[i][j][k]);
        pMULTIPLY(f[i][j][k], 1.0 / jello->mass, a[i][j][k]);
      }
}

void Euler(struct world * jello)
{
  static struct point a[8][8][8];
  computeAcceleration(jello, a);
  for (int i = 0; i <= 7; i++)
    for (int j = 0; j <= 7; j++)
      for (int k = 0; k <= 7; k++)
      {
        jello->p[i][j][k].x += jello->dt * jello->v[i][j][k].x;
        jello->p[i][j][k].y += jello->dt * jello->v[i][j][k].y;
        jello->p[i][j][k].z += jello->dt * jello->v[i][j][k].z;
        jello->v[i][j][k].x += jello->dt * a[i][j][k].x;
        jello->v[i][j][k].y += jello->dt * a[i][j][k].y;
        jello->v[i][j][k].z += jello->dt * a[i][j][k].z;
      }
}

void RK4(struct world * jello)
{
  static struct point F1p[8][8][8], F1v[8][8][8], F2p[8][8][8], F2v[8][8][8],
      F3p[8][8][8], F3v[8][8][8], F4p[8][8][8], F4v[8][8][8];
  static struct world buffer;
  double dt = jello->dt;
  buffer = *jello;
  computeAcceleration(jello, F1v);
  memcpy(F1p, jello->v, sizeof F1p);
  for (int i = 0; i <= 7; i++)
    for (int j = 0; j <= 7; j++)
      for (int k = 0; k <= 7; k++)
      {
        pMULTIPLY(F1p[i][j][k], dt / 2, buffer.p[i][j][k]);
        pSUM(jello->p[i][j][k], buffer.p[i][j][k], buffer.p[i][j][k]);
        pMULTIPLY(F1v[i][j][k], dt / 2, buffer.v[i][j][k]);
        pSUM(jello->v[i][j][k], buffer.v[i][j][k], buffer.v[i][j][k]);
      }
  computeAcceleration(&buffer, F2v);
  memcpy(F2p, buffer.v, sizeof F2p);
  for (int i = 0; i <= 7; i++)
    for (int j = 0; j <= 7; j++)
      for (int k = 0; k <= 7; k++)
      {
        pMULTIPLY(F2p[i][j][k], dt / 2, buffer.p[i][j][k]);
        pSUM(jello->p[i][j][k], buffer.p[i][j][k], buffer.p[i][j][k]);
        pMULTIPLY(F2v[i][j][k], dt / 2, buffer.v[i][j][k]);
        pSUM(jello->v[i][j][k], buffer.v[i][j][k], buffer.v[i][j][k]);
      }
  computeAcceleration(&buffer, F3v);
  memcpy(F3p, buffer.v, sizeof F3p);
  for (int i = 0; i <= 7; i++)
    for (int j = 0; j <= 7; j++)
      for (int k = 0; k <= 7; k++)
      {
        pMULTIPLY(F3p[i][j][k], dt, buffer.p[i][j][k]);
        pSUM(jello->p[i][j][k], buffer.p[i][j][k], buffer.p[i][j][k]);
        pMULTIPLY(F3v[i][j][k], dt, buffer.v[i][j][k]);
        pSUM(jello->v[i][j][k], buffer.v[i][j][k], buffer.v[i][j][k]);
      }
  computeAcceleration(&buffer, F4v);
  memcpy(F4p, buffer.v, sizeof F4p);
  for (int i = 0; i <= 7; i++)
    for (int j = 0; j <= 7; j++)
      for (int k = 0; k <= 7; k++)
      {
        jello->p[i][j][k].x += dt / 6 * (F1p[i][j][k].x + 2 * F2p[i][j][k].x + 2 * F3p[i][j][k].x + F4p[i][j][k].x);
        jello->p[i][j][k].y += dt / 6 * (F1p[i][j][k].y + 2 * F2p[i][j][k].y + 2 * F3p[i][j][k].y + F4p[i][j][k].y);
        jello->p[i][j][k].z += dt / 6 * (F1p[i][j][k].z + 2 * F2p[i][j][k].z + 2 * F3p[i][j][k].z + F4p[i][j][k].z);
        jello->v[i][j][k].x += dt / 6 * (F1v[i][j][k].x + 2 * F2v[i][j][k].x + 2 * F3v[i][j][k].x + F4v[i][j][k].x);
        jello->v[i][j][k].y += dt / 6 * (F1v[i][j][k].y + 2 * F2v[i][j][k].y + 2 * F3v[i][j][k].y + F4v[i][j][k].y);
        jello->v[i][j][k].z += dt / 6 * (F1v[i][j][k].z + 2 * F2v[i][j][k].z + 2 * F3v[i][j][k].z + F4v[i][j][k].z);
      }
}
