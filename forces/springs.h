// forces/springs.h: the damped springs of the lattice (structural, shear, bend), a pair term.
//
// Units: metres, seconds, newtons; k in N/m, d in N s/m. Sign convention: a spring's force is
// the force ON its end a; its end b gets minus that. L = p_a - p_b points from b to a.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "forces/term.h"

namespace jello {

enum class SpringKind : std::uint8_t { Structural, Shear, Bend };

// One row of the table the spring list is built from: every lattice point (i,j,k) whose
// neighbour (i+di, j+dj, k+dk) exists is joined to it by a spring of rest length |offset|/7.
struct SpringOffset {
  int di, dj, dk;
  SpringKind kind;
};
// 16 rows, 6220 springs; the order in which the kernel adds them (docs/physics.md).
inline constexpr std::array<SpringOffset, 16> kSpringOffsets = {{
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
}};

struct Spring {
  int a, b;     // point indices, see pointIndex()
  double rest;  // m, from the ideal lattice
  SpringKind kind;
};

// How the force kernel covers the springs of one offset. It works on lattice rows (fixed i and
// j, the 8 points along k, one Pack): the row of point q joins q to q + delta. A row computes
// its 8 slots when its neighbours' row (i + di, j + dj) exists, and keeps the slots whose
// neighbour k + dk exists too; a kept slot is a spring, and every spring is a kept slot
// (6,832 slots computed for 6,220 springs). Rows whose neighbours' row is missing compute
// nothing.
constexpr int springDelta(const SpringOffset& o) { return pointIndex(o.di, o.dj, o.dk); }
constexpr bool rowHasSprings(const SpringOffset& o, int row) {
  const int i = row / kLatticeSize + o.di, j = row % kLatticeSize + o.dj;
  return i >= 0 && i < kLatticeSize && j >= 0 && j < kLatticeSize;
}
constexpr bool slotKept(const SpringOffset& o, int lane) {
  return lane + o.dk >= 0 && lane + o.dk < kLatticeSize;
}
// The rest length |offset|/7, computed as docs/physics.md gives it.
double restLength(const SpringOffset& o);
// The springs one by one (6,220), grouped by offset in the order of kSpringOffsets, each group
// in the order of its points a: the kernel's kept slots.
std::vector<Spring> buildSprings();

// Where two threads split the kernel's rows so that each has as many slots to compute: the first
// point of the second range. The second range also computes again the slots of the rows just
// before it whose springs end in it (the kernel's rings), so it is the shorter.
int balancedSplitPoint();

// Spring and damper, as magnitudes along u = L/|L| (positive pushes a away from b).
inline double springTension(double len, double k, double rest) { return -k * (len - rest); }
inline double damperTension(Vec3 relVel, Vec3 u, double d) { return -d * dot(relVel, u); }

// Damped spring of rest length `rest` between a and b: L = p_a - p_b, relVel = v_a - v_b.
// F_a = -k (|L| - rest) u - d (relVel . u) u; zero when |L| = 0.
inline Vec3 springForce(Vec3 L, Vec3 relVel, double k, double d, double rest) {
  double len;
  Vec3 u = direction(L, &len);
  return (springTension(len, k, rest) + damperTension(relVel, u, d)) * u;
}
// Derivatives of springForce with respect to L and to w = relVel. With the geometric term:
// dF/dL = -k [u u^T + (1 - rest/|L|) P] - (d/|L|) [u (P w)^T + (w.u) P], where P = I - u u^T;
// dF/dw = -d u u^T. Zero at |L| = 0, where the force is zero.
void springJacobian(Vec3 L, Vec3 relVel, double k, double d, double rest, Block3* dFdL,
                    Block3* dFdw);

// All the springs of the lattice, with one stiffness and one damping. Without dampers
// (d = 0, and not the reference) the kernel leaves their term out.
class SpringTerm final : public ForceTerm {
 public:
  SpringTerm(double k, double d, bool dampers);
  const std::vector<Spring>& springs() const { return springs_; }

  bool isPairTerm() const override { return true; }
  std::vector<std::pair<int, int>> pairs() const override;
  std::size_t pairCount() const override { return springs_.size(); }
  bool mayReach(const Bounds&) const override { return true; }
  void addForcesOn(PointRange points, const double* p, const double* v, const Bounds* box,
                   double* force) const override;
  void addJacobian(const double* p, const double* v, JacobianSink* sink) const override;
  void addEnergy(const double* p, double* energy) const override;
  void summarise(std::vector<std::string>* kept, std::vector<std::string>* leftOut) const override;
  std::vector<TermLine> describe(const double* p) const override;

 private:
  double k_, d_;
  bool dampers_;
  std::array<double, kSpringOffsets.size()> rests_;  // m, restLength of each offset
  std::vector<Spring> springs_;
};

}  // namespace jello
