// forces/springs.cpp: the lattice's springs: the spring list, the force kernel, Jacobian, energy
// and description.

#include "forces/springs.h"

#include <cmath>
#include <utility>

#include "forces/pack.h"

namespace jello {

double restLength(const SpringOffset& o) {
  return kRestSpacing * std::sqrt(double(o.di * o.di + o.dj * o.dj + o.dk * o.dk));
}

std::vector<Spring> buildSprings() {
  std::vector<Spring> springs;
  for (const SpringOffset& o : kSpringOffsets)
    for (int q = 0; q < kNumPoints; ++q)
      if (rowHasSprings(o, q / kPackLanes) && slotKept(o, q % kPackLanes))
        springs.push_back({q, q + springDelta(o), restLength(o), o.kind});
  return springs;
}

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

// The force kernel. It goes through the lattice a row at a time (8 points along k, one Pack),
// and for each row through the 16 offsets in table order, keeping the row's total force in
// registers: for each offset it computes the row's 8 slots (the springs from the row's points a
// to their points b = a + delta) and adds, lane by lane, (total - in) + out. `out` is the
// force of the spring starting at the point, `in` that of the spring ending at it, which
// started delta points earlier: a slot of an earlier row, which the kernel kept in a small ring
// of that offset's recent rows. That is docs/physics.md's order of summation, so the sums round
// exactly as a loop over single springs would. Each offset is a template argument: its delta,
// its ring and its kept lanes are constants, and the 16 offsets unroll into one loop body.
constexpr int kRows = kNumPoints / kPackLanes;
constexpr int kOffsets = static_cast<int>(kSpringOffsets.size());

// A spring of an offset ends `delta` points further on: rowsOn whole rows and lanesOn lanes.
// The springs ending in row r start in rows r - rowsOn - 1 and r - rowsOn: the offset's ring
// keeps the slots of its last rowsOn + 2 rows, row r at r % ringRows.
constexpr int ringRows(int offset) { return springDelta(kSpringOffsets[offset]) / kPackLanes + 2; }
constexpr int ringStart(int offset) {
  return offset == 0 ? 0 : ringStart(offset - 1) + ringRows(offset - 1);
}
constexpr int kRingRows = ringStart(kOffsets);  // 121 rows, 23 KB: the rings stay in L1

// One row of slot forces, by axis.
struct RowForce {
  Pack axis[3];
};

// The 8 lanes that start kFirst lanes into lo and run on into hi.
template <int kFirst>
JELLO_PACK_INLINE Pack lanesFrom(Pack lo, Pack hi) {
  if constexpr (kFirst == 0)
    return lo;
  else
    return __builtin_shufflevector(lo, hi, kFirst, kFirst + 1, kFirst + 2, kFirst + 3, kFirst + 4,
                                   kFirst + 5, kFirst + 6, kFirst + 7);
}

// The 8 doubles of one axis from point `first` on, where some lie past the last point (the far
// ends of slots the kernel discards, in the last rows): those lanes read 0, not past the array.
JELLO_PACK_INLINE Pack loadUpToEnd(const double* axis, int first) {
  Pack out = {};
  for (int l = 0; first + l < kNumPoints; ++l) out[l] = axis[first + l];
  return out;
}

// 1 for the lanes whose spring exists, 0 for the slots the kernel discards.
template <int kOffset>
JELLO_PACK_INLINE Pack keptLanes() {
  Pack keep;
  for (int l = 0; l < kPackLanes; ++l) keep[l] = slotKept(kSpringOffsets[kOffset], l) ? 1.0 : 0.0;
  return keep;
}

// The inputs every row and offset shares.
struct Inputs {
  const double* p;
  const double* v;
  Pack minusK, minusD;  // -kElastic, -dElastic
  const double* rests;  // m, by offset
};

// The 8 slot forces of one row for one offset: springForce() lane by lane, times the lane's
// keep (1 or 0), exactly as a single spring's force is computed.
template <int kOffset, bool kDampers>
JELLO_PACK_INLINE RowForce slotForces(const Inputs& in, int q, const RowForce& p,
                                      const RowForce& v) {
  constexpr SpringOffset o = kSpringOffsets[kOffset];
  constexpr int delta = springDelta(o);
  // Only an offset whose far ends are not whole rows on can reach past the last point.
  const bool pastEnd = delta % kPackLanes != 0 && q + delta + kPackLanes > kNumPoints;
  Pack L[3], w[3];
  for (int a = 0; a < 3; ++a) {
    const double *pb = in.p + a * kNumPoints, *vb = in.v + a * kNumPoints;
    L[a] = p.axis[a] - (pastEnd ? loadUpToEnd(pb, q + delta) : loadPack(pb + q + delta));
    if constexpr (kDampers)
      w[a] = v.axis[a] - (pastEnd ? loadUpToEnd(vb, q + delta) : loadPack(vb + q + delta));
  }
  // direction(): |L| and L/|L|, zero for a zero L (a select: the lanes go on together).
  const Pack len = sqrtPack((L[0] * L[0] + L[1] * L[1]) + L[2] * L[2]);
  const Pack inverse = len != 0 ? splat(1.0) / len : Pack{};
  const Pack u[3] = {inverse * L[0], inverse * L[1], inverse * L[2]};
  Pack tension = in.minusK * (len - in.rests[kOffset]);
  if constexpr (kDampers)
    tension = tension + in.minusD * ((w[0] * u[0] + w[1] * u[1]) + w[2] * u[2]);
  if constexpr (o.dk != 0) tension = keptLanes<kOffset>() * tension;  // 1 * t is t: skipped
  RowForce out = {{tension * u[0], tension * u[1], tension * u[2]}};
  // Slots whose far end is past the last point hold exactly 0, as they always have.
  if (pastEnd)
    for (int l = 0; l < kPackLanes; ++l)
      if (q + l + delta >= kNumPoints) out.axis[0][l] = out.axis[1][l] = out.axis[2][l] = 0.0;
  return out;
}

// One offset's part of a row's total: its slots (zero in a row without springs of the offset)
// go into the ring, and the forces of the springs ending at the row's points come out of it:
// the slots lanesOn lanes from the end of row - rowsOn - 1 on, into row - rowsOn (this row when
// rowsOn is 0). Rows before the first hold no springs: zeros. Reading whole rows and shifting
// lanes is faster than a load across two rows, which may wait for the stores of both.
template <int kOffset, bool kDampers>
JELLO_PACK_INLINE void addOffset(const Inputs& in, int row, const RowForce& p, const RowForce& v,
                                 RowForce* rings, RowForce* total) {
  constexpr int delta = springDelta(kSpringOffsets[kOffset]);
  constexpr int rowsOn = delta / kPackLanes, lanesOn = delta % kPackLanes, size = ringRows(kOffset);
  RowForce* ring = rings + ringStart(kOffset);
  const RowForce out = rowHasSprings(kSpringOffsets[kOffset], row)
                           ? slotForces<kOffset, kDampers>(in, row * kPackLanes, p, v)
                           : RowForce{};
  ring[row % size] = out;
  const int near = row - rowsOn, far = near - 1;
  for (int a = 0; a < 3; ++a) {
    Pack ending = near >= 0 ? ring[near % size].axis[a] : Pack{};
    if constexpr (lanesOn != 0)
      ending =
          lanesFrom<kPackLanes - lanesOn>(far >= 0 ? ring[far % size].axis[a] : Pack{}, ending);
    total->axis[a] = (total->axis[a] - ending) + out.axis[a];
  }
}

template <bool kDampers, int... kOffset>
JELLO_PACK_INLINE void addOffsets(std::integer_sequence<int, kOffset...>, const Inputs& in, int row,
                                  const RowForce& p, const RowForce& v, RowForce* rings,
                                  RowForce* total) {
  (addOffset<kOffset, kDampers>(in, row, p, v, rings, total), ...);
}

template <bool kDampers>
void addSpringForces(const Inputs& in, double* __restrict force) {
  RowForce rings[kRingRows];  // each ring row is written before it is read
  for (int row = 0; row < kRows; ++row) {
    const int q = row * kPackLanes;
    RowForce p, v, total;
    for (int a = 0; a < 3; ++a) {
      p.axis[a] = loadPack(in.p + a * kNumPoints + q);
      v.axis[a] = loadPack(in.v + a * kNumPoints + q);
      total.axis[a] = loadPack(force + a * kNumPoints + q);
    }
    addOffsets<kDampers>(std::make_integer_sequence<int, kOffsets>{}, in, row, p, v, rings, &total);
    for (int a = 0; a < 3; ++a) storePack(force + a * kNumPoints + q, total.axis[a]);
  }
}

}  // namespace

