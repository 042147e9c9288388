// model/springs.cpp: the lattice's springs: the spring list, the force kernel, Jacobian, energy
// and description.

#include "model/springs.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>

#include "core/assert.h"
#include "model/pack.h"

namespace jello {

const std::vector<Spring>& buildSprings() { return courseBody().springs; }

void springJacobian(Vec3 L, Vec3 relVel, double k, double d, double rest, Block3* dFdL,
                    Block3* dFdw) {
  double len;
  const Vec3 unit = direction(L, &len);
  *dFdL = Block3{};
  *dFdw = Block3{};
  if (len == 0) return;
  const double u[3] = {unit.x, unit.y, unit.z}, w[3] = {relVel.x, relVel.y, relVel.z};
  double uu[9], P[9], Pw[3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      uu[3 * i + j] = u[i] * u[j];
      P[3 * i + j] = (i == j ? 1.0 : 0.0) - uu[3 * i + j];
    }
  // P w summed as this Jacobian was summed when Eigen computed it (its SSE2 product adds rows 0
  // and 1 left to right, row 2 right to left), so that IMPLICIT's results stay bit for bit.
  for (int i = 0; i < 2; ++i) Pw[i] = (P[3 * i] * w[0] + P[3 * i + 1] * w[1]) + P[3 * i + 2] * w[2];
  Pw[2] = P[6] * w[0] + (P[7] * w[1] + P[8] * w[2]);
  const double uw = u[0] * w[0] + u[1] * w[1] + u[2] * w[2];
  const double bend = 1 - rest / len, damping = d / len;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int e = 3 * i + j;
      dFdL->m[e] = -k * (uu[e] + bend * P[e]) - damping * (u[i] * Pw[j] + uw * P[e]);
      dFdw->m[e] = -d * uu[e];
    }
}

