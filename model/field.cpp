// model/field.cpp: the force field: interpolation, its gradient, the kernel's fast paths, and
// the recognition of the course's fields.

#include "model/field.h"

#include <algorithm>
#include <cmath>

#include "core/assert.h"
#include "model/pack.h"
#include "model/walls.h"

namespace jello {

FieldUse fieldUse(FieldView field) {
  if (field.resolution == 0) return FieldUse::Absent;
  const Vec3 first = field.node(0);
  bool zero = true, uniform = true;
  const std::size_t nodes = field.nodes();
  for (std::size_t n = 0; n < nodes; ++n) {
    Vec3 f = field.node(n);
    zero = zero && f.x == 0 && f.y == 0 && f.z == 0;
    uniform = uniform && f.x == first.x && f.y == first.y && f.z == first.z;
  }
  return zero ? FieldUse::Zero : uniform ? FieldUse::Uniform : FieldUse::Trilinear;
}

namespace {

constexpr int kPaddedNode = 4;  // doubles per node in the padded copy

// A coordinate's cell along one axis, and its position in it: the one mapping the force and
// its gradient share. The cell is clamped in floating point, so that only a number in
// [0, lastCell] reaches the integer conversion: a NaN fails g >= 0 and takes cell 0
// (std::max(NaN, 0.0) would have kept it NaN).
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
inline double cellsPerMetre(int r) { return (r - 1) / (2 * kBoxHalfSize); }

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
// T is a double, or a vector of them (the kernel's, lane by lane).
template <class T>
inline T lerpValue(T a, T b, T t) {
  const auto nearA = t < 0.5;
  const T s = nearA ? t : t - 1;
  return (nearA ? a : b) + s * (b - a);
}
template <int kStride>
inline NodeForce<kStride> lerp(const NodeForce<kStride>& a, const NodeForce<kStride>& b, double t) {
  NodeForce<kStride> out;
  for (int i = 0; i < kStride; ++i) out.c[i] = lerpValue(a.c[i], b.c[i], t);
  return out;
}

// Trilinear interpolation of a field of resolution r >= 2 at a point inside the box.
template <int kStride>
inline Vec3 trilinear(const double* f, int r, Vec3 p) {
  const double perMetre = cellsPerMetre(r), lastCell = r - 2;
  const CellCoordinate x = cellCoordinate(p.x, perMetre, lastCell),
                       y = cellCoordinate(p.y, perMetre, lastCell),
                       z = cellCoordinate(p.z, perMetre, lastCell);
  const double* base = f + kStride * ((x.cell * r + y.cell) * r + z.cell);
  auto node = [base, r](int di, int dj, int dk) {
    const double* n = base + kStride * ((di * r + dj) * r + dk);
    NodeForce<kStride> out;
    for (int i = 0; i < kStride; ++i) out.c[i] = n[i];
    return out;
  };
  using N = NodeForce<kStride>;
  const N c00 = lerp(node(0, 0, 0), node(0, 0, 1), z.t),
          c01 = lerp(node(0, 1, 0), node(0, 1, 1), z.t);
  const N c10 = lerp(node(1, 0, 0), node(1, 0, 1), z.t),
          c11 = lerp(node(1, 1, 0), node(1, 1, 1), z.t);
  const N value = lerp(lerp(c00, c01, y.t), lerp(c10, c11, y.t), x.t);
  return {value.c[0], value.c[1], value.c[2]};
}

Vec3 referenceForce(const double* f, int r, Vec3 p) {
  if (r == 0 || !insideBox(p)) return {};
  if (r == 1) return {f[0], f[1], f[2]};
  return trilinear<3>(f, r, p);
}

Block3 gradientAt(const double* f, int r, Vec3 p) {
  Block3 J;
  // Outside the box, or not a number (which fails every comparison): no field, no gradient.
  if (r < 2 || !insideBox(p)) return J;
  const double perMetre = cellsPerMetre(r);  // dt/dx of the cell coordinate
  const CellCoordinate c[3] = {cellCoordinate(p.x, perMetre, r - 2),
                               cellCoordinate(p.y, perMetre, r - 2),
                               cellCoordinate(p.z, perMetre, r - 2)};
  for (int corner = 0; corner < 8; ++corner) {
    const int bit[3] = {(corner >> 2) & 1, (corner >> 1) & 1, corner & 1};
    double factor[3], slope[3];
    for (int a = 0; a < 3; ++a) {
      factor[a] = bit[a] ? c[a].t : 1 - c[a].t;
      slope[a] = bit[a] ? perMetre : -perMetre;
    }
    std::size_t node =
        (static_cast<std::size_t>(c[0].cell + bit[0]) * r + (c[1].cell + bit[1])) * r +
        (c[2].cell + bit[2]);
    const Vec3 force = FieldView(f, r).node(node);
    const double fv[3] = {force.x, force.y, force.z};
    const double dw[3] = {slope[0] * factor[1] * factor[2], factor[0] * slope[1] * factor[2],
                          factor[0] * factor[1] * slope[2]};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) J.m[3 * i + j] += fv[i] * dw[j];
  }
  return J;
}

}  // namespace

