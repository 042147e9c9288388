// io/jellyreader.cpp: a scene's jellies (jellyreader.h; the keys are in docs/scenes.md).

#include "io/jellyreader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "io/tetmesh.h"
#include "io/voxels.h"
#include "model/bodycontact.h"
#include "model/elements.h"
#include "model/winding.h"

namespace jello {

namespace {

constexpr std::initializer_list<const char*> kJellyKeys = {
    "mass",     "total_mass",     "stiffness",     "damping", "offset",       "velocity",
    "shape",    "size",           "spacing",       "radius",  "mesh",         "self_contact",
    "material", "youngs_modulus", "poisson_ratio", "density", "mass_damping", "stiffness_damping"};

// A whole number in [lowest, highest].
int wholeNumber(const Reader& r, const toml::node& node, const std::string& key, int lowest,
                int highest) {
  const std::optional<std::int64_t> value = node.value<std::int64_t>();
  if (!node.is_integer() || !value || *value < lowest || *value > highest)
    r.fail(node, key,
           "expected a whole number from " + std::to_string(lowest) + " to " +
               std::to_string(highest));
  return static_cast<int>(*value);
}

// A lattice's size [nx, ny, nz]: each from 2, except that one may be 1 (a sheet: cloth).
Body readLattice(const Reader& r, const toml::table& t, const std::string& path, double spacing) {
  const toml::node* size = t.get("size");
  if (!size) r.fail(*t.get("shape"), path + "size", "a lattice needs its size = [nx, ny, nz]");
  const toml::array* array = size->as_array();
  if (!array || array->size() != 3) r.fail(*size, path + "size", "expected [nx, ny, nz]");
  int n[3];
  for (int i = 0; i < 3; ++i)
    n[i] = wholeNumber(r, *array->get(i), path + "size", 1, kMostScenePoints);
  if ((n[0] == 1) + (n[1] == 1) + (n[2] == 1) > 1)
    r.fail(*size, path + "size", "at most one side may be 1 (a sheet); the others from 2");
  const long long points = static_cast<long long>(n[0]) * n[1] * n[2];
  if (points > kMostScenePoints)
    r.fail(*size, path + "size",
           std::to_string(n[0]) + "x" + std::to_string(n[1]) + "x" + std::to_string(n[2]) + " is " +
               std::to_string(points) + " points; a scene holds at most " +
               std::to_string(kMostScenePoints));
  return latticeBody(n[0], n[1], n[2], spacing);
}

// The body of a jelly's shape: a lattice (the course's cube when it is 8x8x8 at 1/7 m), or the
// voxels of a ball or of a mesh (io/voxels.h).
Body readShape(const Reader& r, const toml::table& t, const std::string& path,
               const std::string& shape, double spacing) {
  const toml::node& at = *t.get("shape");
  if (shape == "lattice") return readLattice(r, t, path, spacing);
  VoxelGrid grid;
  std::string why, what;
  if (shape == "sphere") {
    const std::optional<double> radius = r.number(t, path, "radius", 0, true);
    if (!radius) r.fail(at, path + "radius", "a sphere needs its radius (m)");
    if (!voxeliseSphere(*radius, spacing, &grid, &why))
      r.fail(*t.get("radius"), path + "radius", why);
    what = "a ball of radius " + Reader::textOf(*radius) + " m";
  } else if (shape == "mesh") {
    const toml::node* node = t.get("mesh");
    const std::optional<std::string> file = node ? node->value<std::string>() : std::nullopt;
    if (!node) r.fail(at, path + "mesh", "a mesh jelly needs its mesh = \"FILE.obj\"");
    if (!file || file->empty())
      r.fail(*node, path + "mesh", "expected the path of an OBJ file or a TetGen .node file");
    if (file->size() > 5 && file->compare(file->size() - 5, 5, ".node") == 0) {
      if (t.get("spacing"))
        r.fail(*t.get("spacing"), path + "spacing",
               "a TetGen mesh has its own points; spacing is for voxels");
      const std::string nodePath = r.pathFromScene(*file);
      std::string nodeText, eleText;
      r.noteInput(elementFileOf(nodePath));
      if (!readTetMeshFiles(nodePath, &nodeText, &eleText, &why)) r.fail(*node, path + "mesh", why);
      Body body = parseTetMesh(nodeText, nodePath, eleText, elementFileOf(nodePath));
      body.what = "the tetrahedra of " + *file;
      return body;
    }
    TriangleMesh mesh;
    if (!readObjMesh(r.pathFromScene(*file), &mesh, &why) ||
        !voxeliseMesh(mesh, spacing, &grid, &why))
      r.fail(*node, path + "mesh", why);
    keepLargestPiece(&grid);
    what = "the voxels of " + *file;
  } else {
    r.fail(at, path + "shape", "expected \"lattice\", \"sphere\" or \"mesh\"");
  }
  return voxelBody(grid, spacing, what);  // where the voxels lie is the body's placement's
}

// The jelly's body when the table gives a shape, or null (the course cube). Its spacing is the
// voxels' edge: 1/7 m, the course's, unless given.
std::shared_ptr<const Body> readBody(const Reader& r, const toml::table& t,
                                     const std::string& path) {
  const toml::node* node = t.get("shape");
  for (const char* key : {"size", "spacing", "radius", "mesh"})
    if (!node && t.get(key))
      r.fail(*t.get(key), path + key,
             "give the jelly's shape (\"lattice\", \"sphere\" or \"mesh\") with it");
  if (!node) return nullptr;
  const std::optional<std::string> shape = node->value<std::string>();
  if (!shape) r.fail(*node, path + "shape", "expected \"lattice\", \"sphere\" or \"mesh\"");
  for (const auto& [key, owner] :
       {std::pair{"size", "lattice"}, {"radius", "sphere"}, {"mesh", "mesh"}})
    if (t.get(key) && *shape != owner)
      r.fail(*t.get(key), path + key,
             "belongs to shape = \"" + std::string(owner) + "\", not \"" + *shape + "\"");
  const double spacing =
      r.number(t, path, "spacing", kSmallestSpacing, false).value_or(kRestSpacing);
  if (spacing > kLargestSpacing)
    r.fail(*t.get("spacing"), path + "spacing",
           "must be at most " + Reader::textOf(kLargestSpacing));
  return std::make_shared<Body>(readShape(r, t, path, *shape, spacing));
}

// A stiffness or damping: one number for every kind of spring, or a table by kind
// ({structural = ..., shear = ..., bend = ...}; a kind left out keeps *all, the world's).
void readByKind(const Reader& r, const toml::table& t, const std::string& path, const char* key,
                double* all, std::array<double, kSpringKinds>* byKind, bool* perKind) {
  const toml::node* node = t.get(key);
  if (!node) return;
  const std::string full = path + key;
  if (const toml::table* kinds = node->as_table()) {
    r.onlyKeys(*kinds, full + ".", {"structural", "shear", "bend"});
    for (int kind = 0; kind < kSpringKinds; ++kind)
      if (auto v = r.number(*kinds, full + ".", springKindName(SpringKind(kind)), 0))
        (*byKind)[kind] = *v;
    *perKind = true;
    return;
  }
  *all = *r.number(t, path, key, 0);
  byKind->fill(*all);
}

// The keys that gave the jelly's shape, once readBody has checked them.
JellyRecipe recipeOf(const Reader& r, const toml::table& t, const std::string& path) {
  JellyRecipe recipe;
  recipe.shape = t.get("shape") ? *t.get("shape")->value<std::string>() : "";
  if (const toml::array* size = t.get("size") ? t.get("size")->as_array() : nullptr)
    for (int i = 0; i < 3; ++i)
      recipe.size[i] = static_cast<int>(*size->get(i)->value<std::int64_t>());
  recipe.radius = r.number(t, path, "radius", 0, true).value_or(0);
  if (const toml::node* mesh = t.get("mesh"))
    recipe.mesh = r.pathFromScene(*mesh->value<std::string>());
  recipe.spacing = r.number(t, path, "spacing", kSmallestSpacing, false);
  return recipe;
}

// A jelly's rest placement: a shaped body centred on the origin (the middle of its grid, or of a
// mesh's bounding box); the course cube as the default world has it.
State placedBody(const Body& body) {
  const int n = body.count();
  State state(n);
  Vec3 middle =
      0.5 * body.spacing * Vec3{double(body.nx - 1), double(body.ny - 1), double(body.nz - 1)};
  if (body.gridless()) {
    Vec3 lower = body.rest[0], upper = body.rest[0];
    for (const Vec3& x : body.rest) {
      lower = {std::min(lower.x, x.x), std::min(lower.y, x.y), std::min(lower.z, x.z)};
      upper = {std::max(upper.x, x.x), std::max(upper.y, x.y), std::max(upper.z, x.z)};
    }
    middle = 0.5 * (lower + upper);
  }
  for (int q = 0; q < n; ++q) store(state.p(), q, n, body.restPosition(q) - middle);
  return state;
}

// The jelly's material: springs unless `material` names elements, which then need Young's modulus,
// Poisson's ratio and the density, and take no spring constants and no mass (theirs is lumped).
Material readMaterial(const Reader& r, const toml::table& t, const std::string& path) {
  Material m;
  const toml::node* node = t.get("material");
  const char* kElementKeys[] = {"youngs_modulus", "poisson_ratio", "density", "mass_damping",
                                "stiffness_damping"};
  if (node) {
    std::optional<std::string> name = node->value<std::string>();
    if (name)
      for (char& c : *name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    const MaterialInfo* found = nullptr;
    for (const MaterialInfo& info : kMaterials)
      if (name && *name == info.name) found = &info;
    if (!found)
      r.fail(*node, path + "material", "expected \"springs\", \"corotated\" or \"neohookean\"");
    m.kind = found->kind;
  }
  if (!m.elements()) {
    for (const char* key : kElementKeys)
      if (t.get(key))
        r.fail(*t.get(key), path + key,
               "belongs to a jelly of finite elements (material = \"corotated\" or "
               "\"neohookean\")");
    return m;
  }
  for (const char* key : {"mass", "total_mass", "stiffness", "damping"})
    if (t.get(key))
      r.fail(
          *t.get(key), path + key,
          std::string("a jelly of finite elements takes ") +
              (key[0] == 'm' || key[0] == 't' ? "its mass from its density"
                                              : "youngs_modulus and poisson_ratio, not springs"));
  for (const char* key : {"youngs_modulus", "poisson_ratio", "density"})
    if (!t.get(key))
      r.fail(*node, path + key, std::string("a jelly of finite elements needs its ") + key);
  m.youngsModulus = *r.number(t, path, "youngs_modulus", 0, true);
  m.poissonRatio = *r.number(t, path, "poisson_ratio");
  if (m.poissonRatio < smallestPoissonRatio(m.kind) || m.poissonRatio > kLargestPoissonRatio)
    r.fail(*t.get("poisson_ratio"), path + "poisson_ratio",
           "must be from " + Reader::textOf(smallestPoissonRatio(m.kind)) + " to " +
               Reader::textOf(kLargestPoissonRatio) +
               (m.kind == MaterialKind::NeoHookean
                    ? " (at -1 a solid could not keep its volume, at 0.5 it could not change it)"
                    : " for corotated elasticity (below 0, material = \"neohookean\")"));
  m.density = *r.number(t, path, "density", 0, true);
  if (m.density < kSmallestDensity || m.density > kLargestDensity)
    r.fail(*t.get("density"), path + "density",
           "must be from " + Reader::textOf(kSmallestDensity) + " to " +
               Reader::textOf(kLargestDensity) + " kg/m^3");
  m.massDamping = r.number(t, path, "mass_damping", 0, false).value_or(0);
  m.stiffnessDamping = r.number(t, path, "stiffness_damping", 0, false).value_or(0);
  return m;
}

// The body of a jelly of elements: its shape's (the course cube's without one), without springs.
std::shared_ptr<const Body> elementBody(const Reader& r, const toml::table& t,
                                        const std::string& path,
                                        std::shared_ptr<const Body> shaped) {
  Body body = shaped ? *shaped : courseBody();
  if (isSheet(body))
    r.fail(*t.get("material"), path + "material",
           "a sheet has no volume to make elements of: a cloth is made of springs");
  body.springs.clear();
  body.courseLattice = false;
  return std::make_shared<Body>(std::move(body));
}

// One jelly's table: its body (null: the course cube), placed state, mass and springs, starting
// from the world's.
struct ReadJelly {
  std::shared_ptr<const Body> body;
  State state;
  JellySpec spec;
  bool perKind = false;
  double kElastic = 0, dElastic = 0;
};

ReadJelly readOne(const Reader& r, const toml::table& t, const std::string& path, const World& w,
                  const State& courseState) {
  r.onlyKeys(t, path, std::vector<std::string>(kJellyKeys.begin(), kJellyKeys.end()));
  ReadJelly out;
  out.body = readBody(r, t, path);
  out.spec.material = readMaterial(r, t, path);
  if (out.spec.material.elements()) out.body = elementBody(r, t, path, out.body);
  out.state = out.body ? placedBody(*out.body) : courseState;
  const int n = out.state.points();
  if (const toml::node* self = t.get("self_contact"); self && out.body && out.body->gridless())
    r.fail(*self, path + "self_contact", "self-contact needs a jelly on a grid, not a TetGen mesh");
  if (t.get("mass") && t.get("total_mass"))
    r.fail(*t.get("total_mass"), path + "total_mass",
           "give mass (per point) or total_mass, not both");
  out.spec.mass = w.mass;
  if (out.spec.material.elements()) out.spec.mass = meanElementMass(*out.body, out.spec.material);
  if (auto m = r.number(t, path, "mass", 0, true)) out.spec.mass = *m;
  if (auto m = r.number(t, path, "total_mass", 0, true)) out.spec.mass = *m / n;
  out.kElastic = w.kElastic, out.dElastic = w.dElastic;
  out.spec.springs = SpringConstants::same(w.kElastic, w.dElastic);
  readByKind(r, t, path, "stiffness", &out.kElastic, &out.spec.springs.k, &out.perKind);
  readByKind(r, t, path, "damping", &out.dElastic, &out.spec.springs.d, &out.perKind);
  if (const toml::node* self = t.get("self_contact")) {
    if (!self->is_boolean()) r.fail(*self, path + "self_contact", "expected true or false");
    out.spec.selfContact = *self->value<bool>();
  }
  out.spec.recipe = recipeOf(r, t, path);
  const Vec3 offset = r.vector(t, path, "offset").value_or(Vec3{});
  const std::optional<Vec3> velocity = r.vector(t, path, "velocity");
  for (int q = 0; q < n; ++q) {
    store(out.state.p(), q, n, load(out.state.p(), q, n) + offset);
    if (velocity) store(out.state.v(), q, n, *velocity);
  }
  return out;
}

// Several jellies: their bodies joined, their states one after another.
void readSeveral(const Reader& r, const toml::array& array, WorldFile* file, SceneSpec* spec) {
  if (array.size() > std::size_t(kMostJellies))
    r.fail(*array.get(kMostJellies), "jelly",
           "more than " + std::to_string(kMostJellies) + " jellies");
  std::vector<std::shared_ptr<const Body>> bodies;
  std::vector<State> states;
  std::size_t points = 0;
  for (std::size_t i = 0; i < array.size(); ++i) {
    const std::string path = "jelly[" + std::to_string(i + 1) + "].";
    ReadJelly one = readOne(r, *array.get(i)->as_table(), path, file->world, file->state);
    if (!one.body) one.body = std::make_shared<Body>(courseBody());
    points += one.body->count();
    if (points > std::size_t(kMostScenePoints))
      r.fail(*array.get(i), "jelly",
             "more than " + std::to_string(kMostScenePoints) + " points in all");
    bodies.push_back(one.body);
    states.push_back(std::move(one.state));
    spec->jellies.push_back(one.spec);
  }
  spec->body = std::make_shared<Body>(joinBodies(bodies));
  const int n = spec->body->count();
  State joined(n);
  for (std::size_t p = 0; p < states.size(); ++p) {
    const int first = spec->body->partFirst[p], count = states[p].points();
    for (int q = 0; q < count; ++q) {
      store(joined.p(), first + q, n, load(states[p].p(), q, count));
      store(joined.v(), first + q, n, load(states[p].v(), q, count));
    }
  }
  file->state = std::move(joined);
  file->world.mass = spec->jellies[0].mass;
  file->world.kElastic = spec->jellies[0].springs.k[0];
  file->world.dElastic = spec->jellies[0].springs.d[0];
}

}  // namespace

void readJelly(const Reader& r, const toml::table& root, WorldFile* file, SceneSpec* spec) {
  const toml::node* node = root.get("jelly");
  if (!node) return;
  if (const toml::array* array = node->as_array(); array && array->is_array_of_tables()) {
    if (array->size() > 1) return readSeveral(r, *array, file, spec);
    node = array->get(0);
  }
  if (!node->is_table()) r.fail(*node, "jelly", "expected a [jelly] table or [[jelly]] tables");
  const std::string path = root.get("jelly")->is_array() ? "jelly[1]." : "jelly.";
  ReadJelly one = readOne(r, *node->as_table(), path, file->world, file->state);
  World& w = file->world;
  spec->body = one.body;
  file->state = std::move(one.state);
  w.mass = one.spec.mass;
  w.kElastic = one.kElastic;
  w.dElastic = one.dElastic;
  if (one.perKind) spec->springs = one.spec.springs;
  spec->selfContact = one.spec.selfContact;
  spec->material = one.spec.material;
  spec->recipe = one.spec.recipe;
}

namespace {

// The bounds of points [first, end) of a per-point array of n points.
Bounds partBounds(const double* p, int first, int end, int n) {
  Bounds b{load(p, first, n), load(p, first, n)};
  for (int q = first; q < end; ++q) {
    const Vec3 x = load(p, q, n);
    b.lower = {std::min(b.lower.x, x.x), std::min(b.lower.y, x.y), std::min(b.lower.z, x.z)};
    b.upper = {std::max(b.upper.x, x.x), std::max(b.upper.y, x.y), std::max(b.upper.z, x.z)};
  }
  return b;
}

}  // namespace

void checkJellies(const Reader& r, const toml::table& root, const WorldFile& file,
                  const SceneSpec& spec) {
  if (spec.jellies.empty()) return;
  const Body& body = *spec.body;
  const toml::array& tables = *root.get("jelly")->as_array();
  const int n = body.count();
  const double* p = file.state.p();
  auto fail = [&](int part, const std::string& what) {
    r.fail(*tables.get(part), "jelly[" + std::to_string(part + 1) + "].offset", what);
  };
  if (spec.boundsPresent) {
    const Vec3 lower =
        spec.bounds ? spec.bounds->lower : Vec3{-kBoxHalfSize, -kBoxHalfSize, -kBoxHalfSize};
    const Vec3 upper =
        spec.bounds ? spec.bounds->upper : Vec3{kBoxHalfSize, kBoxHalfSize, kBoxHalfSize};
    for (int q = 0; q < n; ++q)
      if (!inBox(load(p, q, n), lower, upper))
        fail(body.partOf(q), "jelly " + std::to_string(body.partOf(q) + 1) +
                                 " starts outside the bounding box (its point " + body.label(q) +
                                 ")");
  }
  // Closer than the contact distance: the contact's own pairs at the start.
  std::vector<ContactPart> parts;
  for (std::size_t i = 0; i < body.parts.size(); ++i) {
    const double distance = spec.bodyContact->distance;
    parts.push_back({distance > 0 ? distance / 2 : body.parts[i]->spacing / 2, false});
  }
  const BodyContactTerm contact(body, parts, *spec.bodyContact);
  for (const ContactPair& pair : contact.contacts(p))
    fail(body.partOf(pair.b),
         "jelly " + std::to_string(body.partOf(pair.b) + 1) + " starts overlapping jelly " +
             std::to_string(body.partOf(pair.a) + 1) + ": points " + body.label(pair.a) + " and " +
             body.label(pair.b) + " are closer than their contact distance " +
             Reader::textOf(pair.distance) + " m");
  // Wholly inside another: one of its points inside the other's surface (where it is inside the
  // other's bounding box at all).
  std::vector<Bounds> box;
  for (std::size_t b = 0; b < body.parts.size(); ++b)
    box.push_back(partBounds(p, body.partFirst[b], body.partFirst[b + 1], n));
  for (std::size_t a = 0; a < body.parts.size(); ++a)
    for (std::size_t b = 0; b < body.parts.size(); ++b) {
      if (a == b || isSheet(*body.parts[b])) continue;
      const int q = body.partFirst[a];
      const Vec3 x = load(p, q, n);
      if (!inBox(x, box[b].lower, box[b].upper)) continue;
      if (std::fabs(windingNumber(body, static_cast<int>(b), p, x)) > 0.5)
        fail(static_cast<int>(a),
             "jelly " + std::to_string(a + 1) + " starts inside jelly " + std::to_string(b + 1));
    }
}

}  // namespace jello
