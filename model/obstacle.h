// model/obstacle.h: a scene's static obstacles (scene files, docs/scenes.md): a sphere, an
// axis-aligned box, a half-space bounded by a plane, or the container box that holds the jelly.
// Each pushes a point inside it out with the course's collision spring (model/contact.h), from
// the nearest point of its surface, and holds it back with Coulomb friction. A point term.
//
// Units: metres, seconds, newtons; k in N/m, d in N s/m, friction speeds in m/s. A penetration's
// normal is the unit vector pointing out of the obstacle (the way the point is pushed).
//
// Friction (why it is regularised): Coulomb's law is a set-valued force at zero sliding speed,
// which no explicit integrator steps across. Here the friction force on a point in contact is
//   F_t = -mu(s) N t / sqrt(s^2 + eps^2),  t = v - (v . n) n,  s = |t|,
//   mu(s) = mu_d + (mu_s - mu_d) exp(-s / (kStribeckRatio eps)),
// N = max(0, k depth - d v . n) the contact's normal push: a smooth function of the velocity, at
// most mu_s N, tending to mu_d N when sliding fast (above the Stribeck speed kStribeckRatio eps).
// A tangential load below about 0.9 mu_s N (the largest F_t reaches at low speed, near s = 5 eps)
// is held: the point creeps at a few eps instead of sticking. A smaller eps (scene key
// friction_speed) creeps less but is stiffer (dF/dv ~ mu N / eps) and needs a smaller dt.
#pragma once

#include <optional>
#include <string>

#include "model/contact.h"
#include "model/term.h"

namespace jello {

// Friction's regularisation speed by default, m/s, and the Stribeck speed's ratio to it.
constexpr double kDefaultFrictionSpeed = 0.01;
constexpr double kStribeckRatio = 20;

// A friction coefficient is at most this (few pairs of materials exceed 2; a point that must
// not slide is pinned instead).
constexpr double kMostFriction = 10;

struct Friction {
  double muStatic = 0, muDynamic = 0;    // >= 0, muDynamic <= muStatic
  double speed = kDefaultFrictionSpeed;  // eps, m/s, > 0
};

// Friction's rule, the one the scene reader, the panel and the scene writer keep (docs/scenes.md):
// 0 <= muDynamic <= muStatic <= kMostFriction and speed > 0 (each finite). Where `f` breaks it:
// the scene file's key and why, in its words.
struct FrictionFault {
  const char* key;  // "friction_static", "friction_dynamic" or "friction_speed"
  std::string why;
};
std::optional<FrictionFault> frictionFault(const Friction& f);

enum class ObstacleShape {
  Sphere,     // solid ball: centre, radius
  Box,        // solid axis-aligned box: lower, upper
  HalfSpace,  // solid { p : normal . (p - point) < 0 }; normal is a unit vector
  Container,  // the points are kept INSIDE the box lower..upper (a scene's bounding box)
};

// "sphere", "box", "plane" or "bounding box": the scene file's words for the shapes.
const char* obstacleShapeName(ObstacleShape shape);

struct Obstacle {
  ObstacleShape shape = ObstacleShape::Sphere;
  Vec3 centre;         // Sphere, m
  double radius = 0;   // Sphere, m, > 0
  Vec3 lower, upper;   // Box, Container, m
  Vec3 point, normal;  // HalfSpace: a point of the plane (m) and the unit normal out of the solid
  Vec3 givenNormal;    // HalfSpace: the normal as given, not zero (a scene written back says it)
  ContactSpring spring;
  Friction friction;
};

// A point inside an obstacle: how deep (m, > 0) and the unit normal out of it.
struct Penetration {
  double depth = 0;
  Vec3 normal;
};
// The point's penetrations of the obstacle: at most one, except in a container, where a point
// beyond several walls (a corner) has one for each (as the course's walls). Returns the count.
int penetrations(const Obstacle& obstacle, Vec3 p, Penetration out[3]);

// The contact's force for one penetration: the collision spring along the normal plus friction.
Vec3 penetrationForce(const Obstacle& obstacle, const Penetration& pen, Vec3 v);
// The friction part alone (for tests and the description).
Vec3 frictionForce(const Friction& friction, double push, Vec3 normal, Vec3 v);
// Sum over the point's penetrations.
Vec3 obstacleForce(const Obstacle& obstacle, Vec3 p, Vec3 v);
// Its derivatives with respect to the point's position and velocity, exact (a sphere's normal
// turns as the point moves; the friction's regularisation is differentiated too).
void obstacleJacobian(const Obstacle& obstacle, Vec3 p, Vec3 v, Block3* dFdp, Block3* dFdv);

// Whether a point holds or slips against an obstacle (the window's friction colouring, README:
// The viewer). The regularised friction has no true sticking: a held point creeps (above). Up to
// about 3 eps the force still rises steeply with the slip (0.7 mu N at eps, 0.9 mu N at 3 eps for
// the scenes' mu), so a load it can hold settles at a steady creep below that: "sticking" (the
// scenes' slope holds its jelly, its bottom points slipping at up to 1.8 eps). Faster, the force is
// at its limit and the point slides. "None": out of contact, in contact without a push (leaving
// faster than the spring pushes), or against an obstacle without friction. Ordered: a point that
// slides against any obstacle slides (strongerState).
enum class FrictionState { None, Sticking, Sliding };
constexpr double kStickingSpeedRatio = 3;
FrictionState frictionState(const Obstacle& obstacle, Vec3 p, Vec3 v);
inline FrictionState strongerState(FrictionState a, FrictionState b) { return a < b ? b : a; }

// "sphere at (0, 0, -1), radius 0.5 m", and the like.
std::string obstacleText(const Obstacle& obstacle);

class ObstacleTerm final : public ForceTerm {
 public:
  ObstacleTerm(int points, const Obstacle& obstacle) : ForceTerm(points), obstacle_(obstacle) {}
  const Obstacle& obstacle() const { return obstacle_; }

  bool mayReach(const Bounds& box) const override;
  int pointsInContact(const double* p) const override;
  void addForcesOn(PointRange points, const double* p, const double* v, const Bounds* box,
                   double* force) const override;
  void addJacobian(const double* p, const double* v, JacobianSink* sink) const override;
  void addEnergy(const double* p, double* energy) const override;
  void summarise(std::vector<std::string>* kept, std::vector<std::string>* leftOut) const override;
  std::vector<TermLine> describe(const double* p) const override;

 private:
  Obstacle obstacle_;
};

}  // namespace jello
