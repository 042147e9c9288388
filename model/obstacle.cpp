// model/obstacle.cpp: a scene's obstacles: penetrations, force, Jacobian, energy, description.

#include "model/obstacle.h"

#include <algorithm>
#include <cmath>

namespace jello {

std::optional<FrictionFault> frictionFault(const Friction& f) {
  if (!(f.muStatic >= 0 && f.muStatic <= kMostFriction))
    return FrictionFault{"friction_static",
                         "must be from 0 to " + std::to_string(static_cast<int>(kMostFriction))};
  if (!(f.muDynamic >= 0 && f.muDynamic <= f.muStatic))
    return FrictionFault{"friction_dynamic",
                         "must be from 0 to friction_static (dynamic friction is the weaker)"};
  if (!(f.speed > 0 && std::isfinite(f.speed)))
    return FrictionFault{"friction_speed", "must be a positive number of m/s"};
  return std::nullopt;
}

const char* obstacleShapeName(ObstacleShape shape) {
  static const char* const kNames[] = {"sphere", "box", "plane", "bounding box"};
  return kNames[static_cast<int>(shape)];
}

namespace {

Vec3 axisVector(int axis, double sign) {
  return {axis == 0 ? sign : 0.0, axis == 1 ? sign : 0.0, axis == 2 ? sign : 0.0};
}
double coordinate(Vec3 p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }

// Strictly inside the solid box: out through the nearest face.
int boxPenetration(const Obstacle& o, Vec3 p, Penetration* out) {
  double depth = INFINITY;
  for (int axis = 0; axis < 3; ++axis) {
    const double c = coordinate(p, axis);
    const double below = c - coordinate(o.lower, axis), above = coordinate(o.upper, axis) - c;
    if (!(below > 0 && above > 0)) return 0;  // outside (or NaN)
    if (below < depth) depth = below, out->normal = axisVector(axis, -1);
    if (above < depth) depth = above, out->normal = axisVector(axis, 1);
  }
  out->depth = depth;
  return 1;
}

// Beyond the container's walls: one penetration for each wall the point is beyond.
int containerPenetrations(const Obstacle& o, Vec3 p, Penetration out[3]) {
  int count = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const double c = coordinate(p, axis);
    if (c > coordinate(o.upper, axis))
      out[count++] = {c - coordinate(o.upper, axis), axisVector(axis, -1)};
    else if (c < coordinate(o.lower, axis))
      out[count++] = {coordinate(o.lower, axis) - c, axisVector(axis, 1)};
  }
  return count;
}

}  // namespace

int penetrations(const Obstacle& o, Vec3 p, Penetration out[3]) {
  switch (o.shape) {
    case ObstacleShape::Sphere: {
      const Vec3 away = p - o.centre;
      const double r = length(away);
      if (!(r < o.radius)) return 0;
      // At the very centre every direction is nearest: up, by convention.
      out[0] = {o.radius - r, r > 0 ? (1 / r) * away : Vec3{0, 0, 1}};
      return 1;
    }
    case ObstacleShape::Box:
      return boxPenetration(o, p, out);
    case ObstacleShape::HalfSpace: {
      const double s = dot(o.normal, p - o.point);
      if (!(s < 0)) return 0;
      out[0] = {-s, o.normal};
      return 1;
    }
    case ObstacleShape::Container:
      return containerPenetrations(o, p, out);
  }
  return 0;
}

Vec3 frictionForce(const Friction& f, double push, Vec3 normal, Vec3 v) {
  if (push <= 0 || f.muStatic == 0) return {};
  const Vec3 tangential = v - dot(v, normal) * normal;
  const double s = length(tangential);
  const double mu =
      f.muDynamic + (f.muStatic - f.muDynamic) * std::exp(-s / (kStribeckRatio * f.speed));
  return (-mu * push / std::sqrt(s * s + f.speed * f.speed)) * tangential;
}

// The collision spring from the nearest surface point c = p + depth n, L = p - c = -depth n.
Vec3 penetrationForce(const Obstacle& o, const Penetration& pen, Vec3 v) {
  const Vec3 spring = contactForce(o.spring, (-pen.depth) * pen.normal, v);
  const double push = o.spring.k * pen.depth - o.spring.d * dot(v, pen.normal);
  return spring + frictionForce(o.friction, push, pen.normal, v);
}

Vec3 obstacleForce(const Obstacle& o, Vec3 p, Vec3 v) {
  Penetration pens[3];
  const int count = penetrations(o, p, pens);
  Vec3 force;
  for (int i = 0; i < count; ++i) force += penetrationForce(o, pens[i], v);
  return force;
}

