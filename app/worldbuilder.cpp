// worldbuilder.cpp: recipes into worlds (the field through io/fieldrecipe).

#include "app/worldbuilder.h"

#include <cmath>
#include <cstdio>
#include <functional>
#include <iterator>

#include "app/describe.h"

namespace jello {

namespace {

constexpr double kCourseMass = 1.0 / kNumPoints;

Recipe courseBase(double dt, double kElastic, double kCollision) {
  Recipe r = defaultRecipe();
  r.run.dt = dt;
  r.world.kElastic = kElastic;
  r.world.kCollision = kCollision;
  r.field.source = FieldRecipe::Source::Uniform;  // the course's files hold a zero field
  r.field.resolution = kCourseResolution;
  return r;
}

// Rz * Ry * Rx applied to v, angles in degrees.
Vec3 rotate(Vec3 v, Vec3 degrees) {
  const double toRadians = kPi / 180;
  double a = degrees.x * toRadians, b = degrees.y * toRadians, c = degrees.z * toRadians;
  v = {v.x, std::cos(a) * v.y - std::sin(a) * v.z, std::sin(a) * v.y + std::cos(a) * v.z};
  v = {std::cos(b) * v.x + std::sin(b) * v.z, v.y, -std::sin(b) * v.x + std::cos(b) * v.z};
  v = {std::cos(c) * v.x - std::sin(c) * v.y, std::sin(c) * v.x + std::cos(c) * v.y, v.z};
  return v;
}

}  // namespace

Recipe defaultRecipe() {
  Recipe r;
  r.run = {Integrator::RK4, 0.001, 1};
  r.world.kElastic = 500;
  r.world.dElastic = 0.25;
  r.world.kCollision = 1000;
  r.world.dCollision = 0.25;
  r.world.mass = kCourseMass;
  return r;
}

namespace {

constexpr double kSeventh = 1.0 / 7;

Recipe jelloPreset() {
  Recipe r = courseBase(0.0005, 200, 400);
  r.world.hasPlane = true;
  r.world.plane = {-1, 1, 1, 2};
  r.state.skewCorner = {kSeventh, kSeventh, kSeventh};
  r.state.velocity = Vec3{10, -10, 20};
  return r;
}

Recipe rotatePreset() {
  Recipe r = courseBase(0.001, 500, 1000);
  r.world.hasPlane = true;
  r.world.plane = {1, -1, -1, 4};
  r.field.source = FieldRecipe::Source::Swirl;
  r.field.strength = 5.0 / 512;
  return r;
}

Recipe moveLeftPreset() {
  Recipe r = courseBase(0.0005, 500, 1000);
  r.state.velocity = Vec3{-50, 0, 0};
  return r;
}

Recipe skewedCornerPreset() {
  Recipe r = courseBase(0.00001, 500, 1000);
  r.state.skewCorner = {kSeventh, kSeventh, kSeventh};
  return r;
}

Recipe gravityPreset() {
  Recipe r = courseBase(0.0001, 500, 1000);
  r.world.hasPlane = true;
  r.world.plane = {-1, 1, 2, 6};
  r.field.uniform = {0, 0, -0.06};
  r.state.velocity = Vec3{10, -10, 0};
  return r;
}

// The course's five worlds, in the course's order.
constexpr Preset kPresets[] = {{"jello", jelloPreset},
                               {"rotate", rotatePreset},
                               {"moveLeft", moveLeftPreset},
                               {"skewedCorner", skewedCornerPreset},
                               {"gravity", gravityPreset}};

}  // namespace

std::vector<Preset> coursePresets() { return {std::begin(kPresets), std::end(kPresets)}; }

std::string presetNameList() {
  std::string list;
  for (std::size_t i = 0; i < std::size(kPresets); ++i)
    list += std::string(i == 0                         ? ""
                        : i + 1 == std::size(kPresets) ? " or "
                                                       : ", ") +
            kPresets[i].name;
  return list;
}

Recipe coursePreset(const std::string& name) {
  for (const Preset& preset : kPresets)
    if (name == preset.name) return preset.make();
  throw InputError("unknown preset '" + name + "', expected " + presetNameList());
}

State buildState(const StateRecipe& recipe) {
  State s;
  Vec3 centre;
  if (recipe.from) {
    s = *recipe.from;
    centre = extentOf(s).centroid;
  } else {
    const double spacing = recipe.cubeSize / (kLatticeSize - 1);
    for (int i = 0; i < kLatticeSize; ++i)
      for (int j = 0; j < kLatticeSize; ++j)
        for (int k = 0; k < kLatticeSize; ++k)
          store(s.p(), pointIndex(i, j, k), Vec3{i * spacing, j * spacing, k * spacing});
    centre = 0.5 * Vec3{recipe.cubeSize, recipe.cubeSize, recipe.cubeSize};
  }
  const Vec3 target = recipe.center.value_or(centre);
  const bool turned =
      recipe.rotateDegrees.x != 0 || recipe.rotateDegrees.y != 0 || recipe.rotateDegrees.z != 0;
  for (int q = 0; q < kNumPoints; ++q) {
    Vec3 r = load(s.p(), q) - centre;
    if (recipe.insideOut) r = -r;
    if (turned) {
      r = rotate(r, recipe.rotateDegrees);
      store(s.v(), q, rotate(load(s.v(), q), recipe.rotateDegrees));
    }
    // Unmoved points keep their exact coordinates (no round trip through the centre).
    if (turned || recipe.center || recipe.insideOut) store(s.p(), q, target + r);
  }
  // Each step below touches the state only when asked to, so that a world taken --from another
  // comes back bit for bit (even its signed zeros) when nothing else is asked.
  auto isZero = [](Vec3 a) { return a.x == 0 && a.y == 0 && a.z == 0; };
  const int corner = pointIndex(kLatticeSize - 1, kLatticeSize - 1, kLatticeSize - 1);
  if (!isZero(recipe.skewCorner)) store(s.p(), corner, load(s.p(), corner) + recipe.skewCorner);
  for (int q = 0; q < kNumPoints; ++q) {
    if (recipe.velocity) store(s.v(), q, *recipe.velocity);
    if (!isZero(recipe.spin))
      store(s.v(), q, load(s.v(), q) + cross(recipe.spin, load(s.p(), q) - target));
  }
  return s;
}

}  // namespace jello