Vec3 fieldForce(const ForceField& field, Vec3 p) {
  return referenceForce(field.forces.data(), field.resolution, p);
}

Block3 fieldJacobian(const ForceField& field, Vec3 p) {
  return gradientAt(field.forces.data(), field.resolution, p);
}

FieldTerm::FieldTerm(int points, const ForceField& field, double mass, Method method)
    : ForceTerm(points), field_(field), method_(method), mass_(mass) {
  // The node array is the world's whole field: what trilinear() and gradientAt() index.
  JELLO_ASSERT(field.forces.size() == 3 * field_.nodes());
  // A padded field is interpolated between nodes: one node is a uniform field.
  JELLO_ASSERT(method != Method::Padded || field.resolution >= 2);
  const std::size_t nodes = field.forces.size() / 3;
  for (std::size_t n = 0; n < nodes; ++n)
    largestNode_ = std::max(largestNode_, length(field.node(n)));
  if (method == Method::Uniform) uniform_ = field.node(0);
  if (method == Method::Padded) {
    padded_.assign(kPaddedNode * nodes, 0.0);
    for (std::size_t n = 0; n < nodes; ++n)
      for (int axis = 0; axis < 3; ++axis)
        padded_[kPaddedNode * n + axis] = field.forces[3 * n + axis];
  }
}

bool FieldTerm::mayReach(const Bounds& box) const {
  return box.lower.x <= kBoxHalfSize && box.upper.x >= -kBoxHalfSize &&
         box.lower.y <= kBoxHalfSize && box.upper.y >= -kBoxHalfSize &&
         box.lower.z <= kBoxHalfSize && box.upper.z >= -kBoxHalfSize;
}