namespace {

// The force kernel. It goes through the points a unit at a time (kNativeLanes points along k in
// one lattice row: a whole row with AVX-512, half a row with AVX, a quarter with SSE2; one vector
// register each), and for each unit through the 16 offsets in table order, keeping the unit's
// total force in registers: for each offset it computes the unit's slots (the springs from its
// points a to their points b = a + delta) and adds, lane by lane, (total - in) + out. `out` is
// the force of the spring starting at the point, `in` that of the spring ending at it, which
// started delta points earlier: a slot of an earlier unit, which the kernel kept in a small ring
// of that offset's recent units. That is docs/physics.md's order of summation, so the sums round
// exactly as a loop over single springs would. Each offset is a template argument: its delta,
// its ring and its kept lanes are constants, and the 16 offsets unroll into one loop body.
// (Units of a whole row with AVX and SSE2 too ran 2 times slower than the kernel before this
// one: their totals and positions did not fit in the 16 registers.)
typedef NativePack Lanes;
constexpr int kLanes = kNativeLanes;
constexpr int kUnitsPerRow = kLatticeSize / kLanes;
constexpr int kOffsets = static_cast<int>(kSpringOffsets.size());

// A spring of an offset ends `delta` points further on: unitsOn whole units and lanesOn lanes.
// The springs ending in unit u start in units u - unitsOn - 1 and u - unitsOn: the offset's ring
// keeps the slots of its last unitsOn + 2 units, unit u at u % ringUnits.
constexpr int ringUnits(int offset) { return springDelta(kSpringOffsets[offset]) / kLanes + 2; }
constexpr int ringStart(int offset) {
  return offset == 0 ? 0 : ringStart(offset - 1) + ringUnits(offset - 1);
}
constexpr int kRingUnits = ringStart(kOffsets);  // 23 KB with AVX-512: the rings stay in L1

// One unit's slot forces, by axis.
struct UnitForce {
  Lanes axis[3];
};

JELLO_PACK_INLINE Lanes loadLanes(const double* a) {
  Lanes out;
  std::memcpy(&out, a, sizeof out);
  return out;
}
// The doubles of one axis from point `first` on, where some lie past the last point (the far
// ends of slots the kernel discards, in the last rows): those lanes read 0, not past the array.
JELLO_PACK_INLINE Lanes loadUpToEnd(const double* axis, int first) {
  Lanes out = {};
  for (int l = 0; first + l < kNumPoints; ++l) out[l] = axis[first + l];
  return out;
}

// 1 for the lanes of a unit kPhase units into its row whose spring exists, 0 for the slots the
// kernel discards.
template <int kOffset, int kPhase>
JELLO_PACK_INLINE Lanes keptLanes() {
  Lanes keep;
  for (int l = 0; l < kLanes; ++l)
    keep[l] = slotKept(kSpringOffsets[kOffset], kPhase * kLanes + l) ? 1.0 : 0.0;
  return keep;
}

// The inputs every unit and offset shares.
struct Inputs {
  const double* p;
  const double* v;
  double minusK, minusD;  // -kElastic, -dElastic
  const double* rests;    // m, by offset
};

// The slot forces of the unit from point q, kPhase units into its row, for one offset:
// springForce() lane by lane, times the lane's keep (1 or 0), as a single spring's is computed.
template <int kOffset, int kPhase, bool kDampers>
JELLO_PACK_INLINE UnitForce slotForces(const Inputs& in, int q) {
  constexpr SpringOffset o = kSpringOffsets[kOffset];
  constexpr int delta = springDelta(o);
  // Only a far end further along k can lie past the last point.
  const bool pastEnd = o.dk > 0 && q + delta + kLanes > kNumPoints;
  Lanes L[3], w[3];
  for (int a = 0; a < 3; ++a) {
    const double *pa = in.p + a * kNumPoints, *va = in.v + a * kNumPoints;
    L[a] = loadLanes(pa + q) - (pastEnd ? loadUpToEnd(pa, q + delta) : loadLanes(pa + q + delta));
    if constexpr (kDampers)
      w[a] = loadLanes(va + q) - (pastEnd ? loadUpToEnd(va, q + delta) : loadLanes(va + q + delta));
  }
  // direction(): |L| and L/|L|, zero for a zero L (a select: the lanes go on together).
  Lanes len = (L[0] * L[0] + L[1] * L[1]) + L[2] * L[2];
  for (int l = 0; l < kLanes; ++l) len[l] = __builtin_sqrt(len[l]);  // one vector square root
  const Lanes inverse = len != 0 ? 1.0 / len : Lanes{};
  const Lanes u[3] = {inverse * L[0], inverse * L[1], inverse * L[2]};
  Lanes tension = in.minusK * (len - in.rests[kOffset]);
  if constexpr (kDampers)
    tension = tension + in.minusD * ((w[0] * u[0] + w[1] * u[1]) + w[2] * u[2]);
  if constexpr (o.dk != 0) tension = keptLanes<kOffset, kPhase>() * tension;  // 1 * t is t
  UnitForce out = {{tension * u[0], tension * u[1], tension * u[2]}};
  // Slots whose far end is past the last point hold exactly 0, as they always have.
  if (pastEnd)
    for (int l = 0; l < kLanes; ++l)
      if (q + l + delta >= kNumPoints) out.axis[0][l] = out.axis[1][l] = out.axis[2][l] = 0.0;
  return out;
}

// The unit's slot forces for one offset: zero in a row without springs of the offset.
template <int kOffset, int kPhase, bool kDampers>
JELLO_PACK_INLINE UnitForce unitSlots(const Inputs& in, int unit) {
  return rowHasSprings(kSpringOffsets[kOffset], unit / kUnitsPerRow)
             ? slotForces<kOffset, kPhase, kDampers>(in, unit * kLanes)
             : UnitForce{};
}

// One offset's part of a unit's total: its slots go into the ring, and the forces of the springs
// ending at the unit's points come out of it: the slots lanesOn lanes from the end of unit -
// unitsOn - 1 on, into unit - unitsOn (this unit when unitsOn is 0). Units before the first hold
// no springs: zeros. Reading whole units and shifting lanes is faster than a load across two
// units, which may wait for both stores.
template <int kOffset, int kPhase, bool kDampers>
JELLO_PACK_INLINE void addOffset(const Inputs& in, int unit, UnitForce* rings, UnitForce* total) {
  constexpr int delta = springDelta(kSpringOffsets[kOffset]);
  constexpr int unitsOn = delta / kLanes, lanesOn = delta % kLanes, size = ringUnits(kOffset);
  UnitForce* ring = rings + ringStart(kOffset);
  const UnitForce out = unitSlots<kOffset, kPhase, kDampers>(in, unit);
  const int at = unit % size;
  ring[at] = out;
  // Units unit - unitsOn and unit - unitsOn - 1 are at + 2 and at + 1, modulo unitsOn + 2.
  const int nearAt = at + 2 >= size ? at + 2 - size : at + 2;
  const int farAt = at + 1 >= size ? at + 1 - size : at + 1;
  const bool nearExists = unit >= unitsOn, farExists = unit > unitsOn;
  for (int a = 0; a < 3; ++a) {
    Lanes ending = nearExists ? ring[nearAt].axis[a] : Lanes{};
    if constexpr (lanesOn != 0)
      ending = nativeLanesFrom<kLanes - lanesOn>(farExists ? ring[farAt].axis[a] : Lanes{}, ending);
    total->axis[a] = (total->axis[a] - ending) + out.axis[a];
  }
}

// How many units before a unit the springs ending in it start in, at most: unit - unitsOn, and
// unit - unitsOn - 1 too when the springs do not span whole units.
constexpr int unitsBack(int offset) {
  const int delta = springDelta(kSpringOffsets[offset]);
  return delta / kLanes + (delta % kLanes != 0);
}

// A unit before a range's first unit `first`: only the offset's slots whose springs end in the
// range (those of units first - unitsBack on) go into the ring, for the range's first units.
template <int kOffset, int kPhase, bool kDampers>
JELLO_PACK_INLINE void warmOffset(const Inputs& in, int unit, int first, UnitForce* rings) {
  if (unit < first - unitsBack(kOffset)) return;
  rings[ringStart(kOffset) + unit % ringUnits(kOffset)] =
      unitSlots<kOffset, kPhase, kDampers>(in, unit);
}

// How many units before a range the springs ending in it start in, at most, and their rows.
constexpr int reachUnits(int offset = 0) {
  return offset == kOffsets ? 0 : std::max(unitsBack(offset), reachUnits(offset + 1));
}
constexpr int kReachRows = (reachUnits() + kUnitsPerRow - 1) / kUnitsPerRow;

template <int kPhase, bool kDampers, int... kOffset>
JELLO_PACK_INLINE void addUnit(std::integer_sequence<int, kOffset...>, const Inputs& in, int unit,
                               UnitForce* rings, double* force) {
  const int q = unit * kLanes;
  UnitForce total;
  for (int a = 0; a < 3; ++a) total.axis[a] = loadLanes(force + a * kNumPoints + q);
  (addOffset<kOffset, kPhase, kDampers>(in, unit, rings, &total), ...);
  for (int a = 0; a < 3; ++a)
    std::memcpy(force + a * kNumPoints + q, &total.axis[a], sizeof(Lanes));
}

template <int kPhase, bool kDampers, int... kOffset>
JELLO_PACK_INLINE void warmUnit(std::integer_sequence<int, kOffset...>, const Inputs& in, int unit,
                                int first, UnitForce* rings) {
  (warmOffset<kOffset, kPhase, kDampers>(in, unit, first, rings), ...);
}

// A lattice row: its units in order, each knowing at compile time where in the row it lies.
template <bool kDampers, int... kPhase>
JELLO_PACK_INLINE void addRow(std::integer_sequence<int, kPhase...>, const Inputs& in, int row,
                              UnitForce* rings, double* force) {
  (addUnit<kPhase, kDampers>(std::make_integer_sequence<int, kOffsets>{}, in,
                             row * kUnitsPerRow + kPhase, rings, force),
   ...);
}

template <bool kDampers, int... kPhase>
void warmRow(std::integer_sequence<int, kPhase...>, const Inputs& in, int row, int first,
             UnitForce* rings) {
  (warmUnit<kPhase, kDampers>(std::make_integer_sequence<int, kOffsets>{}, in,
                              row * kUnitsPerRow + kPhase, first, rings),
   ...);
}

// The rows of `points`. A range after the first row first fills the rings from the kReachRows
// rows before it, whose springs end in it: the same slots, computed again, so the sums are
// those of the whole lattice's pass.
template <bool kDampers>
void addSpringForces(const Inputs& in, PointRange points, double* force) {
  UnitForce rings[kRingUnits];  // each ring unit is written before it is read
  constexpr auto phases = std::make_integer_sequence<int, kUnitsPerRow>{};
  const int firstRow = points.begin / kLatticeSize, endRow = points.end / kLatticeSize;
  for (int row = std::max(0, firstRow - kReachRows); row < firstRow; ++row)
    warmRow<kDampers>(phases, in, row, firstRow * kUnitsPerRow, rings);
  for (int row = firstRow; row < endRow; ++row) addRow<kDampers>(phases, in, row, rings, force);
}

}  // namespace

