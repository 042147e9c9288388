// model/plane.h: the inclined plane a x + b y + c z + d = 0, a point term.
//
// Units: metres, seconds, newtons. The cube keeps to one side of the plane, the side holding
// the centroid of its initial positions (docs/physics.md); a point strictly on the other side
// is pulled back by a collision spring (model/contact.h) from its projection on the plane.
// `side` is the sign of a x + b y + c z + d on the allowed side: +1 or -1.
#pragma once

#include <string>

#include "model/contact.h"
#include "model/term.h"

namespace jello {

// The same plane scaled by a power of two, so that its largest normal component lies in
// [0.5, 1): the squared normal of a plane such as (1e-300, 0, 0, 0) or (1e200, 1e200, 1e200,
// -1.5e200) neither underflows nor overflows. Scaling by a power of two is exact, so every
// force of an ordinary plane stays bit for bit what the unscaled plane gives. A normal
// component far smaller than the largest (by more than 2^1022) may round to zero: its effect
// on the plane was below double's resolution anyway. d is not finite when the plane is beyond
// the range of doubles (see planeProblem).
Plane normalisedPlane(const Plane& plane);
// Why the plane cannot be simulated, "" when it can: its normal is zero, or its normalised d
// is not finite (the plane lies further from the origin than about 1e308 m).
std::string planeProblem(const Plane& plane);
// a*x + b*y + c*z + d at (x, y, z): the one place it is computed (positive on the normal's
// side). T is a double, or a Pack of eight points' coordinates (model/pack.h), which round
// lane by lane as the doubles do.
template <class T>
inline T planeValueAt(const Plane& plane, const T& x, const T& y, const T& z) {
  return ((x * plane.a + y * plane.b) + z * plane.c) + plane.d;
}
inline double planeValue(const Plane& plane, Vec3 p) { return planeValueAt(plane, p.x, p.y, p.z); }
// The allowed side of the plane for a cube at positions p: the sign of the plane's value at
// their centroid, +1 when the centroid is on the plane.
double allowedSide(const Plane& plane, const double* p, int points);
// "x - y - z + 4 = 0" for (1, -1, -1, 4).
std::string planeEquation(const Plane& plane);

// Collision spring to the projection on the plane when the point is strictly on the side of
// sign -side. Computed for every point and selected, so that the kernel's contact loop has no
// branch. Takes the normalised plane, whose |n|^2 neither overflows nor underflows.
inline Vec3 planeForce(const Plane& plane, double side, Vec3 p, Vec3 v,
                       const ContactSpring& spring) {
  Vec3 normal{plane.a, plane.b, plane.c};
  double s = planeValue(plane, p);
  Vec3 L = (s / dot(normal, normal)) * normal;  // p minus its projection p - (s/|n|^2) n
  Vec3 f = contactForce(spring, L, v);
  const bool across = s * side < 0;
  return {across ? f.x : 0.0, across ? f.y : 0.0, across ? f.z : 0.0};
}
// Derivatives of planeForce: -k n n^T / |n|^2 and -d n n^T / |n|^2 when the point is across.
void planeJacobian(const Plane& plane, double side, Vec3 p, double k, double d, Block3* dFdp,
                   Block3* dFdv);
// Whether some point in `box` might be strictly across the plane: the smallest value of
// side * (a x + b y + c z + d) over the box, at one of its corners, is not clearly positive.
bool mayCrossPlane(const Plane& plane, double side, const Bounds& box);

class PlaneTerm final : public ForceTerm {
 public:
  // `given` as the world file has it; the term works with normalisedPlane(given).
  PlaneTerm(int points, const Plane& given, double side, const ContactSpring& spring);
  const Plane& plane() const { return plane_; }  // normalised
  double side() const { return side_; }
  // How many of the points p are strictly on the far side.
  int pointsAcross(const double* p) const;

  bool mayReach(const Bounds& box) const override { return mayCrossPlane(plane_, side_, box); }
  // pointsAcross(p), when the plane's spring pushes at all.
  int pointsInContact(const double* p) const override {
    return spring_.k == 0 && spring_.d == 0 ? 0 : pointsAcross(p);
  }
  void addForcesOn(PointRange points, const double* p, const double* v, const Bounds* box,
                   double* force) const override;
  void addJacobian(const double* p, const double* v, JacobianSink* sink) const override;
  void addEnergy(const double* p, double* energy) const override;
  void summarise(std::vector<std::string>* kept, std::vector<std::string>* leftOut) const override;
  std::vector<TermLine> describe(const double* p) const override;

 private:
  Plane given_, plane_;
  double side_;
  ContactSpring spring_;
};

}  // namespace jello
