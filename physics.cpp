// physics.cpp: forces of the jello model. See physics.h for units and signs.

#include "physics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace jello {

const std::vector<SpringOffset> kSpringOffsets = {
    // structural
    {1, 0, 0, SpringKind::Structural},
    {0, 1, 0, SpringKind::Structural},
    {0, 0, 1, SpringKind::Structural},
    // face shear
    {1, 1, 0, SpringKind::Shear},
    {1, -1, 0, SpringKind::Shear},
    {1, 0, 1, SpringKind::Shear},
    {1, 0, -1, SpringKind::Shear},
    {0, 1, 1, SpringKind::Shear},
    {0, 1, -1, SpringKind::Shear},
    // body shear
    {1, 1, 1, SpringKind::Shear},
    {1, 1, -1, SpringKind::Shear},
    {1, -1, 1, SpringKind::Shear},
    {1, -1, -1, SpringKind::Shear},
    // bend
    {2, 0, 0, SpringKind::Bend},
    {0, 2, 0, SpringKind::Bend},
    {0, 0, 2, SpringKind::Bend},
};

std::vector<SpringGroup> buildSpringGroups() {
  std::vector<SpringGroup> groups;
  auto inside = [](int c) { return c >= 0 && c < kLatticeSize; };
  for (const SpringOffset& o : kSpringOffsets) {
    SpringGroup g;
    g.kind = o.kind;
    g.delta = pointIndex(o.di, o.dj, o.dk);
    g.rest = kRestSpacing * std::sqrt(double(o.di * o.di + o.dj * o.dj + o.dk * o.dk));
    g.mask.assign(kNumPoints, 0.0);
    for (int i = 0; i < kLatticeSize; ++i)
      for (int j = 0; j < kLatticeSize; ++j) {
        if (!inside(i + o.di) || !inside(j + o.dj)) continue;
        const int rowBegin = pointIndex(i, j, 0), rowEnd = rowBegin + kLatticeSize;
        if (!g.spans.empty() && g.spans.back().end == rowBegin) g.spans.back().end = rowEnd;
        else g.spans.push_back({rowBegin, rowEnd});
        for (int k = 0; k < kLatticeSize; ++k)
          if (inside(k + o.dk)) g.mask[pointIndex(i, j, k)] = 1.0;
      }
    // The last row's discarded slots would reach past the last point: they end the last span.
    g.spans.back().end = std::min(g.spans.back().end, kNumPoints - g.delta);
    groups.push_back(std::move(g));
  }
  return groups;
}

// The same table walk as the kernel's: the springs are the groups' slots that are kept.
std::vector<Spring> buildSprings() {
  std::vector<Spring> springs;
  for (const SpringGroup& g : buildSpringGroups())
    for (const SpringGroup::Span& span : g.spans)
      for (int q = span.begin; q < span.end; ++q)
        if (g.mask[q] != 0) springs.push_back({q, q + g.delta, g.rest, g.kind});
  return springs;
}

Scene analyseScene(const World& world) {
  Scene scene;
  scene.dampers = world.dElastic != 0;
  scene.plane = world.hasPlane;
  scene.field = fieldUse(world.field);
  if (scene.field == FieldUse::Uniform) scene.uniformForce = world.field.node(0);
  return scene;
}

FieldUse fieldUse(const ForceField& field) {
  if (field.resolution == 0) return FieldUse::Absent;
  const Vec3 first = field.node(0);
  bool zero = true, uniform = true;
  const std::size_t nodes = field.forces.size() / 3;
  for (std::size_t n = 0; n < nodes; ++n) {
    Vec3 f = field.node(n);
    zero = zero && f.x == 0 && f.y == 0 && f.z == 0;
    uniform = uniform && f.x == first.x && f.y == first.y && f.z == first.z;
  }
  return zero ? FieldUse::Zero : uniform ? FieldUse::Uniform : FieldUse::Trilinear;
}

std::string sceneLine(const Scene& scene, const World& world) {
  std::string kept = "springs", left;
  auto leave = [&left](const std::string& what) { left += (left.empty() ? "" : ", ") + what; };
  if (scene.dampers) kept += ", dampers";
  else leave("dampers (zero damping)");
  kept += ", walls (when the cube's bounding box reaches them)";
  if (scene.plane) kept += ", plane (when the bounding box reaches it)";
  else leave("plane (none in the file)");
  const std::string r = std::to_string(world.field.resolution);
  switch (scene.field) {
    case FieldUse::Absent: leave("field (none in the file)"); break;
    case FieldUse::Zero: leave("field (all zero)"); break;
    case FieldUse::Uniform: kept += ", field (uniform: a constant, no interpolation)"; break;
    case FieldUse::Trilinear: kept += ", field (trilinear, " + r + "^3 nodes)"; break;
  }
  return "scene: kept: " + kept + "; left out: " + (left.empty() ? "nothing" : left);
}