SpringTerm::SpringTerm(const Body& body, const SpringConstants& constants, bool dampers,
                       SpringKernel kernel)
    : SpringTerm(body, std::vector<SpringConstants>{constants}, dampers, kernel) {}

namespace {

// Each offset's constants for springs of `constants` on a grid of `spacing`.
OffsetConstants offsetConstants(const SpringConstants& constants, double spacing) {
  OffsetConstants out;
  for (std::size_t o = 0; o < kSpringOffsets.size(); ++o) {
    const int kind = static_cast<int>(kSpringOffsets[o].kind);
    out.minusK[o] = -constants.k[kind];
    out.minusD[o] = -constants.d[kind];
    out.rest[o] = restLength(kSpringOffsets[o], spacing);
  }
  return out;
}

}  // namespace

SpringTerm::SpringTerm(const Body& body, std::vector<SpringConstants> byPart, bool dampers,
                       SpringKernel kernel)
    : ForceTerm(body.count()),
      body_(body),
      c_(std::move(byPart)),
      dampers_(dampers),
      rowKernel_(kernel == SpringKernel::Fastest && c_.size() == 1 && courseSprings(body, c_[0])) {
  JELLO_ASSERT(c_.size() == (body.joined() ? body.parts.size() : 1u));
  for (std::size_t o = 0; o < kSpringOffsets.size(); ++o) rests_[o] = restLength(kSpringOffsets[o]);
  // Each point's springs in the list's order: counted, then placed.
  const int n = body.count();
  springsStart_.assign(n + 1, 0);
  for (const Spring& s : body.springs) ++springsStart_[s.a + 1], ++springsStart_[s.b + 1];
  for (int q = 0; q < n; ++q) springsStart_[q + 1] += springsStart_[q];
  springsOf_.resize(springsStart_[n]);
  std::vector<int> next(springsStart_.begin(), springsStart_.end() - 1);
  for (int s = 0; s < static_cast<int>(body.springs.size()); ++s) {
    springsOf_[next[body.springs[s].a]++] = s;
    springsOf_[next[body.springs[s].b]++] = s;
  }
  if (kernel == SpringKernel::List || rowKernel_ || body.springs.empty()) return;
  std::vector<const Body*> parts;
  for (const auto& part : body.parts) parts.push_back(part.get());
  if (parts.empty()) parts.push_back(&body);
  for (std::size_t part = 0; part < parts.size(); ++part) {
    grids_.emplace_back(*parts[part]);
    offsetConstants_.push_back(offsetConstants(c_[part], parts[part]->spacing));
    if (!grids_.back().represents()) {  // a body the grid kernel does not know: the list
      grids_.clear();
      offsetConstants_.clear();
      return;
    }
  }
}

