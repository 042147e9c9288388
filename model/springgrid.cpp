// model/springgrid.cpp: the spring kernel of grid bodies (springgrid.h): its layout, its pass
// through the units, and the window a body of voxels is copied onto.

#include "model/springgrid.h"

#include <algorithm>
#include <cstring>
#include <functional>
#include <utility>

#include "core/assert.h"
#include "model/pack.h"

namespace jello {

namespace {

typedef NativePack Lanes;
constexpr int kLanes = kNativeLanes;
constexpr int kOffsets = static_cast<int>(kSpringOffsets.size());
typedef long long LaneBits __attribute__((vector_size(kLanes * sizeof(double))));
static_assert(sizeof(LaneBits) == sizeof(Lanes) && kLanes <= 8, "a unit's keep bits fit a byte");

// What a unit checks before it reads: nothing (the unit and its farthest neighbours are within
// the arrays), the far ends of its springs, or everything (a unit at the call's first or last
// node, or past the arrays' end).
constexpr int kNone = 0, kFar = 1, kAll = 2;

// One unit's slot forces, by axis.
struct Slots {
  Lanes axis[3];
};

// What every unit of a call shares. Node arrays: node q (numbered from the call's first node) of
// axis a at [a * stride + q]; nodes [0, limit) may be read, the forces of nodes [begin, end)
// are added to.
struct Pass {
  const double* p;
  const double* v;
  double* force;
  int stride, limit, begin, end;
  int farthest;  // the largest delta: a unit from q + farthest + kLanes <= limit on reads no guard
  const std::uint8_t* keep;  // the call's first unit's bytes
  const OffsetConstants* c;
  const int* delta;
  const int* ringUnits;
  const int* ringFirst;
  const bool* present;
  double* rings;
  int* at;  // each offset's ring unit for the unit being computed
};

JELLO_PACK_INLINE Lanes loadLanes(const double* a) {
  Lanes out;
  std::memcpy(&out, a, sizeof out);
  return out;
}
JELLO_PACK_INLINE void storeLanes(double* a, const Lanes& x) { std::memcpy(a, &x, sizeof x); }
// The lanes of nodes [first, first + kLanes) that lie in [from, to); the others read 0.
JELLO_PACK_INLINE Lanes loadWithin(const double* axis, int first, int from, int to) {
  Lanes out = {};
  for (int l = 0; l < kLanes; ++l)
    if (first + l >= from && first + l < to) out[l] = axis[first + l];
  return out;
}

// -1 in the lanes whose bit is set, 0 in the others.
JELLO_PACK_INLINE LaneBits laneMask(unsigned bits) {
  LaneBits lane;
  for (int l = 0; l < kLanes; ++l) lane[l] = 1LL << l;
  return ((LaneBits{} + static_cast<long long>(bits)) & lane) != 0;
}

// A unit's own positions and velocities, loaded once for its 16 offsets.
struct Own {
  Lanes p[3], v[3];
};
template <bool kDampers, int kCheck>
JELLO_PACK_INLINE Own ownLanes(const Pass& s, int q) {
  Own own;
  for (int a = 0; a < 3; ++a) {
    const double *pa = s.p + a * s.stride, *va = s.v + a * s.stride;
    own.p[a] = kCheck == kAll ? loadWithin(pa, q, 0, s.limit) : loadLanes(pa + q);
    if constexpr (kDampers)
      own.v[a] = kCheck == kAll ? loadWithin(va, q, 0, s.limit) : loadLanes(va + q);
  }
  return own;
}

// The unit from node q's slots of one offset: springForce() lane by lane, as a single spring's is
// computed; 0 in the lanes whose spring does not exist.
template <int kOffset, bool kDampers, int kCheck>
JELLO_PACK_INLINE Slots slotForces(const Pass& s, const Own& own, int q, unsigned keep) {
  const int far = q + s.delta[kOffset];
  const bool pastEnd = kCheck != kNone && far + kLanes > s.limit;
  Lanes L[3], w[3];
  for (int a = 0; a < 3; ++a) {
    const double *pa = s.p + a * s.stride, *va = s.v + a * s.stride;
    L[a] = own.p[a] - (pastEnd ? loadWithin(pa, far, 0, s.limit) : loadLanes(pa + far));
    if constexpr (kDampers)
      w[a] = own.v[a] - (pastEnd ? loadWithin(va, far, 0, s.limit) : loadLanes(va + far));
  }
  // direction(): |L| and L/|L|, zero for a zero L (a select: the lanes go on together).
  Lanes len = (L[0] * L[0] + L[1] * L[1]) + L[2] * L[2];
  for (int l = 0; l < kLanes; ++l) len[l] = __builtin_sqrt(len[l]);  // one vector square root
  const Lanes inverse = len != 0 ? 1.0 / len : Lanes{};
  const Lanes u[3] = {inverse * L[0], inverse * L[1], inverse * L[2]};
  Lanes tension = s.c->minusK[kOffset] * (len - s.c->rest[kOffset]);
  if constexpr (kDampers)
    tension = tension + s.c->minusD[kOffset] * ((w[0] * u[0] + w[1] * u[1]) + w[2] * u[2]);
  if (keep != (1u << kLanes) - 1) tension = laneMask(keep) ? tension : Lanes{};
  return {{tension * u[0], tension * u[1], tension * u[2]}};
}

// The offset's ring: each axis holds ringUnits + 1 units, the last a copy of the first, so that
// the kLanes slots ending at a unit's nodes (from the ring unit after the current one on) are one
// load.
JELLO_PACK_INLINE double* ringAxis(const Pass& s, int o, int axis) {
  return s.rings + s.ringFirst[o] + axis * (s.ringUnits[o] + 1) * kLanes;
}
JELLO_PACK_INLINE void putInRing(const Pass& s, int o, const Slots& out) {
  const int at = s.at[o];
  for (int a = 0; a < 3; ++a) {
    double* ring = ringAxis(s, o, a);
    storeLanes(ring + at * kLanes, out.axis[a]);
    if (at == 0) storeLanes(ring + s.ringUnits[o] * kLanes, out.axis[a]);
  }
}
JELLO_PACK_INLINE void nextRingUnit(const Pass& s, int o) {
  s.at[o] = s.at[o] + 1 == s.ringUnits[o] ? 0 : s.at[o] + 1;
}

// One offset's part of a unit's total: its slots go into the ring, and the slots of the springs
// ending at the unit's nodes (delta nodes back) come out of it.
template <int kOffset, bool kDampers, int kCheck>
JELLO_PACK_INLINE void addOffset(const Pass& s, const Own& own, int q, unsigned keep,
                                 Slots* total) {
  if (!s.present[kOffset]) return;
  const Slots out = keep ? slotForces<kOffset, kDampers, kCheck>(s, own, q, keep) : Slots{};
  putInRing(s, kOffset, out);
  constexpr SpringOffset offset = kSpringOffsets[kOffset];
  if constexpr (offset.di == 0 && offset.dj == 0) {
    // Along k the delta is dk whatever the grid, at most a unit: the slots ending here are the
    // last lanes of the unit before and the first of this one, shifted together in registers.
    constexpr int delta = offset.dk, lanesOn = delta % kLanes;
    static_assert(delta <= kLanes);
    const int at = s.at[kOffset], before = at == 0 ? s.ringUnits[kOffset] - 1 : at - 1;
    for (int a = 0; a < 3; ++a) {
      const Lanes previous = loadLanes(ringAxis(s, kOffset, a) + before * kLanes);
      Lanes ending = previous;
      if constexpr (lanesOn != 0) ending = nativeLanesFrom<kLanes - lanesOn>(previous, out.axis[a]);
      total->axis[a] = (total->axis[a] - ending) + out.axis[a];
    }
  } else {
    // Node q - delta: lanesOn lanes from the end of the ring unit after this one, and on into the
    // next (one load across the two: measured a little faster than two loads shifted together).
    const int lanesOn = s.delta[kOffset] % kLanes;
    const int after = s.at[kOffset] + 1 == s.ringUnits[kOffset] ? 0 : s.at[kOffset] + 1;
    for (int a = 0; a < 3; ++a) {
      const double* ring = ringAxis(s, kOffset, a) + after * kLanes;
      const Lanes ending = loadLanes(ring + kLanes - lanesOn);
      total->axis[a] = (total->axis[a] - ending) + out.axis[a];
    }
  }
  nextRingUnit(s, kOffset);
}

template <bool kDampers, int kCheck, int... kOffset>
JELLO_PACK_INLINE void addUnit(std::integer_sequence<int, kOffset...>, const Pass& s, int unit) {
  const int q = unit * kLanes;
  const std::uint8_t* keep = s.keep + unit * kOffsets;
  Slots total;
  for (int a = 0; a < 3; ++a) {
    double* axis = s.force + a * s.stride;
    total.axis[a] = kCheck == kAll ? loadWithin(axis, q, s.begin, s.end) : loadLanes(axis + q);
  }
  const Own own = ownLanes<kDampers, kCheck>(s, q);
  (addOffset<kOffset, kDampers, kCheck>(s, own, q, keep[kOffset], &total), ...);
  for (int a = 0; a < 3; ++a) {
    double* axis = s.force + a * s.stride;
    if (kCheck != kAll) {
      storeLanes(axis + q, total.axis[a]);
      continue;
    }
    for (int l = 0; l < kLanes; ++l)
      if (q + l >= s.begin && q + l < s.end) axis[q + l] = total.axis[a][l];
  }
}

// A unit before the call's nodes: the slots of the offsets whose springs from it end in them go
// into their rings (computed again: the sums are those of the whole grid's pass).
template <bool kDampers, int... kOffset>
JELLO_PACK_INLINE void warmUnit(std::integer_sequence<int, kOffset...>, const Pass& s, int unit,
                                int firstUnit, const int* unitsBack) {
  const std::uint8_t* keep = s.keep + unit * kOffsets;
  auto warm = [&](auto offset) {
    constexpr int o = decltype(offset)::value;
    if (!s.present[o]) return;
    if (unit >= firstUnit - unitsBack[o]) {
      const unsigned bits = keep[o];
      const int q = unit * kLanes;
      putInRing(s, o,
                bits ? slotForces<o, kDampers, kFar>(s, ownLanes<kDampers, kNone>(s, q), q, bits)
                     : Slots{});
    }
    nextRingUnit(s, o);
  };
  (warm(std::integral_constant<int, kOffset>{}), ...);
}

template <bool kDampers>
void pass(const Pass& s, int warm, int begin, int end, const int* unitsBack) {
  constexpr auto offsets = std::make_integer_sequence<int, kOffsets>{};
  for (int unit = warm; unit < begin; ++unit)
    warmUnit<kDampers>(offsets, s, unit, begin, unitsBack);
  for (int unit = begin; unit < end; ++unit) {
    const int q = unit * kLanes;
    if (q < s.begin || q + kLanes > s.end || q + kLanes > s.limit)
      addUnit<kDampers, kAll>(offsets, s, unit);
    else if (q + s.farthest + kLanes > s.limit)
      addUnit<kDampers, kFar>(offsets, s, unit);
    else
      addUnit<kDampers, kNone>(offsets, s, unit);
  }
}

// Each thread's scratch, grown once: the rings, and a body of voxels' window.
struct Scratch {
  std::vector<Lanes> rings;  // aligned as a vector register
  std::vector<double> window;
};
Scratch& scratch() {
  thread_local Scratch s;
  return s;
}

// The call's units: warm-up [warm, begin), its own [begin, end).
void runPass(Pass s, int warm, int begin, int end, const int* unitsBack, int ringDoubles,
             bool dampers) {
  std::vector<Lanes>& rings = scratch().rings;
  const std::size_t units = ringDoubles / kLanes;
  if (rings.size() < units) rings.resize(units);
  std::fill(rings.begin(), rings.begin() + units, Lanes{});  // units before the first hold 0
  s.rings = reinterpret_cast<double*>(rings.data());
  int at[kOffsets];
  for (int o = 0; o < kOffsets; ++o) at[o] = s.present[o] ? warm % s.ringUnits[o] : 0;
  s.at = at;
  if (dampers)
    pass<true>(s, warm, begin, end, unitsBack);
  else
    pass<false>(s, warm, begin, end, unitsBack);
}

}  // namespace

namespace {

// The offset (its place in kSpringOffsets) from grid index a to grid index b, or -1.
int offsetBetween(const std::array<int, 3>& a, const std::array<int, 3>& b) {
  for (int o = 0; o < kOffsets; ++o) {
    const SpringOffset& offset = kSpringOffsets[o];
    if (b[0] - a[0] == offset.di && b[1] - a[1] == offset.dj && b[2] - a[2] == offset.dk) return o;
  }
  return -1;
}

}  // namespace

SpringGrid::SpringGrid(const Body& body) : points_(body.count()) {
  if (body.springs.empty()) return;  // nothing to compute (a jelly of elements)
  if (body.joined() || body.gridless() ||
      !std::is_sorted(body.nodeOf.begin(), body.nodeOf.end(), std::less_equal<int>())) {
    represents_ = false;  // the kernel takes points in node order, node q of a lattice point q
    return;
  }
  nodes_ = body.nx * body.ny * body.nz;
  compact_ = points_ == nodes_;
  const int units = (nodes_ + kLanes - 1) / kLanes;
  keep_.assign(std::size_t(units) * kOffsets, 0);
  // The springs as the kernel sums them: grouped by offset in table order, each group in the
  // order of its ends a, each of its offset's rest length. Else the spring list computes them.
  int last = -1, lastA = -1;
  for (const Spring& spring : body.springs) {
    const int o = offsetBetween(body.index(spring.a), body.index(spring.b));
    if (o < 0 || o < last || (o == last && spring.a <= lastA) || spring.part != 0 ||
        spring.rest != restLength(kSpringOffsets[o], body.spacing)) {
      represents_ = false;
      return;
    }
    last = o, lastA = spring.a;
    const int node = body.nodeOf[spring.a];
    keep_[std::size_t(node / kLanes) * kOffsets + o] |= std::uint8_t(1u << (node % kLanes));
    present_[o] = true;
  }
  for (int o = 0; o < kOffsets; ++o) {
    if (!present_[o]) continue;
    const SpringOffset& offset = kSpringOffsets[o];
    delta_[o] = (offset.di * body.ny + offset.dj) * body.nz + offset.dk;
    // A spring's far end has a higher number (di, then dj, then dk the first nonzero positive).
    JELLO_ASSERT(delta_[o] > 0);
    ringUnits_[o] = delta_[o] / kLanes + 2;
    ringFirst_[o] = ringDoubles_;
    ringDoubles_ += 3 * (ringUnits_[o] + 1) * kLanes;
    unitsBack_[o] = delta_[o] / kLanes + (delta_[o] % kLanes != 0);
    reachUnits_ = std::max(reachUnits_, unitsBack_[o]);
    farthest_ = std::max(farthest_, delta_[o]);
  }
  if (!compact_) nodeOf_ = body.nodeOf;
}

SpringGrid::Span SpringGrid::unitsFor(int nodeBegin, int nodeEnd) const {
  const int begin = nodeBegin / kLanes, end = (nodeEnd + kLanes - 1) / kLanes;
  return {std::max(0, begin - reachUnits_), begin, end};
}

long long SpringGrid::warmUpSlots() const {
  long long slots = 0;
  for (int o = 0; o < kOffsets; ++o) slots += present_[o] ? unitsBack_[o] * kLanes : 0;
  return slots;
}

long long SpringGrid::slotsFor(PointRange points) const {
  if (keep_.empty()) return 0;
  long long slots = 0;
  int last = -1;
  for (int q = points.begin; q < points.end; ++q) {
    const int unit = (compact_ ? q : nodeOf_[q]) / kLanes;
    if (unit == last) continue;
    last = unit;
    for (int o = 0; o < kOffsets; ++o)
      slots += keep_[std::size_t(unit) * kOffsets + o] ? kLanes : 0;
  }
  return slots;
}

void SpringGrid::addForces(PointRange points, const BodyArrays& arrays, const OffsetConstants& c,
                           bool dampers) const {
  JELLO_ASSERT(represents_);
  JELLO_ASSERT(0 <= points.begin && points.begin <= points.end && points.end <= points_);
  if (points.begin >= points.end || keep_.empty()) return;
  if (!compact_) return addOnWindow(points, arrays, c, dampers);
  const Span span = unitsFor(points.begin, points.end);
  Pass s{arrays.p,      arrays.v,          arrays.force,      arrays.stride,   points_,
         points.begin,  points.end,        farthest_,         keep_.data(),    &c,
         delta_.data(), ringUnits_.data(), ringFirst_.data(), present_.data(), nullptr,
         nullptr};
  runPass(s, span.warm, span.begin, span.end, unitsBack_.data(), ringDoubles_, dampers);
}

// A body of voxels: the nodes the call reads, from its first warm-up unit to its last unit's
// farthest neighbour, copied onto a window of the grid (0 where there is no point, and past the
// grid), the forces of its points in the range too; the kernel adds to the window's forces, which
// go back to the points.
void SpringGrid::addOnWindow(PointRange points, const BodyArrays& arrays, const OffsetConstants& c,
                             bool dampers) const {
  const int nodeBegin = nodeOf_[points.begin], nodeEnd = nodeOf_[points.end - 1] + 1;
  const Span whole = unitsFor(nodeBegin, nodeEnd);
  const int first = whole.warm * kLanes;  // the window's first node, a unit's first
  const int length = (whole.end - whole.warm) * kLanes + farthest_ + kLanes;
  std::vector<double>& window = scratch().window;
  if (window.size() < std::size_t(9 * length)) window.resize(9 * std::size_t(length));
  double* p = window.data();
  double* v = p + 3 * length;
  double* force = v + 3 * length;
  std::fill(window.begin(), window.begin() + 9 * std::size_t(length), 0.0);
  // The points on the window: their nodes ascend with them.
  const int firstPoint =
      static_cast<int>(std::lower_bound(nodeOf_.begin(), nodeOf_.end(), first) - nodeOf_.begin());
  const int endPoint = static_cast<int>(
      std::lower_bound(nodeOf_.begin(), nodeOf_.end(), first + length) - nodeOf_.begin());
  for (int a = 0; a < 3; ++a) {
    const int from = a * arrays.stride, to = a * length - first;
    for (int q = firstPoint; q < endPoint; ++q) {
      p[to + nodeOf_[q]] = arrays.p[from + q];
      v[to + nodeOf_[q]] = arrays.v[from + q];
    }
    for (int q = points.begin; q < points.end; ++q) force[to + nodeOf_[q]] = arrays.force[from + q];
  }
  Pass s{p,
         v,
         force,
         length,
         length,
         nodeBegin - first,
         nodeEnd - first,
         farthest_,
         keep_.data() + std::size_t(whole.warm) * kOffsets,
         &c,
         delta_.data(),
         ringUnits_.data(),
         ringFirst_.data(),
         present_.data(),
         nullptr,
         nullptr};
  runPass(s, 0, whole.begin - whole.warm, whole.end - whole.warm, unitsBack_.data(), ringDoubles_,
          dampers);
  for (int a = 0; a < 3; ++a)
    for (int q = points.begin; q < points.end; ++q)
      arrays.force[a * arrays.stride + q] = force[a * length + nodeOf_[q] - first];
}

}  // namespace jello