namespace {
// Every point of the box is inside [-2,2]^3, so no point needs the inside test.
bool allInside(const Bounds* box) { return box && insideBox(box->lower) && insideBox(box->upper); }

// The kernel's interpolation, 8 points at a time, each step the same arithmetic as trilinear()'s
// on each component, so that it gives the same bits. The cells come out of one vector
// computation for the 8 points; the interpolation then works on two points at once, a padded
// node (x, y, z, 0) of each side by side in one Pack: 8 loads and 7 lerps for the pair. Point by
// point (each lerp a 256-bit operation on one node) took 3 times as long, the 8 points' corners
// gathered lane by lane twice as long, with the gather instruction 2.8 times.
struct PackCells {
  Pack cell;  // a whole number
  Pack t;     // position within the cell, 0..1
};
// cellCoordinate() of 8 coordinates.
JELLO_PACK_INLINE PackCells cellsOf(Pack x, Pack perMetre, Pack lastCell) {
  const Pack g = (x + kBoxHalfSize) * perMetre;
  const Pack clamped = byPiece(
      [](NativePack gs, NativePack last) {
        const NativePack low = gs >= 0 ? gs : NativePack{};  // a NaN fails g >= 0: cell 0
        return low > last ? last : low;
      },
      g, lastCell);
  const Pack cell = floorPack(clamped);
  return {cell, g - cell};
}
JELLO_PACK_INLINE Pack lerpPack(Pack a, Pack b, Pack t) {
  return byPiece([](NativePack as, NativePack bs, NativePack ts) { return lerpValue(as, bs, ts); },
                 a, b, t);
}
// Padded nodes a and b side by side: (x y z 0) of a in lanes 0-3, of b in lanes 4-7.
JELLO_PACK_INLINE Pack twoNodes(const double* a, const double* b) {
#ifdef JELLO_PACK_ONE_REGISTER
  {
    typedef double NodePack __attribute__((vector_size(kPaddedNode * sizeof(double))));
    NodePack na, nb;
    std::memcpy(&na, a, sizeof na);
    std::memcpy(&nb, b, sizeof nb);
    Pack out;
    out.piece[0] = __builtin_shufflevector(na, nb, 0, 1, 2, 3, 4, 5, 6, 7);
    return out;
  }
#else  // a node is one piece or more
  Pack out;
  for (int c = 0; c < kPackPieces; ++c) {
    const int lane = c * kNativeLanes;
    std::memcpy(&out.piece[c], lane < kPaddedNode ? a + lane : b + lane - kPaddedNode,
                sizeof(NativePack));
  }
  return out;
#endif
}
// Lane kPoint's value in lanes 0-3, lane kPoint + 1's in lanes 4-7.
template <int kPoint>
JELLO_PACK_INLINE Pack pairOf(const Pack& t) {
  Pack out;
#ifdef JELLO_PACK_ONE_REGISTER
  out.piece[0] = __builtin_shufflevector(t.piece[0], t.piece[0], kPoint, kPoint, kPoint, kPoint,
                                         kPoint + 1, kPoint + 1, kPoint + 1, kPoint + 1);
#else
  for (int c = 0; c < kPackPieces; ++c)
    out.piece[c] = NativePack{} + t.lane(c * kNativeLanes < kPaddedNode ? kPoint : kPoint + 1);
#endif
  return out;
}

// The 8 points' cells: the offset of each cell's first node in the padded nodes, and the
// positions within the cells along each axis.
struct PackCorners {
  Pack node;  // whole numbers
  Pack t[3];
};
// trilinear() of points kPoint and kPoint + 1: (x y z 0) of each, side by side.
template <int kPoint>
JELLO_PACK_INLINE Pack interpolatePair(const double* nodes, int r, const PackCorners& c) {
  const std::ptrdiff_t dk = kPaddedNode, dj = dk * r, di = dj * r;
  const double* a = nodes + static_cast<std::ptrdiff_t>(c.node.lane(kPoint));
  const double* b = nodes + static_cast<std::ptrdiff_t>(c.node.lane(kPoint + 1));
  auto node = [a, b](std::ptrdiff_t offset) { return twoNodes(a + offset, b + offset); };
  const Pack tx = pairOf<kPoint>(c.t[0]), ty = pairOf<kPoint>(c.t[1]), tz = pairOf<kPoint>(c.t[2]);
  const Pack c00 = lerpPack(node(0), node(dk), tz), c01 = lerpPack(node(dj), node(dj + dk), tz);
  const Pack c10 = lerpPack(node(di), node(di + dk), tz),
             c11 = lerpPack(node(di + dj), node(di + dj + dk), tz);
  return lerpPack(lerpPack(c00, c01, ty), lerpPack(c10, c11, ty), tx);
}

struct PackVec3 {
  Pack axis[3];
};
// (x y z 0 x y z 0) of the 4 pairs of points into the x, y and z of the 8 points.
JELLO_PACK_INLINE PackVec3 transposePairs(const Pack& v0, const Pack& v1, const Pack& v2,
                                          const Pack& v3) {
  PackVec3 out;
#ifdef JELLO_PACK_ONE_REGISTER
  const NativePack a = v0.piece[0], b = v1.piece[0], c = v2.piece[0], d = v3.piece[0];
  const NativePack xy01 = __builtin_shufflevector(a, b, 0, 4, 8, 12, 1, 5, 9, 13),
                   xy23 = __builtin_shufflevector(c, d, 0, 4, 8, 12, 1, 5, 9, 13),
                   z01 = __builtin_shufflevector(a, b, 2, 6, 10, 14, 3, 7, 11, 15),
                   z23 = __builtin_shufflevector(c, d, 2, 6, 10, 14, 3, 7, 11, 15);
  out.axis[0].piece[0] = __builtin_shufflevector(xy01, xy23, 0, 1, 2, 3, 8, 9, 10, 11);
  out.axis[1].piece[0] = __builtin_shufflevector(xy01, xy23, 4, 5, 6, 7, 12, 13, 14, 15);
  out.axis[2].piece[0] = __builtin_shufflevector(z01, z23, 0, 1, 2, 3, 8, 9, 10, 11);
#else  // through memory: lane l of axis a is lane (l % 2) * 4 + a of pair l / 2
  double pairs[4 * kPackLanes];
  storePack(pairs, v0);
  storePack(pairs + kPackLanes, v1);
  storePack(pairs + 2 * kPackLanes, v2);
  storePack(pairs + 3 * kPackLanes, v3);
  for (int a = 0; a < 3; ++a)
    for (int l = 0; l < kPackLanes; ++l)
      out.axis[a].setLane(l, pairs[(l / 2) * kPackLanes + (l % 2) * kPaddedNode + a]);
#endif
  return out;
}

// The field at points q .. q + 7 by axis, interpolated whether inside the box or not.
JELLO_PACK_INLINE PackVec3 interpolate8(const double* nodes, int r, const double* p, int n, int q) {
  const Pack perMetre = splat(cellsPerMetre(r)), lastCell = splat(r - 2);
  PackCells cells[3];
  for (int a = 0; a < 3; ++a) cells[a] = cellsOf(loadPack(p + a * n + q), perMetre, lastCell);
  // The first node's offset, a whole number below 2^53: exact in doubles.
  const Pack node = ((cells[0].cell * r + cells[1].cell) * r + cells[2].cell) * kPaddedNode;
  const PackCorners c = {node, {cells[0].t, cells[1].t, cells[2].t}};
  const Pack v0 = interpolatePair<0>(nodes, r, c), v1 = interpolatePair<2>(nodes, r, c),
             v2 = interpolatePair<4>(nodes, r, c), v3 = interpolatePair<6>(nodes, r, c);
  return transposePairs(v0, v1, v2, v3);
}

// f where insideBox() of the point (x, y, z) (walls included), 0 elsewhere, lane by lane.
JELLO_PACK_INLINE Pack insideOrZero(Pack x, Pack y, Pack z, Pack f) {
  return byPiece(
      [](NativePack xs, NativePack ys, NativePack zs, NativePack fs) {
        const auto in = (xs <= kBoxHalfSize) & (xs >= -kBoxHalfSize) & (ys <= kBoxHalfSize) &
                        (ys >= -kBoxHalfSize) & (zs <= kBoxHalfSize) & (zs >= -kBoxHalfSize);
        return in ? fs : NativePack{};  // a NaN fails every comparison: outside
      },
      x, y, z, f);
}
// Adds the padded field at every point; kAllInside: every point is inside the box (the common
// case, without the per-point test).
template <bool kAllInside>
void addPaddedField(const double* nodes, int r, int end, int n, int q, const double* p,
                    double* force) {
  for (; q < end; q += kPackLanes) {
    const PackVec3 f = interpolate8(nodes, r, p, n, q);
    for (int a = 0; a < 3; ++a) {
      double* out = force + a * n + q;
      const Pack x = loadPack(p + q), y = loadPack(p + n + q), z = loadPack(p + 2 * n + q);
      storePack(out, loadPack(out) + (kAllInside ? f.axis[a] : insideOrZero(x, y, z, f.axis[a])));
    }
  }
}
}  // namespace