std::vector<std::pair<int, int>> SpringTerm::pairs() const {
  std::vector<std::pair<int, int>> out;
  out.reserve(springs().size());
  for (const Spring& s : springs()) out.emplace_back(s.a, s.b);
  return out;
}

// The force on end a of spring s, as springForce computes it with its kind's constants; without
// dampers their tension is left out altogether, as the row kernel leaves it out.
inline Vec3 listSpringForce(const Spring& s, const std::vector<SpringConstants>& byPart,
                            bool dampers, const double* p, const double* v, int n) {
  const SpringConstants& c = byPart[s.part];
  const int kind = static_cast<int>(s.kind);
  const Vec3 L = load(p, s.a, n) - load(p, s.b, n);
  double len;
  const Vec3 u = direction(L, &len);
  double tension = springTension(len, c.k[kind], s.rest);
  if (dampers) tension += damperTension(load(v, s.a, n) - load(v, s.b, n), u, c.d[kind]);
  return tension * u;
}

void SpringTerm::addListForces(PointRange points, const double* p, const double* v,
                               double* force) const {
  const int n = pointCount();
  const std::vector<Spring>& list = springs();
  if (points.begin == 0 && points.end == n) {
    for (const Spring& s : list) {
      const Vec3 f = listSpringForce(s, c_, dampers_, p, v, n);
      store(force, s.a, n, load(force, s.a, n) + f);
      store(force, s.b, n, load(force, s.b, n) - f);
    }
    return;
  }
  gather(
      points, [&](int s) { return listSpringForce(list[s], c_, dampers_, p, v, n); }, force);
}