namespace {
// Inside the box, walls included; false for a non-finite point.
bool insideBox(Vec3 p) {
  return std::fabs(p.x) <= kBoxHalfSize && std::fabs(p.y) <= kBoxHalfSize && std::fabs(p.z) <= kBoxHalfSize;
}
}  // namespace

Vec3 wallForce(Vec3 p, Vec3 v, double k, double d) {
  Vec3 force;
  for (int axis = 0; axis < 3; ++axis) force += wallForceAlong(axis, p, v, k, d);
  return force;
}

Plane normalisedPlane(const Plane& plane) {
  const double largest = std::max({std::fabs(plane.a), std::fabs(plane.b), std::fabs(plane.c)});
  if (largest == 0 || !std::isfinite(largest)) return plane;  // refused by the reader already
  int exponent;
  std::frexp(largest, &exponent);  // largest = m 2^exponent, m in [0.5, 1)
  return {std::ldexp(plane.a, -exponent), std::ldexp(plane.b, -exponent),
          std::ldexp(plane.c, -exponent), std::ldexp(plane.d, -exponent)};
}

std::string planeProblem(const Plane& plane) {
  if (plane.a == 0 && plane.b == 0 && plane.c == 0) return "the plane's normal (a,b,c) is zero";
  if (!std::isfinite(normalisedPlane(plane).d)) {
    return "the plane is too far from the origin to simulate: d is more than 1e308 times the "
           "largest of |a|, |b|, |c|, beyond the range of doubles";
  }
  return "";
}

int pointsAcrossPlane(const Model& model, const State& state) {
  if (!model.world.hasPlane) return 0;
  int across = 0;
  for (int q = 0; q < kNumPoints; ++q)
    if (planeValue(model.plane, load(state.p(), q)) * model.planeSide < 0) ++across;
  return across;
}

namespace {
constexpr int kPaddedNode = 4;  // doubles per node in Model::paddedField

// A coordinate's cell along one axis, and its position in it. The cell is clamped in floating
// point, so that only a number in [0, lastCell] reaches the integer conversion: a NaN fails
// g >= 0 and takes cell 0 (std::max(NaN, 0.0) would have kept it NaN).
struct CellCoordinate {
  int cell;
  double t;  // position within the cell, 0..1
};
inline CellCoordinate cellCoordinate(double x, double cellsPerMetre, double lastCell) {
  double g = (x + kBoxHalfSize) * cellsPerMetre;
  const double clamped = !(g >= 0) ? 0.0 : g > lastCell ? lastCell : g;
  int cell = static_cast<int>(std::floor(clamped));
  return {cell, g - cell};
}
// A node's force: its 3 doubles in the world's field, or 4 in the kernel's padded copy (the
// 4th is zero), which makes every interpolation step below one 256-bit vector operation.
template <int kStride>
struct NodeForce {
  double c[kStride];
};

// From the nearer end, a + t (b - a) or b - (1 - t) (b - a): equal corners give back exactly
// their value, so a uniform field interpolates to itself bit for bit (the kernel's constant
// fast path agrees with this, where a sum of eight weighted corners would be off by an ulp or
// two), and a node gives exactly its own force from either cell. t - 1 is exact for t >= 0.5.
template <int kStride>
inline NodeForce<kStride> lerp(const NodeForce<kStride>& a, const NodeForce<kStride>& b, double t) {
  const bool nearA = t < 0.5;
  const double s = nearA ? t : t - 1;
  NodeForce<kStride> out;
  for (int i = 0; i < kStride; ++i) out.c[i] = (nearA ? a.c[i] : b.c[i]) + s * (b.c[i] - a.c[i]);
  return out;
}

// Trilinear interpolation of a field of resolution r >= 2 at a point inside the box.
template <int kStride>
inline Vec3 trilinear(const double* f, int r, Vec3 p) {
  const double cellsPerMetre = (r - 1) / (2 * kBoxHalfSize), lastCell = r - 2;
  const CellCoordinate x = cellCoordinate(p.x, cellsPerMetre, lastCell), y = cellCoordinate(p.y, cellsPerMetre, lastCell),
                       z = cellCoordinate(p.z, cellsPerMetre, lastCell);
  const double* base = f + kStride * ((x.cell * r + y.cell) * r + z.cell);
  auto node = [base, r](int di, int dj, int dk) {
    const double* n = base + kStride * ((di * r + dj) * r + dk);
    NodeForce<kStride> out;
    for (int i = 0; i < kStride; ++i) out.c[i] = n[i];
    return out;
  };
  using N = NodeForce<kStride>;
  const N c00 = lerp(node(0, 0, 0), node(0, 0, 1), z.t), c01 = lerp(node(0, 1, 0), node(0, 1, 1), z.t);
  const N c10 = lerp(node(1, 0, 0), node(1, 0, 1), z.t), c11 = lerp(node(1, 1, 0), node(1, 1, 1), z.t);
  const N value = lerp(lerp(c00, c01, y.t), lerp(c10, c11, y.t), x.t);
  return {value.c[0], value.c[1], value.c[2]};
}
}  // namespace

