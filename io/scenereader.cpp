// io/scenereader.cpp: the scene file reader (scenereader.h; the keys are documented in
// docs/scenes.md).

#include "io/scenereader.h"

#include <toml++/toml.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <initializer_list>
#include <iterator>
#include <memory>

#include "core/assert.h"
#include "core/readfile.h"
#include "io/fieldrecipe.h"
#include "io/jellyreader.h"
#include "io/scenetable.h"
#include "io/statefile.h"
#include "io/voxels.h"
#include "model/scenespec.h"

namespace jello {

WorldFile defaultSceneWorld() {
  WorldFile file;
  file.run = {Integrator::RK4, 0.0005, 10};
  World& w = file.world;
  w.kElastic = 500;
  w.dElastic = 0.25;
  w.kCollision = 1000;
  w.dCollision = 0.25;
  w.mass = 1.0 / kNumPoints;
  for (int i = 0; i < kLatticeSize; ++i)
    for (int j = 0; j < kLatticeSize; ++j)
      for (int k = 0; k < kLatticeSize; ++k)
        store(file.state.p(), pointIndex(i, j, k),
              kRestSpacing * Vec3{double(i), double(j), double(k)} - Vec3{0.5, 0.5, 0.5});
  return file;
}

namespace {

// The course world a scene starts from, its path relative to the scene's folder.
WorldFile baseWorld(const Reader& r, const toml::table& root) {
  const toml::node* node = root.get("world");
  if (!node) return defaultSceneWorld();
  const std::optional<std::string> path = node->value<std::string>();
  if (!path || path->empty()) r.fail(*node, "world", "expected the path of a course world (.w)");
  const std::string full = r.pathFromScene(*path);
  try {
    return readWorldFile(full);
  } catch (const InputError& e) {
    r.fail(*node, "world", e.what());
  }
}

void readRun(const Reader& r, const toml::table& root, RunSettings* w) {
  if (const toml::node* node = root.get("integrator")) {
    const std::optional<std::string> text = node->value<std::string>();
    if (!text || !parseIntegratorName(*text, &w->integrator))
      r.fail(*node, "integrator", "expected one of " + integratorNameList());
  }
  if (auto dt = r.number(root, "", "dt", 0, true)) w->dt = *dt;
  if (const toml::node* node = root.get("n")) {
    const std::optional<std::int64_t> n =
        node->is_integer() ? node->value<std::int64_t>() : std::nullopt;
    if (!n || *n < 1 || *n > kMostStepsPerFrame)
      r.fail(*node, "n", "expected a whole number from 1 to " + std::to_string(kMostStepsPerFrame));
    w->n = static_cast<int>(*n);
  }
}

// [field]: the force field (N on each point), replacing the course world's: "fx; fy; fz"
// expressions or one uniform force, at a resolution; or none (present = false).
void readField(const Reader& r, const toml::table& root, ForceField* field) {
  const toml::table* t = r.table(root, "", "field");
  if (!t) return;
  r.onlyKeys(*t, "field.", {"present", "expression", "uniform", "resolution"});
  const int given =
      (t->get("present") ? 1 : 0) + (t->get("expression") ? 1 : 0) + (t->get("uniform") ? 1 : 0);
  if (given != 1) r.fail(*t, "field", "give one of expression, uniform or present = false");
  if (const toml::node* present = t->get("present")) {
    if (present->value<bool>() != std::optional<bool>(false))
      r.fail(*present, "field.present",
             "expected false (no field; a field gives expression or uniform)");
    if (const toml::node* resolution = t->get("resolution"))
      r.fail(*resolution, "field.resolution", "a field that is not present has no resolution");
    *field = ForceField{};
    return;
  }
  FieldRecipe recipe;
  recipe.label = "";
  if (const toml::node* node = t->get("resolution")) {
    const std::optional<std::int64_t> n =
        node->is_integer() ? node->value<std::int64_t>() : std::nullopt;
    if (!n || *n < 2 || *n > kMostSceneFieldResolution)
      r.fail(*node, "field.resolution",
             "expected a whole number from 2 to " + std::to_string(kMostSceneFieldResolution));
    recipe.resolution = static_cast<int>(*n);
  }
  const char* key = t->get("expression") ? "expression" : "uniform";
  const toml::node& node = *t->get(key);
  if (key[0] == 'u') {
    recipe.source = FieldRecipe::Source::Uniform;
    recipe.uniform = *r.vector(*t, "field.", "uniform");
  } else {
    const std::optional<std::string> text = node.value<std::string>();
    if (!text) r.fail(node, "field.expression", "expected a string \"fx; fy; fz\"");
    if (text->size() > kMostFieldExpressionBytes)
      r.fail(node, "field.expression",
             "longer than " + std::to_string(kMostFieldExpressionBytes) + " characters");
    recipe.source = FieldRecipe::Source::Expression;
    recipe.expression = *text;
  }
  try {
    *field = buildField(recipe);
  } catch (const InputError& e) {
    r.fail(node, std::string("field.") + key, e.what());
  }
}

ContactSpring readSpring(const Reader& r, const toml::table& t, const std::string& path,
                         ContactSpring spring) {
  if (auto k = r.number(t, path, "stiffness", 0)) spring.k = *k;
  if (auto d = r.number(t, path, "damping", 0)) spring.d = *d;
  return spring;
}

Friction readFriction(const Reader& r, const toml::table& t, const std::string& path) {
  Friction f;
  f.muStatic = r.number(t, path, "friction_static", 0).value_or(0);
  f.muDynamic = r.number(t, path, "friction_dynamic", 0).value_or(f.muStatic);
  f.speed = r.number(t, path, "friction_speed", 0, true).value_or(kDefaultFrictionSpeed);
  if (const auto fault = frictionFault(f)) {
    // The key that breaks the rule is one given: the others' defaults keep it.
    const toml::node* given = t.get(fault->key);
    JELLO_ASSERT(given != nullptr);
    r.fail(*given, path + fault->key, fault->why);
  }
  return f;
}

// lower < upper on every axis.
void checkBox(const Reader& r, const toml::table& t, const std::string& path, Vec3 lower,
              Vec3 upper) {
  if (lower.x < upper.x && lower.y < upper.y && lower.z < upper.z) return;
  // The bounds may give one corner alone, the other being the course's.
  const char* key = t.get("upper") ? "upper" : "lower";
  r.fail(*t.get(key), path + key,
         key[0] == 'u' ? "must be above lower on every axis" : "must be below upper on every axis");
}

Obstacle readObstacle(const Reader& r, const toml::table& t, const std::string& path,
                      ObstacleShape shape, ContactSpring spring) {
  static const char* const kCommon[] = {"stiffness", "damping", "friction_static",
                                        "friction_dynamic", "friction_speed"};
  Obstacle o;
  o.shape = shape;
  std::vector<std::string> known(std::begin(kCommon), std::end(kCommon));
  if (shape == ObstacleShape::Sphere) known.insert(known.end(), {"centre", "radius"});
  if (shape == ObstacleShape::Box) known.insert(known.end(), {"lower", "upper"});
  if (shape == ObstacleShape::HalfSpace) known.insert(known.end(), {"point", "normal"});
  r.onlyKeys(t, path, known);
  auto need = [&](const char* key) {
    if (!t.get(key)) r.fail(t, path + key, "missing");
  };
  if (shape == ObstacleShape::Sphere) {
    need("centre");
    o.centre = *r.vector(t, path, "centre");
    need("radius");
    o.radius = *r.number(t, path, "radius", 0, true);
  } else if (shape == ObstacleShape::Box) {
    need("lower");
    need("upper");
    o.lower = *r.vector(t, path, "lower");
    o.upper = *r.vector(t, path, "upper");
    checkBox(r, t, path, o.lower, o.upper);
  } else {
    need("point");
    o.point = *r.vector(t, path, "point");
    need("normal");
    const Vec3 normal = *r.vector(t, path, "normal");
    const double size = length(normal);
    if (!(size > 0) || !std::isfinite(size))
      r.fail(*t.get("normal"), path + "normal", "must not be zero");
    o.normal = (1 / size) * normal;
    o.givenNormal = normal;
  }
  o.spring = readSpring(r, t, path, spring);
  o.friction = readFriction(r, t, path);
  return o;
}

void readBounds(const Reader& r, const toml::table& root, ContactSpring spring, SceneSpec* spec) {
  const toml::table* t = r.table(root, "", "bounds");
  if (!t) return;
  r.onlyKeys(*t, "bounds.",
             {"present", "lower", "upper", "stiffness", "damping", "friction_static",
              "friction_dynamic", "friction_speed"});
  if (const toml::node* present = t->get("present")) {
    if (!present->is_boolean()) r.fail(*present, "bounds.present", "expected true or false");
    spec->boundsPresent = present->value<bool>().value_or(true);
  }
  const bool sized = t->get("lower") || t->get("upper");
  const bool changed = t->size() > (t->get("present") ? 1u : 0u);  // any key but present
  if (!spec->boundsPresent && changed)
    for (auto&& [key, node] : *t)
      if (key.str() != "present")
        r.fail(node, "bounds." + std::string(key.str()),
               "a bounding box that is not present takes no other key");
  if (!spec->boundsPresent || !changed) return;
  Obstacle o;
  o.shape = ObstacleShape::Container;
  o.lower =
      r.vector(*t, "bounds.", "lower").value_or(Vec3{-kBoxHalfSize, -kBoxHalfSize, -kBoxHalfSize});
  o.upper =
      r.vector(*t, "bounds.", "upper").value_or(Vec3{kBoxHalfSize, kBoxHalfSize, kBoxHalfSize});
  if (sized) checkBox(r, *t, "bounds.", o.lower, o.upper);
  o.spring = readSpring(r, *t, "bounds.", spring);
  o.friction = readFriction(r, *t, "bounds.");
  spec->bounds = o;
}

// An inclusive range [first, last] of grid indices below `size`, all of them by default.
std::pair<int, int> indexRange(const Reader& r, const toml::table& t, const std::string& path,
                               const char* key, int size) {
  const toml::node* node = t.get(key);
  if (!node) return {0, size - 1};
  const toml::array* array = node->as_array();
  std::optional<std::int64_t> a, b;
  if (array && array->size() == 2)
    a = array->get(0)->value<std::int64_t>(), b = array->get(1)->value<std::int64_t>();
  if (!a || !b || !(*array->get(0)).is_integer() || !(*array->get(1)).is_integer() || *a < 0 ||
      *b >= size || *a > *b)
    r.fail(*node, path + key,
           "expected [first, last], whole numbers with 0 <= first <= last <= " +
               std::to_string(size - 1));
  return {static_cast<int>(*a), static_cast<int>(*b)};
}

// The jelly a pin names (`jelly`, from 1; the first by default, or every one for a region
// without it): its points are [first, end) of the body, its grid `grid`.
struct PinTarget {
  const Body* grid;
  int first, end;
};
PinTarget pinTarget(const Reader& r, const toml::table& t, const std::string& path,
                    const Body& body, bool region) {
  const toml::node* node = t.get("jelly");
  const int jellies = body.joined() ? static_cast<int>(body.parts.size()) : 1;
  if (!node && (region || !body.joined())) return {&body, 0, body.count()};
  const std::optional<std::int64_t> value = node ? node->value<std::int64_t>() : 1;
  if (node && (!node->is_integer() || !value || *value < 1 || *value > jellies))
    r.fail(*node, path + "jelly", "expected a whole number from 1 to " + std::to_string(jellies));
  if (!body.joined()) return {&body, 0, body.count()};
  const int part = static_cast<int>(*value) - 1;
  return {body.parts[part].get(), body.partFirst[part], body.partFirst[part + 1]};
}

void readPins(const Reader& r, const toml::table& root, const Body& body, const State& state,
              SceneSpec* spec) {
  const int n = body.count();
  std::vector<char> pinned(n, 0);
  r.tables(root, "pin", [&](const toml::table& t, const std::string& path) {
    r.onlyKeys(t, path, {"i", "j", "k", "lower", "upper", "jelly"});
    const bool region = t.get("lower") || t.get("upper");
    if (region && (t.get("i") || t.get("j") || t.get("k")))
      r.fail(t, path + "lower",
             "give lattice ranges (i, j, k) or a region (lower, upper), not both");
    int count = 0;
    const PinTarget target = pinTarget(r, t, path, body, region);
    if (region) {
      const Vec3 lower = r.vector(t, path, "lower").value_or(Vec3{-INFINITY, -INFINITY, -INFINITY});
      const Vec3 upper = r.vector(t, path, "upper").value_or(Vec3{INFINITY, INFINITY, INFINITY});
      for (int q = target.first; q < target.end; ++q) {
        if (inBox(load(state.p(), q, n), lower, upper)) pinned[q] = 1, ++count;
      }
    } else {
      const Body& grid = *target.grid;
      if (grid.gridless())
        r.fail(t, path.substr(0, path.size() - 1),
               "a TetGen mesh has no grid to give i, j, k of: pin a region (lower, upper)");
      const auto is = indexRange(r, t, path, "i", grid.nx),
                 js = indexRange(r, t, path, "j", grid.ny),
                 ks = indexRange(r, t, path, "k", grid.nz);
      for (int i = is.first; i <= is.second; ++i)
        for (int j = js.first; j <= js.second; ++j)
          for (int k = ks.first; k <= ks.second; ++k)
            if (const int q = grid.pointAtIndex(i, j, k); q >= 0)
              pinned[target.first + q] = 1, ++count;
    }
    if (count == 0) r.fail(t, path.substr(0, path.size() - 1), "pins no point");
  });
  for (int q = 0; q < n; ++q)
    if (pinned[q]) spec->pinned.push_back(q);
}

void readObstacles(const Reader& r, const toml::table& root, ContactSpring spring,
                   SceneSpec* spec) {
  const std::pair<const char*, ObstacleShape> kinds[] = {{"sphere", ObstacleShape::Sphere},
                                                         {"box", ObstacleShape::Box},
                                                         {"plane", ObstacleShape::HalfSpace}};
  for (const auto& kind : kinds) {
    const ObstacleShape shape = kind.second;  // (a structured binding cannot be captured in C++17)
    r.tables(root, kind.first, [&](const toml::table& t, const std::string& path) {
      if (spec->obstacles.size() >= static_cast<std::size_t>(kMostObstacles))
        r.fail(t, path.substr(0, path.size() - 1),
               "more than " + std::to_string(kMostObstacles) + " obstacles");
      spec->obstacles.push_back(readObstacle(r, t, path, shape, spring));
    });
  }
}

// `state = "FILE"`: the state file that replaces the placement, when the scene gives one.
void readState(const Reader& r, const toml::table& root, const Body& body, State* out) {
  const toml::node* state = root.get("state");
  if (!state) return;
  const std::optional<std::string> path = state->value<std::string>();
  if (!path || path->empty()) r.fail(*state, "state", "expected the path of a state file (.csv)");
  try {
    *out = readStateFile(r.pathFromScene(*path), body);
  } catch (const InputError& e) {
    r.fail(*state, "state", e.what());
  }
}

// The character at (line, column) of `text`, both from 1, as oneLine shows it; "the end" past it.
std::string characterAt(std::string_view text, std::size_t line, std::size_t column) {
  std::size_t at = 0;
  for (std::size_t l = 1; l < line && at < text.size(); ++l) {
    const std::size_t end = text.find('\n', at);
    at = end == std::string_view::npos ? text.size() : end + 1;
  }
  at += column > 0 ? column - 1 : 0;
  if (at >= text.size()) return "the end of the file";
  return "'" + oneLine(text.substr(at, 1)) + "'";
}

// A file that is not TOML: said in this program's words where the TOML reader stopped (its own
// text, from a library, is not shown), and a key or table given twice by its name (the one thing
// taken from that text, "cannot redefine existing ... 'NAME'", made printable).
toml::table parseToml(std::string_view text, const std::string& name) {
  try {
    return toml::parse(text, name);
  } catch (const toml::parse_error& e) {
    const auto& where = e.source().begin;
    const std::string_view said = e.description();
    const std::size_t open = said.find('\''), close = said.rfind('\'');
    if (said.find("cannot redefine existing") != std::string_view::npos &&
        open != std::string_view::npos && close > open) {
      const std::string key = oneLine(said.substr(open + 1, close - open - 1));
      const bool table = said.find("table header") != std::string_view::npos;
      throw InputError(name + ":" + std::to_string(where.line) + ": " +
                       (table ? "[" + key + "]" : key) + " given twice" +
                       (said.find("array-of-tables") != std::string_view::npos
                            ? ": [" + key + "] and [[" + key + "]] do not mix (one [" + key +
                                  "], or each as [[" + key + "]])"
                        : table ? " (a table once; several as [[" + key + "]])"
                                : " (each key once in its table)"));
    }
    throw InputError(
        name + ":" + std::to_string(where.line) + ": not TOML: it cannot be read on from column " +
        std::to_string(where.column) + ", at " + characterAt(text, where.line, where.column) +
        " (each line is key = value, [table] or [[list]]: docs/scenes.md)");
  }
}

}  // namespace

WorldFile parseScene(std::string_view text, const std::string& name, const std::string& folder) {
  const toml::table root = parseToml(text, name);
  const Reader r(name, folder);
  r.onlyKeys(root, "",
             {"world", "integrator", "dt", "n", "gravity", "field", "jelly", "contact", "bounds",
              "sphere", "box", "plane", "pin", "state"});
  WorldFile file = baseWorld(r, root);
  World& w = file.world;
  auto spec = std::make_shared<SceneSpec>();
  readRun(r, root, &file.run);
  readJelly(r, root, &file, spec.get());
  readField(r, root, &w.field);
  const toml::table* contact = r.table(root, "", "contact");
  if (contact) {
    r.onlyKeys(*contact, "contact.",
               {"stiffness", "damping", "distance", "friction_static", "friction_dynamic",
                "friction_speed"});
    const ContactSpring spring = readSpring(r, *contact, "contact.", {w.kCollision, w.dCollision});
    w.kCollision = spring.k;
    w.dCollision = spring.d;
  }
  bool selfContact = spec->selfContact;
  for (const JellySpec& jelly : spec->jellies) selfContact = selfContact || jelly.selfContact;
  if (!spec->jellies.empty() || selfContact) {
    BodyContactSpec bodies;
    bodies.spring = {w.kCollision, w.dCollision};
    if (contact) {
      bodies.distance = r.number(*contact, "contact.", "distance", 0, true).value_or(0);
      bodies.friction = readFriction(r, *contact, "contact.");
    }
    spec->bodyContact = bodies;
  } else if (contact) {
    for (const char* key : {"distance", "friction_static", "friction_dynamic", "friction_speed"})
      if (contact->get(key))
        r.fail(*contact->get(key), std::string("contact.") + key,
               "belongs to contact between bodies: give several [[jelly]] or self_contact = true");
  }
  spec->gravity = r.vector(root, "", "gravity").value_or(Vec3{});
  const ContactSpring spring{w.kCollision, w.dCollision};
  readBounds(r, root, spring, spec.get());
  readObstacles(r, root, spring, spec.get());
  const Body& body = spec->body ? *spec->body : courseBody();
  // The jellies' placement is checked where it is the start: a state file replaces it (and may
  // hold jellies in contact, as a saved run does).
  if (!root.get("state")) checkJellies(r, root, file, *spec);
  readState(r, root, body, &file.state);
  readPins(r, root, body, file.state, spec.get());
  for (int q : spec->pinned) store(file.state.v(), q, body.count(), Vec3{});
  w.scene = std::move(spec);  // before the check: it names points by the scene's body
  if (std::optional<WorldProblem> problem = findWorldProblem(w, file.run, file.state))
    throw InputError(name + ": " + problem->what);
  file.inputs = r.inputs();
  return file;
}

WorldFile readSceneFile(const std::string& path) {
  std::string text, why;
  if (!readRegularFile(path, kMostSceneBytes, "a scene file",
                       std::to_string(kMostSceneBytes) + " bytes", &text, &why))
    throw InputError(why);
  const std::size_t slash = path.rfind('/');
  return parseScene(text, path, slash == std::string::npos ? "" : path.substr(0, slash));
}

bool isSceneFile(const std::string& path) {
  constexpr std::string_view kSuffix = ".toml";
  return path.size() > kSuffix.size() &&
         path.compare(path.size() - kSuffix.size(), kSuffix.size(), kSuffix) == 0;
}

}  // namespace jello