FrictionState frictionState(const Obstacle& o, Vec3 p, Vec3 v) {
  if (o.friction.muStatic == 0) return FrictionState::None;
  Penetration pens[3];
  const int count = penetrations(o, p, pens);
  FrictionState state = FrictionState::None;
  for (int i = 0; i < count; ++i) {
    const Vec3 n = pens[i].normal;
    // The same push frictionForce is given: no push, no friction.
    if (!(o.spring.k * pens[i].depth - o.spring.d * dot(v, n) > 0)) continue;
    const double slip = length(v - dot(v, n) * n);
    state = strongerState(state, slip < kStickingSpeedRatio * o.friction.speed
                                     ? FrictionState::Sticking
                                     : FrictionState::Sliding);
  }
  return state;
}

namespace {

// The Jacobian's algebra on 3x3 blocks (Block3, term.h: row-major).
Block3 outer(Vec3 a, Vec3 b) {
  const double x[3] = {a.x, a.y, a.z}, y[3] = {b.x, b.y, b.z};
  Block3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.m[3 * i + j] = x[i] * y[j];
  return r;
}
Block3 operator*(double s, Block3 a) {
  for (double& e : a.m) e *= s;
  return a;
}
Block3 operator+(Block3 a, const Block3& b) {
  for (int e = 0; e < 9; ++e) a.m[e] += b.m[e];
  return a;
}
Block3 identity() {
  Block3 r;
  r.m[0] = r.m[4] = r.m[8] = 1;
  return r;
}
// a^T M, as a vector.
Vec3 leftTimes(Vec3 a, const Block3& M) {
  return {a.x * M.m[0] + a.y * M.m[3] + a.z * M.m[6], a.x * M.m[1] + a.y * M.m[4] + a.z * M.m[7],
          a.x * M.m[2] + a.y * M.m[5] + a.z * M.m[8]};
}
Block3 product(const Block3& a, const Block3& b) {
  Block3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) r.m[3 * i + j] += a.m[3 * i + k] * b.m[3 * k + j];
  return r;
}
void addTo(Block3* block, const Block3& a) {
  for (int e = 0; e < 9; ++e) block->m[e] += a.m[e];
}

// The derivatives of one penetration's force F = k depth n - d (v.n) n + F_t, where
// F_t = -g(s) N t (obstacle.h), by the chain rule through depth, n and t. dn = dn/dp: zero for a
// flat face, (I - n n^T) / r on a sphere of the point's distance r from the centre.
void addPenetrationJacobian(const Obstacle& o, const Penetration& pen, Vec3 v, const Block3& dn,
                            Block3* dFdp, Block3* dFdv) {
  const double k = o.spring.k, d = o.spring.d;
  const Vec3 n = pen.normal;
  const double vn = dot(v, n);
  const Block3 nn = outer(n, n);
  // d(v.n)/dp = v^T dn; d(v.n) n/dp = n (v^T dn) + (v.n) dn.
  const Block3 dvnn = outer(n, leftTimes(v, dn)) + vn * dn;
  addTo(dFdp, (-k) * nn + (k * pen.depth) * dn + (-d) * dvnn);  // d depth/dp = -n^T
  addTo(dFdv, (-d) * nn);
  const Friction& f = o.friction;
  const double push = k * pen.depth - d * vn;
  if (push <= 0 || f.muStatic == 0) return;
  const Vec3 t = v - vn * n;
  const double s = length(t), root = std::sqrt(s * s + f.speed * f.speed);
  const double decay = std::exp(-s / (kStribeckRatio * f.speed));
  const double mu = f.muDynamic + (f.muStatic - f.muDynamic) * decay;
  const double muSlope = -(f.muStatic - f.muDynamic) * decay / (kStribeckRatio * f.speed);
  const double g = mu / root, gSlope = muSlope / root - mu * s / (root * root * root);
  const Vec3 dPushDp = (-k) * n + (-d) * leftTimes(v, dn), dPushDv = (-d) * n;
  const Block3 dtDp = (-1.0) * dvnn, dtDv = identity() + (-1.0) * nn;
  auto friction = [&](const Block3& dtDx, Vec3 dPushDx) {
    Block3 out = (-push * g) * dtDx + (-g) * outer(t, dPushDx);
    if (s > 0) out = out + (-push * gSlope / s) * product(outer(t, t), dtDx);
    return out;
  };
  addTo(dFdp, friction(dtDp, dPushDp));
  addTo(dFdv, friction(dtDv, dPushDv));
}

}  // namespace

void obstacleJacobian(const Obstacle& o, Vec3 p, Vec3 v, Block3* dFdp, Block3* dFdv) {
  *dFdp = Block3{};
  *dFdv = Block3{};
  Penetration pens[3];
  const int count = penetrations(o, p, pens);
  for (int i = 0; i < count; ++i) {
    Block3 dn;
    const double r = o.radius - pens[i].depth;
    if (o.shape == ObstacleShape::Sphere && r > 0)
      dn = (1 / r) * (identity() + (-1.0) * outer(pens[i].normal, pens[i].normal));
    addPenetrationJacobian(o, pens[i], v, dn, dFdp, dFdv);
  }
}