Vec3 fieldForce(const ForceField& field, Vec3 p) {
  const int r = field.resolution;
  if (r == 0 || !insideBox(p)) return {};
  const double* f = field.forces.data();
  if (r == 1) return {f[0], f[1], f[2]};
  return trilinear<3>(f, r, p);
}

Vec3 pullForce(const Pull& pull, Vec3 p) { return pull.stiffness * (pull.target - p); }

namespace {

// The force kernel is one template; its parameter says which terms an instantiation computes.
// Bits 0 and 1: the springs' dampers, the plane. Bits 2-3: the field (0 none, 1 uniform,
// 2 trilinear). Bit 4: culling, i.e. walls and plane are tested only when the positions'
// bounding box reaches them. The general kernel has every term and no culling: it does, per
// point, what SPEC.md section 2 says.
constexpr unsigned kDampersBit = 1, kPlaneBit = 2, kFieldShift = 2, kCullingBit = 16;
constexpr unsigned kNoField = 0, kUniformField = 1, kTrilinearField = 2;
constexpr unsigned kSpecialisations = 12;  // dampers x plane x three fields
constexpr unsigned kGeneral = kDampersBit | kPlaneBit | (kTrilinearField << kFieldShift);

constexpr unsigned fieldOf(unsigned features) { return (features >> kFieldShift) & 3; }

struct Bounds {
  Vec3 lower, upper;
};

// Bounds of the coordinates. (With a NaN among them they mean little; such a state is caught
// as diverged after this very step.) Eight running bounds side by side, not one: an
// element-wise min the compiler vectorises, where a single running min is a reduction it may
// not reorder.
Bounds boundsOf(const double* p) {
  constexpr int kLanes = 8;
  static_assert(kNumPoints % kLanes == 0);
  double lower[3], upper[3];
  for (int axis = 0; axis < 3; ++axis) {
    const double* c = p + axis * kNumPoints;
    double lo[kLanes], hi[kLanes];
    for (int l = 0; l < kLanes; ++l) lo[l] = hi[l] = c[l];
    for (int q = kLanes; q < kNumPoints; q += kLanes)
      for (int l = 0; l < kLanes; ++l) {
        lo[l] = c[q + l] < lo[l] ? c[q + l] : lo[l];
        hi[l] = c[q + l] > hi[l] ? c[q + l] : hi[l];
      }
    lower[axis] = *std::min_element(lo, lo + kLanes);
    upper[axis] = *std::max_element(hi, hi + kLanes);
  }
  return {{lower[0], lower[1], lower[2]}, {upper[0], upper[1], upper[2]}};
}

// Whether some point in the box `b` might be strictly across the plane: the smallest value of
// side * (a x + b y + c z + d) over the box, at one of its corners, is not clearly positive.
// The margin covers the rounding by which a point's own value may differ from the corner's.
bool mayCrossPlane(const Plane& plane, double side, const Bounds& b) {
  auto lowest = [side](double coefficient, double lo, double hi) {
    return std::min(side * coefficient * lo, side * coefficient * hi);
  };
  double smallest = lowest(plane.a, b.lower.x, b.upper.x) + lowest(plane.b, b.lower.y, b.upper.y) +
                    lowest(plane.c, b.lower.z, b.upper.z) + side * plane.d;
  auto largest = [](double lo, double hi) { return std::max(std::fabs(lo), std::fabs(hi)); };
  double scale = std::fabs(plane.a) * largest(b.lower.x, b.upper.x) + std::fabs(plane.b) * largest(b.lower.y, b.upper.y) +
                 std::fabs(plane.c) * largest(b.lower.z, b.upper.z) + std::fabs(plane.d);
  constexpr double kRelativeMargin = 1e-12;
  return !(smallest > kRelativeMargin * scale);
}

// The springs of one group: the forces of all slots first (loops the compiler vectorises),
// then one pass over the points adding each point's two springs of the group, the one that
// ends at it (q - delta to q) before the one that starts at it: the order in which a loop over
// single springs adds them, so the sums round the same way. f holds zeros before slot 0 and
// outside the spans, so that both reads are plain loads.
constexpr int kMaxDelta = 2 * kLatticeSize * kLatticeSize;  // the bend spring along i
template <bool kDampers>
void addSpringGroup(const SpringGroup& g, double k, double d, const double* __restrict p,
                    const double* __restrict v, double* __restrict force) {
  const double* __restrict mask = g.mask.data();
  alignas(64) double buffer[3][kMaxDelta + kNumPoints];
  const double *px = p, *py = p + kNumPoints, *pz = p + 2 * kNumPoints;
  const double *vx = v, *vy = v + kNumPoints, *vz = v + 2 * kNumPoints;
  const int b = g.delta;
  int written = -b;  // buffer slots before this one are set
  for (const SpringGroup::Span& span : g.spans) {
    for (double* f : buffer) std::fill(f + kMaxDelta + written, f + kMaxDelta + span.begin, 0.0);
    written = span.end;
    for (int q = span.begin; q < span.end; ++q) {
      double len;
      Vec3 u = direction({px[q] - px[q + b], py[q] - py[q + b], pz[q] - pz[q + b]}, &len);
      double tension = springTension(len, k, g.rest);
      if constexpr (kDampers) tension += damperTension({vx[q] - vx[q + b], vy[q] - vy[q + b], vz[q] - vz[q + b]}, u, d);
      Vec3 fq = (mask[q] * tension) * u;
      buffer[0][kMaxDelta + q] = fq.x;
      buffer[1][kMaxDelta + q] = fq.y;
      buffer[2][kMaxDelta + q] = fq.z;
    }
  }
  for (int axis = 0; axis < 3; ++axis) {
    double* __restrict out = force + axis * kNumPoints;
    double* f = buffer[axis] + kMaxDelta;
    std::fill(f + written, f + kNumPoints, 0.0);
    for (int q = 0; q < kNumPoints; ++q) out[q] = (out[q] - f[q - b]) + f[q];
  }
}

// Point by point, each interpolation step one vector operation on padded nodes: 40% faster
// here than scalar steps, where vectorising across points (gathers) was 20% slower.
void addTrilinearField(const double* padded, int r, const double* p, double* force) {
  for (int q = 0; q < kNumPoints; ++q) store(force, q, load(force, q) + trilinear<kPaddedNode>(padded, r, load(p, q)));
}

// The field's force at a point that may be outside the box.
template <unsigned kFeatures>
Vec3 fieldTerm(const Model& model, Vec3 p) {
  if constexpr (fieldOf(kFeatures) == kTrilinearField && (kFeatures & kCullingBit) != 0) {
    // The padded copy (a specialised trilinear field has R >= 2), selected inside the box.
    Vec3 f = trilinear<kPaddedNode>(model.paddedField.data(), model.world.field.resolution, p);
    const bool inside = insideBox(p);
    return {inside ? f.x : 0.0, inside ? f.y : 0.0, inside ? f.z : 0.0};
  }
  if constexpr (fieldOf(kFeatures) == kTrilinearField) return fieldForce(model.world.field, p);
  if constexpr (fieldOf(kFeatures) == kUniformField) return insideBox(p) ? model.scene.uniformForce : Vec3{};
  return {};
}

template <unsigned kFeatures>
void forceKernel(const Model& model, const double* p, const double* v, double* force, const Pull* pull) {
  const World& w = model.world;
  std::fill(force, force + kNumCoords, 0.0);
  for (const SpringGroup& g : model.groups)
    addSpringGroup<(kFeatures & kDampersBit) != 0>(g, w.kElastic, w.dElastic, p, v, force);

  bool walls[3] = {true, true, true}, plane = (kFeatures & kPlaneBit) && w.hasPlane;
  if constexpr ((kFeatures & kCullingBit) != 0) {
    const Bounds bounds = boundsOf(p);
    walls[0] = bounds.upper.x > kBoxHalfSize || bounds.lower.x < -kBoxHalfSize;
    walls[1] = bounds.upper.y > kBoxHalfSize || bounds.lower.y < -kBoxHalfSize;
    walls[2] = bounds.upper.z > kBoxHalfSize || bounds.lower.z < -kBoxHalfSize;
    plane = plane && mayCrossPlane(model.plane, model.planeSide, bounds);
  }
  if (walls[0] || walls[1] || walls[2] || plane) {
    // Some point may touch a wall or the plane: the contact forces of all points first (a
    // loop that vectorises; a wall pair out of reach adds nothing and is left out), then the
    // field's, summed in the order SPEC.md lists the terms.
    alignas(64) double contact[kNumCoords];
    for (int q = 0; q < kNumPoints; ++q) {
      const Vec3 pq = load(p, q), vq = load(v, q);
      Vec3 f;
      for (int axis = 0; axis < 3; ++axis)
        if (walls[axis]) f += wallForceAlong(axis, pq, vq, w.kCollision, w.dCollision);
      if (plane) f += planeForce(model.plane, model.planeSide, pq, vq, w.kCollision, w.dCollision);
      store(contact, q, f);
    }
    for (int q = 0; q < kNumPoints; ++q)
      store(force, q, load(force, q) + (load(contact, q) + fieldTerm<kFeatures>(model, load(p, q))));
  } else if constexpr (fieldOf(kFeatures) == kUniformField) {
    // Every point is inside the box (the walls would be reached otherwise).
    for (int q = 0; q < kNumPoints; ++q) store(force, q, load(force, q) + model.scene.uniformForce);
  } else if constexpr (fieldOf(kFeatures) == kTrilinearField) {
    // Only a specialisation gets here (the general kernel always takes the contact path), and
    // a field the scene calls trilinear has R >= 2: one node would be uniform.
    addTrilinearField(model.paddedField.data(), w.field.resolution, p, force);
  }
  if (pull && pull->point >= 0) store(force, pull->point, load(force, pull->point) + pullForce(*pull, load(p, pull->point)));
}

template <std::size_t... kCode>
constexpr std::array<ForceKernel, sizeof...(kCode)> specialisations(std::index_sequence<kCode...>) {
  return {&forceKernel<kCullingBit | static_cast<unsigned>(kCode)>...};
}
constexpr std::array<ForceKernel, kSpecialisations> kSpecialised =
    specialisations(std::make_index_sequence<kSpecialisations>());

ForceKernel kernelFor(const Scene& scene, KernelChoice choice) {
  if (choice == KernelChoice::General) return &forceKernel<kGeneral>;
  unsigned field = scene.field == FieldUse::Uniform     ? kUniformField
                   : scene.field == FieldUse::Trilinear ? kTrilinearField
                                                        : kNoField;
  unsigned code = (scene.dampers ? kDampersBit : 0) | (scene.plane ? kPlaneBit : 0) | (field << kFieldShift);
  return kSpecialised[code];
}

}  // namespace