void FieldTerm::addForcesOn(PointRange points, const double* p, const double*, const Bounds* box,
                            double* force) const {
  const bool inside = allInside(box);
  switch (method_) {
    case Method::Uniform:
      if (inside) {  // the common case, without the per-point test
        for (int q = points.begin; q < points.end; ++q) addAt(force, q, uniform_);
        return;
      }
      for (int q = points.begin; q < points.end; ++q)
        addAt(force, q, (insideBox(at(p, q)) ? uniform_ : Vec3{}));
      return;
    case Method::Padded: {
      // A body whose count is not a multiple of 8 takes its last points one by one, through the
      // reference interpolation, which rounds as the packed one does (test_kernels).
      const int n = pointCount(), packed = groupedEnd(points, kPackLanes);
      if (inside)
        addPaddedField<true>(padded_.data(), field_.resolution, packed, n, points.begin, p, force);
      else
        addPaddedField<false>(padded_.data(), field_.resolution, packed, n, points.begin, p, force);
      for (int q = packed; q < points.end; ++q)
        addAt(force, q, referenceForce(field_.forces, field_.resolution, at(p, q)));
      return;
    }
    case Method::Reference:
      for (int q = points.begin; q < points.end; ++q)
        addAt(force, q, referenceForce(field_.forces, field_.resolution, at(p, q)));
      return;
  }
}

void FieldTerm::addJacobian(const double* p, const double*, JacobianSink* sink) const {
  const Block3 none;
  for (int q = 0; q < pointCount(); ++q)
    sink->addPoint(q, gradientAt(field_.forces, field_.resolution, at(p, q)), none);
}

void FieldTerm::summarise(std::vector<std::string>* kept, std::vector<std::string>*) const {
  switch (method_) {
    case Method::Uniform:
      kept->push_back("field (uniform: a constant, no interpolation)");
      return;
    case Method::Padded:
    case Method::Reference:
      kept->push_back("field (trilinear, " + std::to_string(field_.resolution) + "^3 nodes)");
      return;
  }
}

