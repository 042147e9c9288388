/* Made by scripts/make-mutants: correct/physics.cpp with one mistake (rk4-quarter). */
/* physics.cpp: a correct solution of the jello cube assignment in the course API, written for
   the grader's tests (docs/physics.md is the model). The grader's mutants are this file with
   one classic mistake each (tests/data/mutants.txt). */
#include "physics.h"

#include "jello.h"

/* The lattice offsets (di, dj, dk) of the springs, each pair once: structural, face shear,
   body shear, bend. The rest length of a spring is the offset's length / 7. */
static const int kOffsets[16][3] = {{1, 0, 0}, {0, 1, 0},  {0, 0, 1}, /* structural */
                                    {1, 1, 0}, {1, -1, 0}, {1, 0, 1},  {1, 0, -1},
                                    {0, 1, 1}, {0, 1, -1},                          /* face shear */
                                    {1, 1, 1}, {1, 1, -1}, {1, -1, 1}, {1, -1, -1}, /* body shear */
                                    {2, 0, 0}, {0, 2, 0},  {0, 0, 2}};              /* bend */
static const int kSpringKinds = 16;

static double restLength(const int* o) {
  return sqrt((double)(o[0] * o[0] + o[1] * o[1] + o[2] * o[2])) / 7.0;
}

/* Adds the force of one spring (stiffness k, damping d, rest length rest) between points a
   and b, moving at va and vb, to fa; b gets the opposite. */
static void addSpring(double k, double d, double rest, struct point pa, struct point pb,
                      struct point va, struct point vb, struct point* fa, struct point* fb) {
  struct point L, dv;
  pDIFFERENCE(pa, pb, L);
  double length = sqrt(L.x * L.x + L.y * L.y + L.z * L.z);
  if (length == 0) return; /* a spring of zero length exerts no force */
  struct point u;
  pMULTIPLY(L, 1.0 / length, u);
  pDIFFERENCE(va, vb, dv);
  double along = dv.x * u.x + dv.y * u.y + dv.z * u.z;
  double magnitude = -k * (length - rest) - d * along;
  fa->x += magnitude * u.x;
  fa->y += magnitude * u.y;
  fa->z += magnitude * u.z;
  fb->x -= magnitude * u.x;
  fb->y -= magnitude * u.y;
  fb->z -= magnitude * u.z;
}

/* A collision spring of rest length 0 from p to its contact point c. */
static void addContact(double k, double d, struct point p, struct point c, struct point v,
                       struct point* f) {
  struct point L;
  pDIFFERENCE(p, c, L);
  double length = sqrt(L.x * L.x + L.y * L.y + L.z * L.z);
  if (length == 0) return;
  double along = (v.x * L.x + v.y * L.y + v.z * L.z) / length;
  f->x += -k * L.x - d * along * L.x / length;
  f->y += -k * L.y - d * along * L.y / length;
  f->z += -k * L.z - d * along * L.z / length;
}

static void addWalls(struct world* jello, struct point p, struct point v, struct point* f) {
  double coordinate[3] = {p.x, p.y, p.z};
  for (int axis = 0; axis < 3; axis++) {
    for (int side = -1; side <= 1; side += 2) {
      if (coordinate[axis] * side <= 2.0) continue;
      struct point c = p;
      if (axis == 0) c.x = 2.0 * side;
      if (axis == 1) c.y = 2.0 * side;
      if (axis == 2) c.z = 2.0 * side;
      addContact(jello->kCollision, jello->dCollision, p, c, v, f);
    }
  }
}

static void addPlane(struct world* jello, struct point p, struct point v, struct point* f) {
  double value = jello->a * p.x + jello->b * p.y + jello->c * p.z + jello->d;
  if (value >= 0) return; /* the cube lives on the positive side */
  double norm2 = jello->a * jello->a + jello->b * jello->b + jello->c * jello->c;
  struct point c;
  c.x = p.x - value / norm2 * jello->a;
  c.y = p.y - value / norm2 * jello->b;
  c.z = p.z - value / norm2 * jello->c;
  addContact(jello->kCollision, jello->dCollision, p, c, v, f);
}

/* The cell of coordinate x and the fraction of the way across it. */
static int fieldCell(double x, int R, double* t) {
  double s = (x + 2.0) * (R - 1) / 4.0;
  int cell = (int)floor(s);
  if (cell < 0) cell = 0;
  if (cell > R - 2) cell = R - 2;
  *t = s - cell;
  return cell;
}

static void addField(struct world* jello, struct point p, struct point* f) {
  int R = jello->resolution;
  if (R == 0) return;
  if (fabs(p.x) > 2 || fabs(p.y) > 2 || fabs(p.z) > 2) return;
  if (R == 1) {
    pSUM(*f, jello->forceField[0], *f);
    return;
  }
  double t[3];
  int i = fieldCell(p.x, R, &t[0]), j = fieldCell(p.y, R, &t[1]), k = fieldCell(p.z, R, &t[2]);
  for (int corner = 0; corner < 8; corner++) {
    int di = (corner >> 2) & 1, dj = (corner >> 1) & 1, dk = corner & 1;
    double w = (di ? t[0] : 1 - t[0]) * (dj ? t[1] : 1 - t[1]) * (dk ? t[2] : 1 - t[2]);
    struct point node = jello->forceField[((i + di) * R + (j + dj)) * R + (k + dk)];
    f->x += w * node.x;
    f->y += w * node.y;
    f->z += w * node.z;
  }
}