// x - f and x + (-f) round alike: a point's sum, its springs' forces in the list's order, is the
// whole pass's, bit for bit.
template <class ForceOf>
void SpringTerm::gather(PointRange points, const ForceOf& forceOf, double* force) const {
  const int n = pointCount();
  const std::vector<Spring>& list = springs();
  for (int q = points.begin; q < points.end; ++q) {
    Vec3 total = load(force, q, n);
    for (int i = springsStart_[q]; i < springsStart_[q + 1]; ++i) {
      const Vec3 f = forceOf(springsOf_[i]);
      total = list[springsOf_[i]].a == q ? total + f : total - f;
    }
    store(force, q, n, total);
  }
}

void SpringTerm::listSpringForces(int first, int end, const double* p, const double* v,
                                  double* springForce) const {
  const int n = pointCount();
  for (int s = first; s < end; ++s) {
    const Vec3 f = listSpringForce(springs()[s], c_, dampers_, p, v, n);
    springForce[3 * s] = f.x;
    springForce[3 * s + 1] = f.y;
    springForce[3 * s + 2] = f.z;
  }
}

void SpringTerm::addListedForces(PointRange points, const double* springForce,
                                 double* force) const {
  gather(
      points,
      [springForce](int s) {
        return Vec3{springForce[3 * s], springForce[3 * s + 1], springForce[3 * s + 2]};
      },
      force);
}

PointRange SpringTerm::inPart(std::size_t part, PointRange points, int* first) const {
  *first = body_.joined() ? body_.partFirst[part] : 0;
  const int end = *first + grids_[part].points();
  return {std::max(points.begin, *first) - *first, std::min(points.end, end) - *first};
}

// Each part's points of the range, through its grid (a body that is not joined: its one part).
void SpringTerm::addGridForces(PointRange points, const double* p, const double* v,
                               double* force) const {
  const int n = pointCount();
  for (std::size_t part = 0; part < grids_.size(); ++part) {
    int first;
    const PointRange mine = inPart(part, points, &first);
    if (mine.begin >= mine.end) continue;
    grids_[part].addForces(mine, {p + first, v + first, force + first, n}, offsetConstants_[part],
                           dampers_);
  }
}

