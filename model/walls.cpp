// model/walls.cpp: the box's walls: force, Jacobian, energy and description.

#include "model/walls.h"

#include <algorithm>
#include <cmath>

namespace jello {

Vec3 wallForce(Vec3 p, Vec3 v, const ContactSpring& spring) {
  Vec3 force;
  for (int axis = 0; axis < 3; ++axis) force += wallForceAlong(axis, p, v, spring);
  return force;
}

void wallJacobian(Vec3 p, const ContactSpring& spring, Block3* dFdp, Block3* dFdv) {
  *dFdp = Block3{};
  *dFdv = Block3{};
  const double coord[3] = {p.x, p.y, p.z};
  for (int axis = 0; axis < 3; ++axis)
    if (std::fabs(coord[axis]) > kBoxHalfSize)
      addContactJacobian(spring,
                         {axis == 0 ? 1.0 : 0.0, axis == 1 ? 1.0 : 0.0, axis == 2 ? 1.0 : 0.0},
                         dFdp, dFdv);
}

namespace {
// Which wall pairs some point of the box is beyond: all three without a box.
void wallsInReach(const Bounds* box, bool reached[3]) {
  if (!box) {
    reached[0] = reached[1] = reached[2] = true;
    return;
  }
  reached[0] = box->upper.x > kBoxHalfSize || box->lower.x < -kBoxHalfSize;
  reached[1] = box->upper.y > kBoxHalfSize || box->lower.y < -kBoxHalfSize;
  reached[2] = box->upper.z > kBoxHalfSize || box->lower.z < -kBoxHalfSize;
}
}  // namespace

bool WallsTerm::mayReach(const Bounds& box) const {
  bool reached[3];
  wallsInReach(&box, reached);
  return reached[0] || reached[1] || reached[2];
}

int WallsTerm::pointsInContact(const double* p) const {
  if (spring_.k == 0 && spring_.d == 0) return 0;
  int outside = 0;
  for (int q = 0; q < pointCount(); ++q) outside += !insideBox(at(p, q));
  return outside;
}

// A wall pair out of reach adds nothing and is left out; the loop over the points vectorises.
void WallsTerm::addForcesOn(PointRange points, const double* p, const double* v, const Bounds* box,
                            double* force) const {
  bool reached[3];
  wallsInReach(box, reached);
  for (int q = points.begin; q < points.end; ++q) {
    const Vec3 pq = at(p, q), vq = at(v, q);
    Vec3 f;
    for (int axis = 0; axis < 3; ++axis)
      if (reached[axis]) f += wallForceAlong(axis, pq, vq, spring_);
    addAt(force, q, f);
  }
}

void WallsTerm::addJacobian(const double* p, const double*, JacobianSink* sink) const {
  Block3 dFdp, dFdv;
  for (int q = 0; q < pointCount(); ++q) {
    wallJacobian(at(p, q), spring_, &dFdp, &dFdv);
    sink->addPoint(q, dFdp, dFdv);
  }
}

void WallsTerm::addEnergy(const double* p, double* energy) const {
  for (int c = 0; c < 3 * pointCount(); ++c) {
    double beyond = std::max(0.0, std::fabs(p[c]) - kBoxHalfSize);
    *energy += 0.5 * spring_.k * beyond * beyond;
  }
}

void WallsTerm::summarise(std::vector<std::string>* kept, std::vector<std::string>*) const {
  kept->push_back("walls (when the cube's bounding box reaches them)");
}

std::vector<TermLine> WallsTerm::describe(const double* p) const {
  int outside = 0;
  for (int q = 0; q < pointCount(); ++q) outside += !insideBox(at(p, q));
  std::string text =
      textf("the box [-2,2]^3, collision springs kCollision %.9g N/m, dCollision %.9g N s/m",
            spring_.k, spring_.d);
  if (outside) text += textf("; %d points start outside it", outside);
  return {{"walls", text}};
}

}  // namespace jello
