// worldbuilder.cpp: recipes into worlds. Field expressions are evaluated by muparser.

#include "app/worldbuilder.h"

#include <muParser.h>

#include <cmath>
#include <cstdio>
#include <functional>

#include "app/describe.h"

namespace jello {

namespace {

constexpr int kCourseResolution = 30;
constexpr double kCourseMass = 1.0 / kNumPoints;

Recipe courseBase(double dt, double kElastic, double kCollision) {
  Recipe r = defaultRecipe();
  r.world.dt = dt;
  r.world.kElastic = kElastic;
  r.world.kCollision = kCollision;
  r.field.source = FieldRecipe::Source::Uniform;  // the course's files hold a zero field
  r.field.resolution = kCourseResolution;
  return r;
}

void fillNodes(ForceField& field, int r, const std::function<Vec3(Vec3)>& force) {
  field.resolution = r;
  field.forces.assign(3 * static_cast<std::size_t>(r) * r * r, 0.0);
  for (int i = 0; i < r; ++i)
    for (int j = 0; j < r; ++j)
      for (int k = 0; k < r; ++k) {
        Vec3 p = r == 1 ? Vec3{}
                        : Vec3{fieldNodeCoordinate(i, r), fieldNodeCoordinate(j, r),
                               fieldNodeCoordinate(k, r)};
        field.setNode((i * r + j) * r + k, force(p));
      }
}

std::string trim(const std::string& s) {
  std::size_t first = s.find_first_not_of(" \t"), last = s.find_last_not_of(" \t");
  return first == std::string::npos ? std::string() : s.substr(first, last - first + 1);
}

// Rz * Ry * Rx applied to v, angles in degrees.
Vec3 rotate(Vec3 v, Vec3 degrees) {
  const double toRadians = 3.14159265358979323846 / 180;
  double a = degrees.x * toRadians, b = degrees.y * toRadians, c = degrees.z * toRadians;
  v = {v.x, std::cos(a) * v.y - std::sin(a) * v.z, std::sin(a) * v.y + std::cos(a) * v.z};
  v = {std::cos(b) * v.x + std::sin(b) * v.z, v.y, -std::sin(b) * v.x + std::cos(b) * v.z};
  v = {std::cos(c) * v.x - std::sin(c) * v.y, std::sin(c) * v.x + std::cos(c) * v.y, v.z};
  return v;
}

}  // namespace

Recipe defaultRecipe() {
  Recipe r;
  r.world.integrator = Integrator::RK4;
  r.world.dt = 0.001;
  r.world.n = 1;
  r.world.kElastic = 500;
  r.world.dElastic = 0.25;
  r.world.kCollision = 1000;
  r.world.dCollision = 0.25;
  r.world.mass = kCourseMass;
  return r;
}

Recipe coursePreset(const std::string& name) {
  const double seventh = 1.0 / 7;
  if (name == "jello") {
    Recipe r = courseBase(0.0005, 200, 400);
    r.world.hasPlane = true;
    r.world.plane = {-1, 1, 1, 2};
    r.state.skewCorner = {seventh, seventh, seventh};
    r.state.velocity = Vec3{10, -10, 20};
    return r;
  }
  if (name == "rotate") {
    Recipe r = courseBase(0.001, 500, 1000);
    r.world.hasPlane = true;
    r.world.plane = {1, -1, -1, 4};
    r.field.source = FieldRecipe::Source::Swirl;
    r.field.strength = 5.0 / 512;
    return r;
  }
  if (name == "moveLeft") {
    Recipe r = courseBase(0.0005, 500, 1000);
    r.state.velocity = Vec3{-50, 0, 0};
    return r;
  }
  if (name == "skewedCorner") {
    Recipe r = courseBase(0.00001, 500, 1000);
    r.state.skewCorner = {seventh, seventh, seventh};
    return r;
  }
  if (name == "gravity") {
    Recipe r = courseBase(0.0001, 500, 1000);
    r.world.hasPlane = true;
    r.world.plane = {-1, 1, 2, 6};
    r.field.uniform = {0, 0, -0.06};
    r.state.velocity = Vec3{10, -10, 0};
    return r;
  }
  throw RecipeError("unknown preset '" + name +
                    "', expected jello, rotate, moveLeft, skewedCorner or gravity");
}

namespace {

// "fx; fy; fz" cut at its semicolons, each part trimmed; refused unless there are three.
std::vector<std::string> splitExpressions(const std::string& expression) {
  std::vector<std::string> parts;
  std::string rest = expression;
  for (std::size_t semicolon; (semicolon = rest.find(';')) != std::string::npos;) {
    parts.push_back(trim(rest.substr(0, semicolon)));
    rest = rest.substr(semicolon + 1);
  }
  parts.push_back(trim(rest));
  if (parts.size() != 3) {
    throw RecipeError("--field-expr needs three expressions \"fx; fy; fz\", got " +
                      std::to_string(parts.size()));
  }
  return parts;
}

// The nodes of an R^3 field, each force the value of the three expressions at the node.
void fillFromExpressions(ForceField& field, int r, const std::string& expression) {
  const std::vector<std::string> parts = splitExpressions(expression);
  double x = 0, y = 0, z = 0;  // the variables the parsers read, set node by node below
  mu::Parser parsers[3];
  const char* names[3] = {"fx", "fy", "fz"};
  for (int c = 0; c < 3; ++c) {
    try {
      parsers[c].DefineVar("x", &x);
      parsers[c].DefineVar("y", &y);
      parsers[c].DefineVar("z", &z);
      parsers[c].SetExpr(parts[c]);
      parsers[c].Eval();  // parse now, so that errors name the expression, not a node
    } catch (const mu::Parser::exception_type& e) {
      throw RecipeError(std::string("--field-expr: ") + names[c] + ": " + e.GetMsg());
    }
  }
  fillNodes(field, r, [&](Vec3 p) {
    x = p.x;
    y = p.y;
    z = p.z;
    double value[3];
    for (int c = 0; c < 3; ++c) {
      value[c] = parsers[c].Eval();
      if (!std::isfinite(value[c])) {
        char where[96];
        std::snprintf(where, sizeof where, "(%g, %g, %g)", p.x, p.y, p.z);
        throw RecipeError(std::string("--field-expr: ") + names[c] + " is not finite at " + where);
      }
    }
    return Vec3{value[0], value[1], value[2]};
  });
}

}  // namespace

ForceField buildField(const FieldRecipe& recipe) {
  using Source = FieldRecipe::Source;
  ForceField field;
  const int r = recipe.resolution;
  if (recipe.source == Source::Given) return recipe.given;
  if (recipe.source == Source::None || r == 0) return field;
  if (r < 0 || r > kMaxResolution) {
    throw RecipeError("field resolution " + std::to_string(r) + " is out of range (0 to " +
                      std::to_string(kMaxResolution) + ")");
  }
  if (r == 1 && recipe.source != Source::Uniform) {
    throw RecipeError(
        "a field that varies in space needs --field-resolution 2 or more (1 is one uniform force)");
  }
  switch (recipe.source) {
    case Source::Uniform:
      fillNodes(field, r, [&](Vec3) { return recipe.uniform; });
      break;
    case Source::Swirl:
      fillNodes(field, r, [&](Vec3 p) { return recipe.strength * Vec3{-p.y, p.x, 0}; });
      break;
    case Source::Radial:
      fillNodes(field, r, [&](Vec3 p) { return recipe.strength * p; });
      break;
    case Source::Expression:
      fillFromExpressions(field, r, recipe.expression);
      break;
    case Source::None:   // returned above
    case Source::Given:  // returned above
      break;
  }
  return field;
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