void computeAcceleration(struct world* jello, struct point a[8][8][8]) {
  static struct point f[8][8][8];
  static double rests[16];
  static int restsReady = 0;
  if (!restsReady) {
    for (int s = 0; s < kSpringKinds; s++) rests[s] = restLength(kOffsets[s]);
    restsReady = 1;
  }
  memset(f, 0, sizeof f);
  for (int i = 0; i < 8; i++)
    for (int j = 0; j < 8; j++)
      for (int k = 0; k < 8; k++)
        for (int s = 0; s < kSpringKinds; s++) {
          const int* o = kOffsets[s];
          int i2 = i + o[0], j2 = j + o[1], k2 = k + o[2];
          if (i2 < 0 || i2 > 7 || j2 < 0 || j2 > 7 || k2 < 0 || k2 > 7) continue;
          addSpring(jello->kElastic, jello->dElastic, rests[s], jello->p[i][j][k],
                    jello->p[i2][j2][k2], jello->v[i][j][k], jello->v[i2][j2][k2], &f[i][j][k],
                    &f[i2][j2][k2]);
        }
  for (int i = 0; i < 8; i++)
    for (int j = 0; j < 8; j++)
      for (int k = 0; k < 8; k++) {
        struct point p = jello->p[i][j][k], v = jello->v[i][j][k];
        addWalls(jello, p, v, &f[i][j][k]);
        if (jello->incPlanePresent == 1) addPlane(jello, p, v, &f[i][j][k]);
        addField(jello, p, &f[i][j][k]);
        pMULTIPLY(f[i][j][k], 1.0 / jello->mass, a[i][j][k]);
      }
}

void Euler(struct world* jello) {
  static struct point a[8][8][8];
  computeAcceleration(jello, a);
  for (int i = 0; i < 8; i++)
    for (int j = 0; j < 8; j++)
      for (int k = 0; k < 8; k++) {
        jello->p[i][j][k].x += jello->dt * jello->v[i][j][k].x;
        jello->p[i][j][k].y += jello->dt * jello->v[i][j][k].y;
        jello->p[i][j][k].z += jello->dt * jello->v[i][j][k].z;
        jello->v[i][j][k].x += jello->dt * a[i][j][k].x;
        jello->v[i][j][k].y += jello->dt * a[i][j][k].y;
        jello->v[i][j][k].z += jello->dt * a[i][j][k].z;
      }
}

/* stage = start + h * (dp, dv) for every point. */
static void stageState(struct world* start, double h, struct point dp[8][8][8],
                       struct point dv[8][8][8], struct world* stage) {
  for (int i = 0; i < 8; i++)
    for (int j = 0; j < 8; j++)
      for (int k = 0; k < 8; k++) {
        stage->p[i][j][k].x = start->p[i][j][k].x + h * dp[i][j][k].x;
        stage->p[i][j][k].y = start->p[i][j][k].y + h * dp[i][j][k].y;
        stage->p[i][j][k].z = start->p[i][j][k].z + h * dp[i][j][k].z;
        stage->v[i][j][k].x = start->v[i][j][k].x + h * dv[i][j][k].x;
        stage->v[i][j][k].y = start->v[i][j][k].y + h * dv[i][j][k].y;
        stage->v[i][j][k].z = start->v[i][j][k].z + h * dv[i][j][k].z;
      }
}

void RK4(struct world* jello) {
  static struct world stage;
  static struct point kp[4][8][8][8], kv[4][8][8][8];
  double dt = jello->dt;
  stage = *jello;
  for (int s = 0; s < 4; s++) {
    if (s > 0) stageState(jello, s == 3 ? dt : (s == 2 ? dt / 4 : dt / 2), kp[s - 1], kv[s - 1], &stage);
    memcpy(kp[s], stage.v, sizeof stage.v);
    computeAcceleration(&stage, kv[s]);
  }
  for (int i = 0; i < 8; i++)
    for (int j = 0; j < 8; j++)
      for (int k = 0; k < 8; k++) {
        struct point* p = &jello->p[i][j][k];
        struct point* v = &jello->v[i][j][k];
        p->x += dt / 6 *
                (kp[0][i][j][k].x + 2 * kp[1][i][j][k].x + 2 * kp[2][i][j][k].x + kp[3][i][j][k].x);
        p->y += dt / 6 *
                (kp[0][i][j][k].y + 2 * kp[1][i][j][k].y + 2 * kp[2][i][j][k].y + kp[3][i][j][k].y);
        p->z += dt / 6 *
                (kp[0][i][j][k].z + 2 * kp[1][i][j][k].z + 2 * kp[2][i][j][k].z + kp[3][i][j][k].z);
        v->x += dt / 6 *
                (kv[0][i][j][k].x + 2 * kv[1][i][j][k].x + 2 * kv[2][i][j][k].x + kv[3][i][j][k].x);
        v->y += dt / 6 *
                (kv[0][i][j][k].y + 2 * kv[1][i][j][k].y + 2 * kv[2][i][j][k].y + kv[3][i][j][k].y);
        v->z += dt / 6 *
                (kv[0][i][j][k].z + 2 * kv[1][i][j][k].z + 2 * kv[2][i][j][k].z + kv[3][i][j][k].z);
      }
}
