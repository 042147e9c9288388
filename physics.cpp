// physics.cpp: forces of the jello model. See physics.h for units and signs.

#include "physics.h"

#include <algorithm>
#include <cmath>

namespace jello {

const std::vector<SpringOffset> kSpringOffsets = {
    // structural
    {1, 0, 0, SpringKind::Structural},
    {0, 1, 0, SpringKind::Structural},
    {0, 0, 1, SpringKind::Structural},
    // face shear
    {1, 1, 0, SpringKind::Shear},
    {1, -1, 0, SpringKind::Shear},
    {1, 0, 1, SpringKind::Shear},
    {1, 0, -1, SpringKind::Shear},
    {0, 1, 1, SpringKind::Shear},
    {0, 1, -1, SpringKind::Shear},
    // body shear
    {1, 1, 1, SpringKind::Shear},
    {1, 1, -1, SpringKind::Shear},
    {1, -1, 1, SpringKind::Shear},
    {1, -1, -1, SpringKind::Shear},
    // bend
    {2, 0, 0, SpringKind::Bend},
    {0, 2, 0, SpringKind::Bend},
    {0, 0, 2, SpringKind::Bend},
};

std::vector<Spring> buildSprings() {
  std::vector<Spring> springs;
  auto inside = [](int c) { return c >= 0 && c < kLatticeSize; };
  for (const SpringOffset& o : kSpringOffsets) {
    double rest = kRestSpacing * std::sqrt(double(o.di * o.di + o.dj * o.dj + o.dk * o.dk));
    for (int i = 0; i < kLatticeSize; ++i)
      for (int j = 0; j < kLatticeSize; ++j)
        for (int k = 0; k < kLatticeSize; ++k) {
          if (!inside(i + o.di) || !inside(j + o.dj) || !inside(k + o.dk)) continue;
          springs.push_back({pointIndex(i, j, k), pointIndex(i + o.di, j + o.dj, k + o.dk), rest, o.kind});
        }
  }
  return springs;
}

Model makeModel(const World& world, const State& initial) {
  Model model;
  model.world = world;
  model.springs = buildSprings();
  if (world.hasPlane) {
    Vec3 centroid;
    for (int q = 0; q < kNumPoints; ++q) centroid += load(initial.p(), q);
    centroid = (1.0 / kNumPoints) * centroid;
    const Plane& pl = world.plane;
    double s = pl.a * centroid.x + pl.b * centroid.y + pl.c * centroid.z + pl.d;
    model.planeSide = s >= 0 ? 1 : -1;
  }
  return model;
}

Vec3 direction(Vec3 L, double* len) {
  *len = length(L);
  if (*len == 0) return {};
  return (1.0 / *len) * L;
}

Vec3 springForce(Vec3 L, Vec3 relVel, double k, double d, double rest) {
  double len;
  Vec3 u = direction(L, &len);
  return (-k * (len - rest) - d * dot(relVel, u)) * u;
}

Vec3 collisionForce(Vec3 L, Vec3 v, double k, double d) {
  double len;
  Vec3 u = direction(L, &len);
  return -k * L + (-d * dot(v, u)) * u;
}

Vec3 wallForce(Vec3 p, Vec3 v, double k, double d) {
  Vec3 force;
  const double coord[3] = {p.x, p.y, p.z};
  for (int axis = 0; axis < 3; ++axis) {
    double beyond = 0;  // signed distance past the wall; the contact point is on the wall
    if (coord[axis] > kBoxHalfSize) beyond = coord[axis] - kBoxHalfSize;
    if (coord[axis] < -kBoxHalfSize) beyond = coord[axis] + kBoxHalfSize;
    if (beyond == 0) continue;
    Vec3 L;
    (axis == 0 ? L.x : axis == 1 ? L.y : L.z) = beyond;
    force += collisionForce(L, v, k, d);
  }
  return force;
}

Vec3 planeForce(const Plane& plane, double side, Vec3 p, Vec3 v, double k, double d) {
  Vec3 normal{plane.a, plane.b, plane.c};
  double s = dot(normal, p) + plane.d;
  if (!(s * side < 0)) return {};
  // p minus its orthogonal projection c = p - (s/|a|^2) a.
  Vec3 L = (s / dot(normal, normal)) * normal;
  return collisionForce(L, v, k, d);
}

int pointsAcrossPlane(const Model& model, const State& state) {
  if (!model.world.hasPlane) return 0;
  const Plane& pl = model.world.plane;
  int across = 0;
  for (int q = 0; q < kNumPoints; ++q) {
    Vec3 p = load(state.p(), q);
    if ((pl.a * p.x + pl.b * p.y + pl.c * p.z + pl.d) * model.planeSide < 0) ++across;
  }
  return across;
}

Vec3 fieldForce(const ForceField& field, Vec3 p) {
  const int r = field.resolution;
  if (r == 0) return {};
  if (std::fabs(p.x) > kBoxHalfSize || std::fabs(p.y) > kBoxHalfSize ||
      std::fabs(p.z) > kBoxHalfSize)
    return {};
  const double* f = field.forces.data();
  if (r == 1) return {f[0], f[1], f[2]};
  int cell[3];
  double t[3];
  const double coord[3] = {p.x, p.y, p.z};
  for (int axis = 0; axis < 3; ++axis) {
    double g = (coord[axis] + kBoxHalfSize) * (r - 1) / (2 * kBoxHalfSize);
    cell[axis] = std::clamp(static_cast<int>(std::floor(g)), 0, r - 2);
    t[axis] = g - cell[axis];
  }
  Vec3 sum;
  for (int corner = 0; corner < 8; ++corner) {
    int di = (corner >> 2) & 1, dj = (corner >> 1) & 1, dk = corner & 1;
    double w = (di ? t[0] : 1 - t[0]) * (dj ? t[1] : 1 - t[1]) * (dk ? t[2] : 1 - t[2]);
    std::size_t node = (static_cast<std::size_t>(cell[0] + di) * r + (cell[1] + dj)) * r + (cell[2] + dk);
    sum += w * Vec3{f[3 * node], f[3 * node + 1], f[3 * node + 2]};
  }
  return sum;
}

Vec3 pullForce(const Pull& pull, Vec3 p) { return pull.stiffness * (pull.target - p); }

void computeForces(const Model& model, const double* p, const double* v, double* force, const Pull* pull) {
  const World& w = model.world;
  std::fill(force, force + kNumCoords, 0.0);
  for (const Spring& s : model.springs) {
    Vec3 f = springForce(load(p, s.a) - load(p, s.b), load(v, s.a) - load(v, s.b), w.kElastic,
                         w.dElastic, s.rest);
    store(force, s.a, load(force, s.a) + f);
    store(force, s.b, load(force, s.b) - f);
  }
  for (int q = 0; q < kNumPoints; ++q) {
    Vec3 pq = load(p, q), vq = load(v, q);
    Vec3 f = wallForce(pq, vq, w.kCollision, w.dCollision);
    if (w.hasPlane) f += planeForce(w.plane, model.planeSide, pq, vq, w.kCollision, w.dCollision);
    f += fieldForce(w.field, pq);
    store(force, q, load(force, q) + f);
  }
  if (pull && pull->point >= 0) store(force, pull->point, load(force, pull->point) + pullForce(*pull, load(p, pull->point)));
}

void derivative(const Model& model, const double* y, double* dydt, const Pull* pull) {
  const double* p = y;
  const double* v = y + kNumCoords;
  std::copy(v, v + kNumCoords, dydt);
  double* a = dydt + kNumCoords;
  computeForces(model, p, v, a, pull);
  const double mass = model.world.mass;
  for (int c = 0; c < kNumCoords; ++c) a[c] /= mass;
}

int findDivergedPoint(const State& state) {
  const double* p = state.p();
  const double* v = state.v();
  for (int q = 0; q < kNumPoints; ++q) {
    Vec3 pq = load(p, q), vq = load(v, q);
    bool finite = std::isfinite(pq.x) && std::isfinite(pq.y) && std::isfinite(pq.z) &&
                  std::isfinite(vq.x) && std::isfinite(vq.y) && std::isfinite(vq.z);
    if (!finite || dot(pq, pq) > kDivergenceRadius * kDivergenceRadius) return q;
  }
  return -1;
}

}  // namespace jello