Model makeModel(const World& world, const State& initial, KernelChoice choice) {
  Model model;
  model.world = world;
  model.springs = buildSprings();
  model.groups = buildSpringGroups();
  model.scene = analyseScene(world);
  model.kernel = kernelFor(model.scene, choice);
  if (model.scene.field == FieldUse::Trilinear) {
    const std::size_t nodes = world.field.forces.size() / 3;
    model.paddedField.assign(kPaddedNode * nodes, 0.0);
    for (std::size_t n = 0; n < nodes; ++n)
      for (int axis = 0; axis < 3; ++axis) model.paddedField[kPaddedNode * n + axis] = world.field.forces[3 * n + axis];
  }
  if (world.hasPlane) {
    model.plane = normalisedPlane(world.plane);
    Vec3 centroid;
    for (int q = 0; q < kNumPoints; ++q) centroid += load(initial.p(), q);
    centroid = (1.0 / kNumPoints) * centroid;
    model.planeSide = planeValue(model.plane, centroid) >= 0 ? 1 : -1;
  }
  return model;
}

void derivative(const Model& model, const double* y, double* dydt, const Pull* pull) {
  const double* p = y;
  const double* v = y + kNumCoords;
  std::copy(v, v + kNumCoords, dydt);
  double* a = dydt + kNumCoords;
  computeForces(model, p, v, a, pull);
  const double mass = model.world.mass;
  for (int c = 0; c < kNumCoords; ++c) a[c] /= mass;
}

int findDivergedPoint(const State& state) {
  const double* p = state.p();
  const double* v = state.v();
  for (int q = 0; q < kNumPoints; ++q) {
    Vec3 pq = load(p, q), vq = load(v, q);
    bool finite = std::isfinite(pq.x) && std::isfinite(pq.y) && std::isfinite(pq.z) &&
                  std::isfinite(vq.x) && std::isfinite(vq.y) && std::isfinite(vq.z);
    if (!finite || dot(pq, pq) > kDivergenceRadius * kDivergenceRadius) return q;
  }
  return -1;
}

}  // namespace jello
