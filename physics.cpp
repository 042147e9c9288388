// physics.cpp: the scene of a world, the force kernel that sums its terms, and the derivative
// of a state. See physics.h for units and signs, forces/ for the terms themselves.

#include "physics.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/assert.h"
#include "core/team.h"
#include "forces/gravity.h"
#include "forces/obstacle.h"
#include "scene/spec.h"

namespace jello {

namespace {

// The field as a specialised scene computes it, or why it is left out.
void addField(const World& world, int n, KernelChoice choice, Scene* scene) {
  if (choice == KernelChoice::General) {
    scene->terms.push_back(
        std::make_unique<FieldTerm>(n, world.field, world.mass, FieldTerm::Method::Reference));
    return;
  }
  switch (fieldUse(world.field)) {
    case FieldUse::Absent:
      scene->leftOut.push_back("field (none in the file)");
      return;
    case FieldUse::Zero:
      scene->leftOut.push_back("field (all zero)");
      return;
    case FieldUse::Uniform:
      scene->terms.push_back(
          std::make_unique<FieldTerm>(n, world.field, world.mass, FieldTerm::Method::Uniform));
      return;
    case FieldUse::Trilinear:
      // A field the scene calls trilinear has R >= 2: one node would be uniform.
      scene->terms.push_back(
          std::make_unique<FieldTerm>(n, world.field, world.mass, FieldTerm::Method::Padded));
      return;
  }
}

// What a scene file adds after the course's terms (so that a scene that adds nothing sums as the
// course world does): gravity, then the obstacles in the file's order.
void addSceneTerms(const World& world, int n, const SceneSpec& spec, Scene* scene) {
  if (spec.gravity.x != 0 || spec.gravity.y != 0 || spec.gravity.z != 0)
    scene->terms.push_back(std::make_unique<GravityTerm>(n, spec.gravity, world.mass));
  for (const Obstacle& obstacle : spec.obstacles)
    scene->terms.push_back(std::make_unique<ObstacleTerm>(n, obstacle));
}

// The terms of `world` in the order their forces are summed. The field term reads the nodes of
// `world`, which must be the model's own.
Scene buildScene(const World& world, const State& initial, KernelChoice choice) {
  Scene scene;
  const bool general = choice == KernelChoice::General;
  scene.culling = !general;
  const SceneSpec* spec = world.scene.get();
  const Body& body = bodyOf(world);
  const int n = body.count();
  const SpringConstants constants = springConstantsOf(world);
  auto springs = std::make_unique<SpringTerm>(body, constants, general || constants.anyDamping());
  scene.springs = springs.get();
  scene.terms.push_back(std::move(springs));
  const ContactSpring contact{world.kCollision, world.dCollision};
  if (hasCourseWalls(spec))
    scene.terms.push_back(std::make_unique<WallsTerm>(n, contact));
  else if (spec->bounds)
    scene.terms.push_back(std::make_unique<ObstacleTerm>(n, *spec->bounds));
  else
    scene.leftOut.push_back("walls (the scene has no bounding box)");
  if (world.hasPlane) {
    auto plane = std::make_unique<PlaneTerm>(n, world.plane,
                                             allowedSide(world.plane, initial.p(), n), contact);
    scene.plane = plane.get();
    scene.terms.push_back(std::move(plane));
  } else {
    // In a scene, the course world's inclined plane, not the scene's own [[plane]] obstacles.
    scene.leftOut.push_back(spec ? "the course's inclined plane (none in the world)"
                                 : "plane (none in the file)");
  }
  addField(world, n, choice, &scene);
  if (spec) addSceneTerms(world, n, *spec, &scene);
  return scene;
}

constexpr int kMaxTerms = 8 + kMostObstacles;

}  // namespace

SceneSummary summarise(const Scene& scene) {
  SceneSummary summary;
  for (const auto& term : scene.terms) term->summarise(&summary.kept, &summary.leftOut);
  summary.leftOut.insert(summary.leftOut.end(), scene.leftOut.begin(), scene.leftOut.end());
  return summary;
}

std::string listText(const std::vector<std::string>& parts) {
  std::string out;
  for (const std::string& part : parts) out += (out.empty() ? "" : ", ") + part;
  return out.empty() ? std::string("nothing") : out;
}

std::string sceneLine(const Scene& scene) {
  const SceneSummary summary = summarise(scene);
  return "scene: kept: " + listText(summary.kept) + "; left out: " + listText(summary.leftOut);
}

const Body& Model::body() const { return bodyOf(world); }

const Body& bodyOf(const World& world) {
  return world.scene && world.scene->body ? *world.scene->body : courseBody();
}

SpringConstants springConstantsOf(const World& world) {
  if (world.scene && world.scene->springs) return *world.scene->springs;
  return SpringConstants::same(world.kElastic, world.dElastic);
}

bool hasCourseSprings(const World& world) {
  return courseSprings(bodyOf(world), springConstantsOf(world));
}

Model makeModel(const World& world, const State& initial, KernelChoice choice) {
  JELLO_ASSERT(initial.points() == bodyOf(world).count());
  Model model;
  model.world = world;
  model.scene = buildScene(model.world, initial, choice);
  if (world.scene) model.pinned = world.scene->pinned;
  JELLO_ASSERT(model.scene.terms.size() <= kMaxTerms);
  return model;
}

int pointsAcrossPlane(const Model& model, const State& state) {
  return model.scene.plane ? model.scene.plane->pointsAcross(state.p()) : 0;
}

Vec3 pullForce(const Pull& pull, Vec3 p) { return pull.stiffness * (pull.target - p); }

// The pair terms add into the total; the point terms in reach add into their own sum first,
// which then joins the total (one term alone adds directly: x + (0 + y) is x + y). This is the
// order docs/physics.md gives the terms in, so every kernel rounds alike, and every range of
// points gets the forces the whole pass gives it.
void computeForcesOn(const Model& model, PointRange points, const double* p, const double* v,
                     const Bounds* reach, double* force, const Pull* pull,
                     const double* springForce) {
  const int n = model.points();
  for (int a = 0; a < 3; ++a)
    std::fill(force + a * n + points.begin, force + a * n + points.end, 0.0);
  const ForceTerm* inReach[kMaxTerms];
  int count = 0;
  for (const auto& term : model.scene.terms) {
    if (springForce && term.get() == model.scene.springs)
      model.scene.springs->addListedForces(points, springForce, force);
    else if (term->isPairTerm())
      term->addForcesOn(points, p, v, reach, force);
    else if (!reach || term->mayReach(*reach))
      inReach[count++] = term.get();
  }
  if (count == 1) {
    inReach[0]->addForcesOn(points, p, v, reach, force);
  } else if (count > 1) {
    // The course cube's sum fits on the stack; a larger body's is this thread's own, grown once.
    alignas(64) double onStack[kNumCoords];
    thread_local std::vector<double> grown;
    if (3 * n > kNumCoords && grown.size() < std::size_t(3 * n)) grown.resize(3 * n);
    double* sum = 3 * n > kNumCoords ? grown.data() : onStack;
    for (int a = 0; a < 3; ++a)
      std::fill(sum + a * n + points.begin, sum + a * n + points.end, 0.0);
    for (int t = 0; t < count; ++t) inReach[t]->addForcesOn(points, p, v, reach, sum);
    for (int a = 0; a < 3; ++a)
      for (int q = a * n + points.begin; q < a * n + points.end; ++q) force[q] += sum[q];
  }
  if (pull && pull->point >= points.begin && pull->point < points.end)
    store(force, pull->point, n,
          load(force, pull->point, n) + pullForce(*pull, load(p, pull->point, n)));
}

namespace {

// The two threads' ranges: for the row kernel balancedSplitPoint; for the spring list, whose
// points cost alike, halves (the first a multiple of kRangeAlignment points).
PointRange teamPart(const Model& model, int part) {
  static const int rowSplit = balancedSplitPoint();
  const int n = model.points();
  const int split = model.scene.springs->rowKernel()
                        ? rowSplit
                        : (n / 2 + kRangeAlignment / 2) / kRangeAlignment * kRangeAlignment;
  return part == 0 ? PointRange{0, split} : PointRange{split, n};
}

// With two threads, a spring list's forces are computed a spring at a time, half the springs
// each, before the points' ranges gather them (each spring once, where a range alone computes the
// springs of its points, each at both ends). Into this thread's buffer, grown once. Null for the
// row kernel, whose rows split as they are.
const double* listedSpringForces(const Model& model, const double* p, const double* v, Team* team) {
  const SpringTerm& springs = *model.scene.springs;
  if (springs.rowKernel()) return nullptr;
  thread_local std::vector<double> buffer;
  const int count = static_cast<int>(springs.springs().size());
  if (buffer.size() < std::size_t(3 * count)) buffer.resize(3 * count);
  double* out = buffer.data();
  team->run([&](int part) {
    springs.listSpringForces(part == 0 ? 0 : count / 2, part == 0 ? count / 2 : count, p, v, out);
  });
  return out;
}

// dp/dt and dv/dt = F/mass on the points of `points`.
void derivativeOn(const Model& model, PointRange points, const double* y, const Bounds* reach,
                  double* dydt, const Pull* pull, const double* springForce) {
  const int n = model.points();
  const double* p = y;
  const double* v = y + 3 * n;
  double* a = dydt + 3 * n;
  computeForcesOn(model, points, p, v, reach, a, pull, springForce);
  const double mass = model.world.mass;
  for (int axis = 0; axis < 3; ++axis) {
    const int first = axis * n + points.begin, end = axis * n + points.end;
    std::copy(v + first, v + end, dydt + first);
    for (int c = first; c < end; ++c) a[c] /= mass;
  }
  // A pinned point neither moves nor accelerates: every integrator keeps it exactly where it is.
  for (int q : model.pinned)
    if (q >= points.begin && q < points.end)
      for (int axis = 0; axis < 3; ++axis)
        dydt[coordIndex(q, axis, n)] = a[coordIndex(q, axis, n)] = 0;
}

}  // namespace

void computeForces(const Model& model, const double* p, const double* v, double* force,
                   const Pull* pull, Team* team) {
  const Bounds box = model.scene.culling ? boundsOf(p, model.points()) : Bounds{};
  const Bounds* reach = model.scene.culling ? &box : nullptr;
  if (!team)
    computeForcesOn(model, {0, model.points()}, p, v, reach, force, pull);
  else {
    const double* springForce = listedSpringForces(model, p, v, team);
    team->run([&](int part) {
      computeForcesOn(model, teamPart(model, part), p, v, reach, force, pull, springForce);
    });
  }
}

void derivative(const Model& model, const double* y, double* dydt, const Pull* pull, Team* team) {
  const Bounds box = model.scene.culling ? boundsOf(y, model.points()) : Bounds{};
  const Bounds* reach = model.scene.culling ? &box : nullptr;
  if (!team)
    derivativeOn(model, {0, model.points()}, y, reach, dydt, pull, nullptr);
  else {
    const double* springForce = listedSpringForces(model, y, y + model.coords(), team);
    team->run([&](int part) {
      derivativeOn(model, teamPart(model, part), y, reach, dydt, pull, springForce);
    });
  }
}

int findDivergedPoint(const State& state) {
  const double* p = state.p();
  const double* v = state.v();
  const int n = state.points();
  for (int q = 0; q < n; ++q) {
    Vec3 pq = load(p, q, n), vq = load(v, q, n);
    bool finite = std::isfinite(pq.x) && std::isfinite(pq.y) && std::isfinite(pq.z) &&
                  std::isfinite(vq.x) && std::isfinite(vq.y) && std::isfinite(vq.z);
    if (!finite || dot(pq, pq) > kDivergenceRadius * kDivergenceRadius) return q;
  }
  return -1;
}

}  // namespace jello
