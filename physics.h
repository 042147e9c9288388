// physics.h: the forces of the jello model (docs/physics.md) and the derivative of a state.
//
// Units: metres, seconds, kilograms, newtons. Sign convention: every force term returns the
// force ON the point it is asked about (for a spring, on its end `a`; its end `b` gets minus
// that). L always points from the anchor (the other end, or the contact point) to the point.
// Each term lives in forces/ (one file each: its force, Jacobian, energy, reach test and
// description); this file puts them together into a scene. It links no GL.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "forces/field.h"
#include "forces/plane.h"
#include "forces/springs.h"
#include "forces/term.h"
#include "forces/walls.h"
#include "vec3.h"
#include "world.h"

namespace jello {

class Team;  // core/team.h

// Which force kernel a model uses: the one made for its scene, or the one that computes every
// term everywhere (the reference the specialisations are tested and timed against).
enum class KernelChoice { Specialised, General };

// The terms a world needs, in the order their forces are summed: the springs, the walls, the
// plane, the field (docs/physics.md). A specialised scene leaves out what adds
// nothing (dampers without damping, a plane the file does not have, a zero field), computes a
// uniform field as a constant, and lets every term skip its work when the cube's bounding box
// is out of its reach (culling). The general scene computes every term for every point.
struct Scene {
  std::vector<std::unique_ptr<ForceTerm>> terms;  // owned; pair terms first
  std::vector<std::string> leftOut;               // what the world does not need, and why
  bool culling = true;
  const SpringTerm* springs = nullptr;  // in terms, always there
  const PlaneTerm* plane = nullptr;     // in terms, or null without a plane
};
// What a scene computes ("springs", "plane (when the bounding box reaches it)", ...) and what it
// leaves out, and why: its terms' parts, then the terms it does not have.
struct SceneSummary {
  std::vector<std::string> kept, leftOut;
};
SceneSummary summarise(const Scene& scene);
// "a, b, c", or "nothing" for no parts.
std::string listText(const std::vector<std::string>& parts);
// "scene: kept: ...; left out: ...", naming every term of the force.
std::string sceneLine(const Scene& scene);

// A world ready to simulate: its parameters and what is derived from them once. Moved, never
// copied: its terms point into its world's field.
struct Model {
  World world;
  Scene scene;
  std::vector<int>
      pinned;  // the scene's pinned points (scene/spec.h), sorted; none for a course world

  Model() = default;
  Model(Model&&) = default;
  Model& operator=(Model&&) = default;
  Model(const Model&) = delete;
  Model& operator=(const Model&) = delete;

  const std::vector<Spring>& springs() const { return scene.springs->springs(); }
  // The body (body.h): the course cube, or a scene's. It lives as long as the world's scene.
  const Body& body() const;
  int points() const { return scene.springs->pointCount(); }
  int coords() const { return 3 * points(); }
  // The plane as the forces use it (normalisedPlane of the world's; only when the world has
  // one), and the sign of a*x + b*y + c*z + d on its allowed side (+1 or -1; +1 without one).
  const Plane& plane() const { return scene.plane->plane(); }
  double planeSide() const { return scene.plane ? scene.plane->side() : 1; }
};
// The body of a world: its scene's, or the course cube.
const Body& bodyOf(const World& world);
// The springs' constants: a scene's per kind, or the world's kElastic and dElastic for all.
SpringConstants springConstantsOf(const World& world);
// Whether the world's jelly is the course cube with the course's springs (courseSprings).
bool hasCourseSprings(const World& world);
// `initial` holds the body's points.
Model makeModel(const World& world, const State& initial,
                KernelChoice choice = KernelChoice::Specialised);

// How many points of `state` are strictly on the far side of the model's plane (0 without one).
int pointsAcrossPlane(const Model& model, const State& state);

// A user's pull on one point (the viewer's left-drag): a spring of rest length 0 from the point
// to a target the user moves. point < 0: no pull.
struct Pull {
  int point = -1;
  Vec3 target;           // m
  double stiffness = 0;  // N/m
};
// F = stiffness (target - p) on the pulled point.
Vec3 pullForce(const Pull& pull, Vec3 p);

// The force kernel: total force on every point (per-point arrays, see coordIndex) for
// positions p and velocities v, with the user's pull when there is one: the scene's terms,
// each skipped when the positions are out of its reach. With a team, its two threads take a
// range of points each (balancedSplitPoint), with the same result bit for bit.
void computeForces(const Model& model, const double* p, const double* v, double* force,
                   const Pull* pull = nullptr, Team* team = nullptr);

// The same on the points of `points` alone (force elsewhere is left as it was), with `reach` the
// bounds of all the positions when the scene culls (null when it does not): what computeForces
// does, a range at a time, bit for bit.
// springForce: the spring list's forces a spring at a time (SpringTerm::listSpringForces), to
// gather rather than compute; null to compute them.
void computeForcesOn(const Model& model, PointRange points, const double* p, const double* v,
                     const Bounds* reach, double* force, const Pull* pull,
                     const double* springForce = nullptr);

// The derivative of a state y = [p; v] (2 * model.coords() doubles): dp/dt = v, dv/dt = F/mass.
// With a team, its two threads take half the points each (balancedSplitPoint for the course
// cube's row kernel, halves of a spring list's points), with the same result.
void derivative(const Model& model, const double* y, double* dydt, const Pull* pull = nullptr,
                Team* team = nullptr);

constexpr double kDivergenceRadius = 100.0;  // m: a point further from the origin has diverged

// Index of the first point with a non-finite coordinate or velocity, or further than
// kDivergenceRadius from the origin; -1 when the state is sane.
int findDivergedPoint(const State& state);

}  // namespace jello
