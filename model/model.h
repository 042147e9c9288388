// model/model.h: a world ready to simulate: its force terms, put together once (docs/physics.md).
//
// Units: metres, seconds, kilograms, newtons. Sign convention: every force term returns the
// force ON the point it is asked about (for a spring, on its end `a`; its end `b` gets minus
// that). L always points from the anchor (the other end, or the contact point) to the point.
// Each term lives in a file of its own here in model/ (its force, Jacobian, energy, reach test and
// description); this file puts them together into a world's list of terms. The sum of their
// forces and the derivative of a state are solver/physics.h's. No file I/O, no GL.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "model/bodycontact.h"
#include "model/elements.h"
#include "model/field.h"
#include "model/plane.h"
#include "model/scenespec.h"
#include "model/springs.h"
#include "model/term.h"
#include "model/vec3.h"
#include "model/walls.h"
#include "model/world.h"

namespace jello {

// Which force kernel a model uses: the one made for its scene, or the one that computes every
// term everywhere (the reference the specialisations are tested and timed against).
enum class KernelChoice { Specialised, General };

// The terms a world needs, in the order their forces are summed: the springs, a scene's contact
// between bodies (the pair terms), the walls, the plane, the field, then a scene file's gravity
// and obstacles (docs/physics.md). The specialised
// list leaves out what adds nothing (dampers without damping, a plane the file does not have, a
// zero field), computes a uniform field as a constant, and lets every term skip its work when the
// cube's bounding box is out of its reach (culling). The general list computes every term for
// every point.
// The most terms a list holds: the springs, walls, plane, field and gravity, and a scene's
// obstacles (its bounding box among them). The force kernel keeps the terms in reach on the stack.
constexpr int kMaxTerms = 9 + kMostObstacles;

struct ForceTerms {
  std::vector<std::unique_ptr<ForceTerm>> terms;  // owned; pair terms first
  std::vector<std::string> leftOut;               // what the world does not need, and why
  bool culling = true;
  const SpringTerm* springs = nullptr;    // in terms, always there
  const PlaneTerm* plane = nullptr;       // in terms, or null without a plane
  const ElementTerm* elements = nullptr;  // in terms when a jelly is made of elements, else null
};
// What a list of terms computes ("springs", "plane (when the bounding box reaches it)", ...) and
// what it leaves out, and why: its terms' parts, then the terms it does not have.
struct TermSummary {
  std::vector<std::string> kept, leftOut;
};
TermSummary summarise(const ForceTerms& forces);
// "a, b, c", or "nothing" for no parts.
std::string listText(const std::vector<std::string>& parts);
// "scene: kept: ...; left out: ...", naming every term of the force.
std::string termsLine(const ForceTerms& forces);

// A world ready to simulate: its parameters and what is derived from them once. Moved, never
// copied: its terms point into its world's field.
struct Model {
  World world;
  ForceTerms forces;
  std::vector<int>
      pinned;  // the scene's pinned points (scenespec.h), sorted; none for a course world
  // Each point's mass, kg: the world's mass for one jelly, each jelly's own for several; and
  // that mass when every point has it (0 when they differ).
  std::vector<double> pointMass;
  double commonMass = 0;

  Model() = default;
  Model(Model&&) = default;
  Model& operator=(Model&&) = default;
  Model(const Model&) = delete;
  Model& operator=(const Model&) = delete;

  const std::vector<Spring>& springs() const { return forces.springs->springs(); }
  // The body (body.h): the course cube, or a scene's. It lives as long as the world's scene.
  const Body& body() const;
  int points() const { return forces.springs->pointCount(); }
  int coords() const { return 3 * points(); }
  // The plane as the forces use it (normalisedPlane of the world's; only when the world has
  // one), and the sign of a*x + b*y + c*z + d on its allowed side (+1 or -1; +1 without one).
  const Plane& plane() const { return forces.plane->plane(); }
  double planeSide() const { return forces.plane ? forces.plane->side() : 1; }
};
// The body of a world: its scene's, or the course cube.
const Body& bodyOf(const World& world);
// The springs' constants: a scene's per kind, or the world's kElastic and dElastic for all (for
// several jellies, the first's).
SpringConstants springConstantsOf(const World& world);
// Each part's material (one for a body that is not joined): springs for a course world.
std::vector<Material> materialsOf(const World& world);
// Whether some jelly of the world is made of finite elements.
bool hasElements(const World& world);
// Each point's mass, kg (Model::pointMass): a jelly of springs gives each point its mass; a jelly
// of elements lumps each tetrahedron's density * volume, a quarter to each of its points.
std::vector<double> pointMassesOf(const World& world);
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

}  // namespace jello