std::vector<TermLine> FieldTerm::describe(const double*) const {
  if (field_.resolution == 0) return {{"field", "none"}};
  const FieldShape shape = classifyField(field_);
  std::string text = textf("R = %d, %s", field_.resolution, fieldKindName(shape.kind));
  switch (shape.kind) {
    case FieldKind::Uniform: {
      // The acceleration too: a user thinking of g (9.8 m/s^2) writes it as a force by mistake.
      const Vec3 a{shape.uniform.x / mass_, shape.uniform.y / mass_, shape.uniform.z / mass_};
      text += textf(" F = (%.6g, %.6g, %.6g) N, a = F/m = (%.6g, %.6g, %.6g) m/s^2",
                    shape.uniform.x, shape.uniform.y, shape.uniform.z, a.x, a.y, a.z);
      break;
    }
    case FieldKind::Swirl:
      text += textf(" about z, F = %.6g (-y, x, 0) N", shape.strength);
      break;
    case FieldKind::Radial:
      text += textf(", F = %.6g (x, y, z) N", shape.strength);
      break;
    case FieldKind::Zero:
    case FieldKind::General:
      break;
  }
  if (shape.kind != FieldKind::Zero && shape.kind != FieldKind::Uniform)
    text += textf("; |F| from %.6g to %.6g N (|a| up to %.6g m/s^2)", shape.smallest, shape.largest,
                  shape.largest / mass_);
  return {{"field", text}};
}

double fieldNodeCoordinate(int index, int resolution) {
  return -kBoxHalfSize + 2 * kBoxHalfSize * index / (resolution - 1);
}

const char* fieldKindName(FieldKind kind) {
  switch (kind) {
    case FieldKind::Zero:
      return "zero";
    case FieldKind::Uniform:
      return "uniform";
    case FieldKind::Swirl:
      return "swirl";
    case FieldKind::Radial:
      return "radial";
    case FieldKind::General:
      return "general";
  }
  return "general";  // not reached: every kind is named above
}

namespace {

// The course's files hold six decimals: a value is "the same" within half of their last digit,
// plus a little for the rounding of the node coordinates themselves.
constexpr double kFileRounding = 1e-6;

Vec3 nodePosition(std::size_t node, int r) {
  std::size_t i = node / (static_cast<std::size_t>(r) * r), j = (node / r) % r, k = node % r;
  return {fieldNodeCoordinate(static_cast<int>(i), r), fieldNodeCoordinate(static_cast<int>(j), r),
          fieldNodeCoordinate(static_cast<int>(k), r)};
}

// Least-squares s of F ~ s * pattern(p) over the nodes, and whether every node fits.
bool fitsPattern(FieldView field, Vec3 (*pattern)(Vec3), double* strength) {
  const int r = field.resolution;
  const std::size_t nodes = field.nodes();
  double num = 0, den = 0;
  for (std::size_t node = 0; node < nodes; ++node) {
    Vec3 g = pattern(nodePosition(node, r)), f = field.node(node);
    num += dot(f, g);
    den += dot(g, g);
  }
  if (den == 0) return false;
  *strength = num / den;
  for (std::size_t node = 0; node < nodes; ++node) {
    Vec3 g = pattern(nodePosition(node, r)), f = field.node(node);
    Vec3 misfit = f - *strength * g;
    if (std::max({std::fabs(misfit.x), std::fabs(misfit.y), std::fabs(misfit.z)}) > kFileRounding)
      return false;
  }
  return true;
}

Vec3 swirl(Vec3 p) { return {-p.y, p.x, 0}; }
Vec3 radial(Vec3 p) { return p; }

}  // namespace

FieldShape classifyField(FieldView field) {
  FieldShape shape;
  const std::size_t nodes = field.nodes();
  if (nodes == 0) return shape;
  shape.smallest = INFINITY;
  for (std::size_t node = 0; node < nodes; ++node) {
    double magnitude = length(field.node(node));
    shape.smallest = std::min(shape.smallest, magnitude);
    shape.largest = std::max(shape.largest, magnitude);
  }
  const FieldUse use = fieldUse(field);  // the exact zero and uniform tests, as the kernel's
  if (use == FieldUse::Zero) return shape;
  if (use == FieldUse::Uniform) {
    shape.kind = FieldKind::Uniform;
    shape.uniform = field.node(0);
    return shape;
  }
  if (field.resolution >= 2) {
    for (auto [pattern, kind] :
         {std::pair{&swirl, FieldKind::Swirl}, std::pair{&radial, FieldKind::Radial}})
      if (fitsPattern(field, pattern, &shape.strength)) {
        shape.kind = kind;
        return shape;
      }
  }
  shape.kind = FieldKind::General;
  return shape;
}

}  // namespace jello