std::string obstacleText(const Obstacle& o) {
  auto vec = [](Vec3 a) { return textf("(%.6g, %.6g, %.6g)", a.x, a.y, a.z); };
  std::string text;
  switch (o.shape) {
    case ObstacleShape::Sphere:
      text = "sphere at " + vec(o.centre) + textf(", radius %.6g m", o.radius);
      break;
    case ObstacleShape::Box:
      text = "box from " + vec(o.lower) + " to " + vec(o.upper);
      break;
    case ObstacleShape::HalfSpace:
      text = "plane through " + vec(o.point) + ", normal " + vec(o.normal);
      break;
    case ObstacleShape::Container:
      text = "bounding box from " + vec(o.lower) + " to " + vec(o.upper);
      break;
  }
  text += textf(": k %.6g N/m, d %.6g N s/m", o.spring.k, o.spring.d);
  if (o.friction.muStatic > 0)
    text += textf(", friction mu_s %.6g, mu_d %.6g (eps %.3g m/s)", o.friction.muStatic,
                  o.friction.muDynamic, o.friction.speed);
  return text;
}

// Conservative: some point of `box` may be inside (or, for a container, outside) the obstacle.
bool ObstacleTerm::mayReach(const Bounds& b) const {
  const Obstacle& o = obstacle_;
  switch (o.shape) {
    case ObstacleShape::Sphere: {
      // The box's nearest point to the centre.
      const Vec3 nearest{std::clamp(o.centre.x, b.lower.x, b.upper.x),
                         std::clamp(o.centre.y, b.lower.y, b.upper.y),
                         std::clamp(o.centre.z, b.lower.z, b.upper.z)};
      return !(length(nearest - o.centre) >= o.radius * (1 + 1e-12));
    }
    case ObstacleShape::Box:
      return !(b.upper.x < o.lower.x || b.lower.x > o.upper.x || b.upper.y < o.lower.y ||
               b.lower.y > o.upper.y || b.upper.z < o.lower.z || b.lower.z > o.upper.z);
    case ObstacleShape::HalfSpace: {
      auto lowest = [](double n, double lo, double hi) { return std::min(n * lo, n * hi); };
      const double smallest = lowest(o.normal.x, b.lower.x, b.upper.x) +
                              lowest(o.normal.y, b.lower.y, b.upper.y) +
                              lowest(o.normal.z, b.lower.z, b.upper.z) - dot(o.normal, o.point);
      return !(smallest > 1e-12 * (1 + length(o.point)));
    }
    case ObstacleShape::Container:
      return !(b.lower.x >= o.lower.x && b.upper.x <= o.upper.x && b.lower.y >= o.lower.y &&
               b.upper.y <= o.upper.y && b.lower.z >= o.lower.z && b.upper.z <= o.upper.z);
  }
  return true;
}

int ObstacleTerm::pointsInContact(const double* p) const {
  if (obstacle_.spring.k == 0 && obstacle_.spring.d == 0) return 0;
  int count = 0;
  Penetration pens[3];
  for (int q = 0; q < pointCount(); ++q) count += penetrations(obstacle_, at(p, q), pens) > 0;
  return count;
}

void ObstacleTerm::addForcesOn(PointRange points, const double* p, const double* v, const Bounds*,
                               double* force) const {
  for (int q = points.begin; q < points.end; ++q)
    addAt(force, q, obstacleForce(obstacle_, at(p, q), at(v, q)));
}

void ObstacleTerm::addJacobian(const double* p, const double* v, JacobianSink* sink) const {
  Block3 dFdp, dFdv;
  for (int q = 0; q < pointCount(); ++q) {
    obstacleJacobian(obstacle_, at(p, q), at(v, q), &dFdp, &dFdv);
    sink->addPoint(q, dFdp, dFdv);
  }
}

void ObstacleTerm::addEnergy(const double* p, double* energy) const {
  Penetration pens[3];
  for (int q = 0; q < pointCount(); ++q) {
    const int count = penetrations(obstacle_, at(p, q), pens);
    for (int i = 0; i < count; ++i)
      *energy += 0.5 * obstacle_.spring.k * pens[i].depth * pens[i].depth;
  }
}

void ObstacleTerm::summarise(std::vector<std::string>* kept, std::vector<std::string>*) const {
  kept->push_back(std::string(obstacleShapeName(obstacle_.shape)) +
                  (obstacle_.friction.muStatic > 0 ? " with friction" : "") +
                  " (when the bounding box reaches it)");
}

std::vector<TermLine> ObstacleTerm::describe(const double* p) const {
  return {
      {"obstacle", obstacleText(obstacle_) + textf(" (%d points in contact)", pointsInContact(p))}};
}

}  // namespace jello
