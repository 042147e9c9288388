// model/model.cpp: the force terms of a world, in the order their forces are summed. See
// model.h for units and signs, the terms' own files for the terms themselves.

#include "model/model.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/assert.h"
#include "model/gravity.h"
#include "model/obstacle.h"
#include "model/scenespec.h"

namespace jello {

namespace {

// The field as the specialised list computes it, or why it is left out.
void addField(const World& world, int n, KernelChoice choice, ForceTerms* forces) {
  if (choice == KernelChoice::General) {
    forces->terms.push_back(
        std::make_unique<FieldTerm>(n, world.field, world.mass, FieldTerm::Method::Reference));
    return;
  }
  switch (fieldUse(world.field)) {
    case FieldUse::Absent:
      forces->leftOut.push_back("field (none in the file)");
      return;
    case FieldUse::Zero:
      forces->leftOut.push_back("field (all zero)");
      return;
    case FieldUse::Uniform:
      forces->terms.push_back(
          std::make_unique<FieldTerm>(n, world.field, world.mass, FieldTerm::Method::Uniform));
      return;
    case FieldUse::Trilinear:
      // A field fieldUse calls trilinear has R >= 2: one node would be uniform.
      forces->terms.push_back(
          std::make_unique<FieldTerm>(n, world.field, world.mass, FieldTerm::Method::Padded));
      return;
  }
}

// What a scene file adds after the course's terms (so that a scene that adds nothing sums as the
// course world does): gravity, then the obstacles in the file's order.
void addSceneTerms(const World& world, const std::vector<double>& pointMass, const SceneSpec& spec,
                   ForceTerms* forces) {
  const int n = static_cast<int>(pointMass.size());
  if (spec.gravity.x != 0 || spec.gravity.y != 0 || spec.gravity.z != 0) {
    if (spec.jellies.empty() && !hasElements(world))
      forces->terms.push_back(std::make_unique<GravityTerm>(n, spec.gravity, world.mass));
    else
      forces->terms.push_back(std::make_unique<GravityTerm>(spec.gravity, pointMass));
  }
  for (const Obstacle& obstacle : spec.obstacles)
    forces->terms.push_back(std::make_unique<ObstacleTerm>(n, obstacle));
}

// Contact between the scene's jellies, or of its one jelly with itself.
void addBodyContact(const Body& body, const SceneSpec& spec, ForceTerms* forces) {
  const BodyContactSpec& contact = *spec.bodyContact;
  std::vector<ContactPart> parts;
  auto radius = [&](const Body& b) {
    return contact.distance > 0 ? contact.distance / 2 : b.spacing / 2;
  };
  if (body.joined())
    for (std::size_t p = 0; p < body.parts.size(); ++p)
      parts.push_back({radius(*body.parts[p]), spec.jellies[p].selfContact});
  else
    parts.push_back({radius(body), spec.selfContact});
  forces->terms.push_back(std::make_unique<BodyContactTerm>(body, std::move(parts), contact));
}

// The terms of `world` in the order their forces are summed. The field term reads the nodes of
// `world`, which must be the model's own; `pointMass` is each point's (pointMassesOf).
ForceTerms buildForceTerms(const World& world, const State& initial,
                           const std::vector<double>& pointMass, KernelChoice choice) {
  ForceTerms forces;
  const bool general = choice == KernelChoice::General;
  forces.culling = !general;
  const SceneSpec* spec = world.scene.get();
  const Body& body = bodyOf(world);
  const int n = body.count();
  std::vector<SpringConstants> byPart;
  bool damping = false;
  if (spec && !spec->jellies.empty())
    for (const JellySpec& jelly : spec->jellies) byPart.push_back(jelly.springs);
  else
    byPart.push_back(springConstantsOf(world));
  for (const SpringConstants& c : byPart) damping = damping || c.anyDamping();
  auto springs = std::make_unique<SpringTerm>(body, std::move(byPart), general || damping,
                                              general ? SpringKernel::List : SpringKernel::Fastest);
  forces.springs = springs.get();
  forces.terms.push_back(std::move(springs));
  if (hasElements(world)) {
    auto elements = std::make_unique<ElementTerm>(body, materialsOf(world), pointMass);
    forces.elements = elements.get();
    forces.terms.push_back(std::move(elements));
  }
  if (spec && spec->bodyContact) addBodyContact(body, *spec, &forces);
  const ContactSpring contact{world.kCollision, world.dCollision};
  if (hasCourseWalls(spec))
    forces.terms.push_back(std::make_unique<WallsTerm>(n, contact));
  else if (spec->bounds)
    forces.terms.push_back(std::make_unique<ObstacleTerm>(n, *spec->bounds));
  else
    forces.leftOut.push_back("walls (the scene has no bounding box)");
  if (world.hasPlane) {
    auto plane = std::make_unique<PlaneTerm>(n, world.plane,
                                             allowedSide(world.plane, initial.p(), n), contact);
    forces.plane = plane.get();
    forces.terms.push_back(std::move(plane));
  } else {
    // In a scene, the course world's inclined plane, not the scene's own [[plane]] obstacles.
    forces.leftOut.push_back(spec ? "the course's inclined plane (none in the world)"
                                  : "plane (none in the file)");
  }
  addField(world, n, choice, &forces);
  if (spec) addSceneTerms(world, pointMass, *spec, &forces);
  return forces;
}

}  // namespace

TermSummary summarise(const ForceTerms& forces) {
  TermSummary summary;
  for (const auto& term : forces.terms) term->summarise(&summary.kept, &summary.leftOut);
  summary.leftOut.insert(summary.leftOut.end(), forces.leftOut.begin(), forces.leftOut.end());
  return summary;
}

std::string listText(const std::vector<std::string>& parts) {
  std::string out;
  for (const std::string& part : parts) out += (out.empty() ? "" : ", ") + part;
  return out.empty() ? std::string("nothing") : out;
}

std::string termsLine(const ForceTerms& forces) {
  const TermSummary summary = summarise(forces);
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

std::vector<Material> materialsOf(const World& world) {
  if (!world.scene) return {Material{}};
  if (world.scene->jellies.empty()) return {world.scene->material};
  std::vector<Material> out;
  for (const JellySpec& jelly : world.scene->jellies) out.push_back(jelly.material);
  return out;
}

bool hasElements(const World& world) {
  for (const Material& m : materialsOf(world))
    if (m.elements()) return true;
  return false;
}

std::vector<double> pointMassesOf(const World& world) {
  const Body& body = bodyOf(world);
  std::vector<double> mass(body.count(), world.mass);
  if (world.scene && !world.scene->jellies.empty())
    for (int q = 0; q < body.count(); ++q) mass[q] = world.scene->jellies[body.partOf(q)].mass;
  const std::vector<Material> materials = materialsOf(world);
  for (std::size_t part = 0; part < materials.size(); ++part) {
    if (!materials[part].elements()) continue;
    const Body& own = body.joined() ? *body.parts[part] : body;
    const int first = body.joined() ? body.partFirst[part] : 0;
    for (int q = first; q < first + own.count(); ++q) mass[q] = 0;
    const std::vector<double> rest = restPositionsOf(own);
    for (const Tet& t : tetrahedraOf(own)) {
      const double share = materials[part].density * tetVolume(t, rest.data(), own.count()) / 4;
      for (int q : t) mass[first + q] += share;
    }
  }
  return mass;
}

bool hasCourseSprings(const World& world) {
  return courseSprings(bodyOf(world), springConstantsOf(world));
}

Model makeModel(const World& world, const State& initial, KernelChoice choice) {
  JELLO_ASSERT(initial.points() == bodyOf(world).count());
  Model model;
  model.world = world;
  model.pointMass = pointMassesOf(model.world);
  model.forces = buildForceTerms(model.world, initial, model.pointMass, choice);
  if (world.scene) model.pinned = world.scene->pinned;
  const auto& mass = model.pointMass;
  if (std::all_of(mass.begin(), mass.end(), [&](double m) { return m == mass[0]; }))
    model.commonMass = mass.empty() ? 0 : mass[0];
  JELLO_ASSERT(model.forces.terms.size() <= kMaxTerms);
  return model;
}

int pointsAcrossPlane(const Model& model, const State& state) {
  return model.forces.plane ? model.forces.plane->pointsAcross(state.p()) : 0;
}

Vec3 pullForce(const Pull& pull, Vec3 p) { return pull.stiffness * (pull.target - p); }

}  // namespace jello
