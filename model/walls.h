// model/walls.h: the six walls of the box [-2,2]^3, a point term.
//
// Units: metres, seconds, newtons. A point strictly beyond a wall is pulled back by a collision
// spring (model/contact.h) from its projection on that wall.
#pragma once

#include "model/contact.h"
#include "model/term.h"

namespace jello {

// The collision spring of the wall perpendicular to `axis` (0 x, 1 y, 2 z) that the point is
// strictly beyond, from the point's projection on it; zero when it is beyond neither. Selects,
// not branches, so that the kernel's loop over the points vectorises.
inline Vec3 wallForceAlong(int axis, Vec3 p, Vec3 v, const ContactSpring& spring) {
  const double c = axis == 0 ? p.x : axis == 1 ? p.y : p.z;
  const double beyond = c > kBoxHalfSize    ? c - kBoxHalfSize
                        : c < -kBoxHalfSize ? c + kBoxHalfSize
                                            : 0.0;
  const Vec3 L{axis == 0 ? beyond : 0.0, axis == 1 ? beyond : 0.0, axis == 2 ? beyond : 0.0};
  return contactForce(spring, L, v);
}
// Sum of the collision springs of the walls of [-2,2]^3 the point is strictly beyond.
Vec3 wallForce(Vec3 p, Vec3 v, const ContactSpring& spring);
// Derivatives of wallForce: -k e e^T and -d e e^T for each wall the point is beyond.
void wallJacobian(Vec3 p, const ContactSpring& spring, Block3* dFdp, Block3* dFdv);

// Inside the box, walls included; false for a non-finite point.
inline bool insideBox(Vec3 p) {
  return std::fabs(p.x) <= kBoxHalfSize && std::fabs(p.y) <= kBoxHalfSize &&
         std::fabs(p.z) <= kBoxHalfSize;
}

class WallsTerm final : public ForceTerm {
 public:
  WallsTerm(int points, const ContactSpring& spring) : ForceTerm(points), spring_(spring) {}
  // Some point of the box is beyond a wall.
  bool mayReach(const Bounds& box) const override;
  // The points beyond a wall, when the walls' spring pushes at all.
  int pointsInContact(const double* p) const override;
  void addForcesOn(PointRange points, const double* p, const double* v, const Bounds* box,
                   double* force) const override;
  void addJacobian(const double* p, const double* v, JacobianSink* sink) const override;
  void addEnergy(const double* p, double* energy) const override;
  void summarise(std::vector<std::string>* kept, std::vector<std::string>* leftOut) const override;
  std::vector<TermLine> describe(const double* p) const override;

 private:
  ContactSpring spring_;
};

}  // namespace jello