long long SpringTerm::costOf(PointRange points) const {
  if (rowKernel_) return 16LL * (points.end - points.begin);
  if (grids_.empty()) return springsStart_[points.end] - springsStart_[points.begin];
  long long slots = 0;
  for (std::size_t part = 0; part < grids_.size(); ++part) {
    int first;
    const PointRange mine = inPart(part, points, &first);
    if (mine.begin < mine.end) slots += grids_[part].slotsFor(mine);
  }
  return slots;
}

long long SpringTerm::warmUpCost() const {
  long long most = 0;
  for (const SpringGrid& grid : grids_) most = std::max(most, grid.warmUpSlots());
  return most;
}

void SpringTerm::addForcesOn(PointRange points, const double* p, const double* v, const Bounds*,
                             double* force) const {
  if (!grids_.empty()) return addGridForces(points, p, v, force);
  if (!rowKernel_) return addListForces(points, p, v, force);
  // The row kernel is the course cube's: 512 points, ranges of whole lattice rows.
  JELLO_ASSERT(pointCount() == kNumPoints);
  JELLO_ASSERT(points.begin % kLatticeSize == 0 && points.end % kLatticeSize == 0);
  const Inputs in{p, v, -c_[0].k[0], -c_[0].d[0], rests_.data()};
  if (dampers_)
    addSpringForces<true>(in, points, force);
  else
    addSpringForces<false>(in, points, force);
}

void SpringTerm::addJacobian(const double* p, const double* v, JacobianSink* sink) const {
  const int n = pointCount();
  Block3 dFdL, dFdw;
  for (const Spring& s : springs()) {
    const int kind = static_cast<int>(s.kind);
    const SpringConstants& c = c_[s.part];
    springJacobian(load(p, s.a, n) - load(p, s.b, n), load(v, s.a, n) - load(v, s.b, n), c.k[kind],
                   c.d[kind], s.rest, &dFdL, &dFdw);
    sink->addPair(dFdL, dFdw);
  }
}

void SpringTerm::addEnergy(const double* p, double* energy) const {
  const int n = pointCount();
  for (const Spring& s : springs()) {
    double stretch = length(load(p, s.a, n) - load(p, s.b, n)) - s.rest;
    *energy += 0.5 * c_[s.part].k[static_cast<int>(s.kind)] * stretch * stretch;
  }
}

void SpringTerm::summarise(std::vector<std::string>* kept,
                           std::vector<std::string>* leftOut) const {
  if (springs().empty()) {
    leftOut->push_back("springs (the jelly is made of finite elements)");
    return;
  }
  kept->push_back("springs");
  if (dampers_)
    kept->push_back("dampers");
  else
    leftOut->push_back("dampers (zero damping)");
}

namespace {

std::string constantsText(const SpringConstants& c, std::size_t springs) {
  if (c.uniform())
    return textf("kElastic %.9g N/m, dElastic %.9g N s/m (%zu springs: structural, shear, bend)",
                 c.k[0], c.d[0], springs);
  std::string text = textf("%zu springs:", springs);
  for (int kind = 0; kind < kSpringKinds; ++kind)
    text += textf("%s %s k %.9g N/m, d %.9g N s/m", kind ? ";" : "",
                  springKindName(SpringKind(kind)), c.k[kind], c.d[kind]);
  return text;
}

}  // namespace

std::vector<TermLine> SpringTerm::describe(const double*) const {
  if (springs().empty()) return {{"springs", "none: the jelly is made of finite elements"}};
  if (c_.size() == 1) return {{"springs", constantsText(c_[0], springs().size())}};
  std::vector<std::size_t> count(c_.size(), 0);
  for (const Spring& s : springs()) ++count[s.part];
  std::vector<TermLine> lines;
  for (std::size_t part = 0; part < c_.size(); ++part)
    lines.push_back(
        {"springs", textf("jelly %zu: ", part + 1) + constantsText(c_[part], count[part])});
  return lines;
}

}  // namespace jello
