// io/scenewriter.cpp: a setup written back as a scene (scenewriter.h; docs/scenes.md, "Saved
// scenes").

#include "io/scenewriter.h"

#include <filesystem>
#include <string_view>
#include <vector>

#include "core/assert.h"
#include "core/output.h"
#include "io/input.h"
#include "io/scenereader.h"
#include "io/statefile.h"
#include "model/model.h"
#include "model/scenespec.h"

namespace jello {

namespace {

std::string number(double value) {
  std::string out;
  appendNumber(out, value);
  return out;
}

std::string vector(Vec3 v) {
  return "[" + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + "]";
}

// A TOML basic string: quotes, backslashes and control characters escaped.
std::string quoted(const std::string& text) {
  if (!isUtf8(text))
    throw OutputError(text + ": a path that is not UTF-8 cannot be written in a scene file");
  std::string out = "\"";
  for (char c : text) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (u < 0x20 || u == 0x7f) {
      char escape[8];
      std::snprintf(escape, sizeof escape, "\\u%04x", u);
      out += escape;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

// `path` as the scene in `folder` names it: from the scene's folder where both are on one tree.
std::string pathFromFolder(const std::string& path, const std::string& folder) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::path absolute = fs::absolute(path, error);
  const fs::path base = fs::absolute(folder.empty() ? "." : folder, error);
  if (error) return path;
  const fs::path relative = absolute.lexically_normal().lexically_relative(base.lexically_normal());
  return relative.empty() ? absolute.lexically_normal().string() : relative.string();
}

void writeSprings(std::string& out, const SpringConstants& springs) {
  const char* names[] = {"stiffness", "damping"};
  for (int which = 0; which < 2; ++which) {
    const auto& values = which == 0 ? springs.k : springs.d;
    out += std::string(names[which]) + " = { ";
    for (int kind = 0; kind < kSpringKinds; ++kind)
      out += std::string(kind ? ", " : "") + springKindName(SpringKind(kind)) + " = " +
             number(values[kind]);
    out += " }\n";
  }
}

void writeMaterial(std::string& out, const Material& m) {
  if (!m.elements()) return;
  out += "material = " + quoted(materialInfo(m.kind).name) + "\n";
  out += "youngs_modulus = " + number(m.youngsModulus) + "\n";
  out += "poisson_ratio = " + number(m.poissonRatio) + "\n";
  out += "density = " + number(m.density) + "\n";
  out += "mass_damping = " + number(m.massDamping) + "\n";
  out += "stiffness_damping = " + number(m.stiffnessDamping) + "\n";
}

void writeShape(std::string& out, const JellyRecipe& recipe, const std::string& folder) {
  if (recipe.shape.empty()) return;
  out += "shape = " + quoted(recipe.shape) + "\n";
  if (recipe.shape == "lattice")
    out += "size = [" + std::to_string(recipe.size[0]) + ", " + std::to_string(recipe.size[1]) +
           ", " + std::to_string(recipe.size[2]) + "]\n";
  if (recipe.shape == "sphere") out += "radius = " + number(recipe.radius) + "\n";
  if (recipe.shape == "mesh") out += "mesh = " + quoted(pathFromFolder(recipe.mesh, folder)) + "\n";
  if (recipe.spacing) out += "spacing = " + number(*recipe.spacing) + "\n";
}

// One jelly's table: its shape and material, and its mass and springs where given (several
// jellies: each its own; one: the .w's unless its springs differ by kind). No offset or velocity:
// the state file is the placement.
void writeJelly(std::string& out, const char* header, const JellyRecipe& recipe,
                const Material& material, const SpringConstants* springs, const double* mass,
                bool selfContact, const std::string& folder) {
  out += std::string("\n") + header + "\n";
  writeShape(out, recipe, folder);
  writeMaterial(out, material);
  if (!material.elements() && mass) out += "mass = " + number(*mass) + "\n";
  if (!material.elements() && springs) writeSprings(out, *springs);
  if (selfContact) out += "self_contact = true\n";
}

void writeContact(std::string& out, const ContactSpring& spring, const Friction& friction) {
  JELLO_ASSERT(!frictionFault(friction));  // what the reader reads back (the panel keeps it)
  out += "stiffness = " + number(spring.k) + "\ndamping = " + number(spring.d) + "\n";
  out += "friction_static = " + number(friction.muStatic) + "\n";
  out += "friction_dynamic = " + number(friction.muDynamic) + "\n";
  out += "friction_speed = " + number(friction.speed) + "\n";
}

void writeObstacle(std::string& out, const Obstacle& o) {
  switch (o.shape) {
    case ObstacleShape::Sphere:
      out += "\n[[sphere]]\ncentre = " + vector(o.centre) + "\nradius = " + number(o.radius) + "\n";
      break;
    case ObstacleShape::Box:
      out += "\n[[box]]\nlower = " + vector(o.lower) + "\nupper = " + vector(o.upper) + "\n";
      break;
    case ObstacleShape::HalfSpace:
      JELLO_ASSERT(hasNormal({o.givenNormal.x, o.givenNormal.y, o.givenNormal.z, 0}));
      out +=
          "\n[[plane]]\npoint = " + vector(o.point) + "\nnormal = " + vector(o.givenNormal) + "\n";
      break;
    case ObstacleShape::Container:
      out += "\n[bounds]\nlower = " + vector(o.lower) + "\nupper = " + vector(o.upper) + "\n";
      break;
  }
  writeContact(out, o.spring, o.friction);
}

// The pins: on a grid, runs of k at one (jelly, i, j), and runs of j with the same k run merged;
// in a mesh, each point's position (it never moves) as a region of one point.
void writePins(std::string& out, const Body& body, const State& state,
               const std::vector<int>& pins) {
  const int n = body.count();
  for (std::size_t at = 0; at < pins.size();) {
    const int q = pins[at];
    const int part = body.partOf(q);
    const std::string jelly = body.joined() ? "jelly = " + std::to_string(part + 1) + "\n" : "";
    const Body& grid = body.joined() ? *body.parts[part] : body;
    if (grid.gridless()) {
      const Vec3 p = load(state.p(), q, n);
      out += "\n[[pin]]\n" + jelly + "lower = " + vector(p) + "\nupper = " + vector(p) + "\n";
      ++at;
      continue;
    }
    // The run of k from q's index, then the j that carry the same run of k.
    const auto [i, j, k] = body.index(q);
    auto pinnedAt = [&](std::size_t from, int ii, int jj, int kk) {
      return from < pins.size() && body.partOf(pins[from]) == part &&
             body.index(pins[from]) == std::array<int, 3>{ii, jj, kk};
    };
    int kLast = k;
    std::size_t next = at + 1;
    while (pinnedAt(next, i, j, kLast + 1)) ++kLast, ++next;
    int jLast = j;
    for (;;) {
      std::size_t probe = next;
      bool whole = true;
      for (int kk = k; kk <= kLast && whole; ++kk, ++probe)
        whole = pinnedAt(probe, i, jLast + 1, kk);
      if (!whole || pinnedAt(probe, i, jLast + 1, kLast + 1)) break;
      // Nothing of (i, jLast + 1) may lie below k: the pins are in point order.
      ++jLast;
      next = probe;
    }
    out += "\n[[pin]]\n" + jelly + "i = [" + std::to_string(i) + ", " + std::to_string(i) +
           "]\nj = [" + std::to_string(j) + ", " + std::to_string(jLast) + "]\nk = [" +
           std::to_string(k) + ", " + std::to_string(kLast) + "]\n";
    at = next;
  }
}

std::string baseName(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

}  // namespace

SavedSceneFiles savedSceneFiles(const std::string& scenePath, bool hasScene) {
  JELLO_ASSERT(isSceneFile(scenePath));
  const std::string stem = scenePath.substr(0, scenePath.size() - 5);  // without ".toml"
  return {scenePath, stem + ".w", hasScene ? stem + ".csv" : ""};
}

std::string formatScene(const World& world, const RunSettings& run, const SavedSceneFiles& files) {
  const std::string folder = folderOf(files.scene);
  std::string out = "# Saved by jello's window: this scene with " + baseName(files.world) +
                    (files.state.empty() ? "" : " and " + baseName(files.state)) +
                    " reads back as the same world and state, bit for bit.\nworld = " +
                    quoted(baseName(files.world)) + "\n";
  out += "integrator = " + quoted(integratorName(run.integrator)) + "\ndt = " + number(run.dt) +
         "\nn = " + std::to_string(run.n) + "\n";
  const SceneSpec* spec = world.scene.get();
  if (!spec) return out;
  out += "gravity = " + vector(spec->gravity) + "\nstate = " + quoted(baseName(files.state)) + "\n";
  if (spec->jellies.empty()) {
    const SpringConstants* springs = spec->springs ? &*spec->springs : nullptr;
    // The .w holds the mass and the springs' kElastic and dElastic for one jelly.
    writeJelly(out, "[jelly]", spec->recipe, spec->material, springs, nullptr, spec->selfContact,
               folder);
  }
  for (const JellySpec& jelly : spec->jellies)
    writeJelly(out, "[[jelly]]", jelly.recipe, jelly.material, &jelly.springs, &jelly.mass,
               jelly.selfContact, folder);
  out += "\n[contact]\n";
  if (spec->bodyContact) {
    writeContact(out, spec->bodyContact->spring, spec->bodyContact->friction);
    if (spec->bodyContact->distance > 0)
      out += "distance = " + number(spec->bodyContact->distance) + "\n";
  } else {
    out += "stiffness = " + number(world.kCollision) + "\ndamping = " + number(world.dCollision) +
           "\n";
  }
  if (!spec->boundsPresent) out += "\n[bounds]\npresent = false\n";
  if (spec->bounds) writeObstacle(out, *spec->bounds);
  for (const Obstacle& o : spec->obstacles) writeObstacle(out, o);
  return out;
}

void writeScene(const std::string& scenePath, const World& world, const RunSettings& run,
                const State& state, bool overwrite) {
  if (!isSceneFile(scenePath)) throw OutputError(scenePath + ": a scene file's name ends in .toml");
  const SavedSceneFiles files = savedSceneFiles(scenePath, world.scene != nullptr);
  const Existing existing = overwrite ? Existing::Replace : Existing::Refuse;
  std::vector<std::string> paths = {files.world, files.scene};
  if (!files.state.empty()) paths.push_back(files.state);
  for (const std::string& path : paths)
    if (const std::string why = whyNotWritable(path, existing); !why.empty())
      throw OutputError(path + ": " + why);
  std::string sceneText = formatScene(world, run, files);
  if (world.scene) writePins(sceneText, bodyOf(world), state, world.scene->pinned);
  if (sceneText.size() > kMostSceneBytes)
    throw OutputError(scenePath +
                      ": its pins would make a scene file larger than the reader takes (" +
                      std::to_string(kMostSceneBytes) + " bytes)");
  // Those written anew (not replacing a file) are removed when a later one fails.
  std::vector<std::string> written;
  auto created = [&](const std::string& path) {
    return !checkWritable(path, Existing::Refuse).alreadyExists;
  };
  try {
    // A scene's .w holds the course world alone; its cube (unused: the state file replaces it) is
    // the rest lattice a scene without a world starts from.
    World course = world;
    course.scene = nullptr;
    const bool newWorld = created(files.world);
    writeWorldFile(files.world, course, run, world.scene ? defaultSceneWorld().state : state,
                   overwrite);
    if (newWorld) written.push_back(files.world);
    if (!files.state.empty()) {
      const bool newState = created(files.state);
      writeFileWhole(files.state, formatState(bodyOf(world), state), existing);
      if (newState) written.push_back(files.state);
    }
    writeFileWhole(files.scene, sceneText, existing);
  } catch (...) {
    for (const std::string& path : written) std::remove(path.c_str());
    throw;
  }
}

}  // namespace jello