SpringTerm::SpringTerm(double k, double d, bool dampers)
    : k_(k), d_(d), dampers_(dampers), springs_(buildSprings()) {
  for (std::size_t o = 0; o < kSpringOffsets.size(); ++o) rests_[o] = restLength(kSpringOffsets[o]);
}

std::vector<std::pair<int, int>> SpringTerm::pairs() const {
  std::vector<std::pair<int, int>> out;
  out.reserve(springs_.size());
  for (const Spring& s : springs_) out.emplace_back(s.a, s.b);
  return out;
}

void SpringTerm::addForces(const double* p, const double* v, const Bounds*, double* force) const {
  const Inputs in{p, v, splat(-k_), splat(-d_), rests_.data()};
  if (dampers_)
    addSpringForces<true>(in, force);
  else
    addSpringForces<false>(in, force);
}

void SpringTerm::addJacobian(const double* p, const double* v, JacobianSink* sink) const {
  Block3 dFdL, dFdw;
  for (const Spring& s : springs_) {
    springJacobian(load(p, s.a) - load(p, s.b), load(v, s.a) - load(v, s.b), k_, d_, s.rest, &dFdL,
                   &dFdw);
    sink->addPair(dFdL, dFdw);
  }
}

void SpringTerm::addEnergy(const double* p, double* energy) const {
  for (const Spring& s : springs_) {
    double stretch = length(load(p, s.a) - load(p, s.b)) - s.rest;
    *energy += 0.5 * k_ * stretch * stretch;
  }
}

void SpringTerm::summarise(std::vector<std::string>* kept,
                           std::vector<std::string>* leftOut) const {
  kept->push_back("springs");
  if (dampers_)
    kept->push_back("dampers");
  else
    leftOut->push_back("dampers (zero damping)");
}

std::vector<TermLine> SpringTerm::describe(const double*) const {
  return {{"springs",
           textf("kElastic %.9g N/m, dElastic %.9g N s/m (%zu springs: structural, shear, bend)",
                 k_, d_, springs_.size())}};
}

}  // namespace jello
