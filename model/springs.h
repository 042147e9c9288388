// model/springs.h: the damped springs of the lattice (structural, shear, bend), a pair term.
//
// Units: metres, seconds, newtons; k in N/m, d in N s/m. Sign convention: a spring's force is
// the force ON its end a; its end b gets minus that. L = p_a - p_b points from b to a.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "model/body.h"
#include "model/springgrid.h"
#include "model/term.h"

namespace jello {

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
// The course cube's springs one by one (6,220; courseBody's), grouped by offset in the order of
// kSpringOffsets, each group in the order of its points a: the kernel's kept slots.
const std::vector<Spring>& buildSprings();

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

// The stiffness (N/m) and damping (N s/m) of each kind of spring, indexed by SpringKind. A
// course world has one of each for all three kinds.
struct SpringConstants {
  std::array<double, kSpringKinds> k{}, d{};
  static SpringConstants same(double k, double d) { return {{k, k, k}, {d, d, d}}; }
  bool uniform() const { return k[0] == k[1] && k[1] == k[2] && d[0] == d[1] && d[1] == d[2]; }
  bool anyDamping() const { return d[0] != 0 || d[1] != 0 || d[2] != 0; }
};
// The course's springs: the 8x8x8 lattice with one stiffness and one damping for every kind.
// Only these go through the row kernel, and only these have the free lattice's modes (spectrum.h).
inline bool courseSprings(const Body& body, const SpringConstants& constants) {
  return body.courseLattice && constants.uniform();
}

// How a SpringTerm computes its forces: the kernels made for its body (the row kernel for the
// course cube with one stiffness and one damping, the grid kernel of springgrid.h for any other
// grid body), or the spring list alone (the reference the kernels are tested and timed against).
enum class SpringKernel { Fastest, List };

// All the springs of a body (body.h). The course cube with one stiffness and one damping goes
// through the row kernel above; any other grid body (a joined body's part by part) through the
// grid kernel (springgrid.h); the reference through the spring list: on all its points a pass
// over the springs in their order, adding each spring's force to its end a and taking it from its
// end b; on a range of points, each point's springs in the same order (each spring is computed at
// both its ends), which rounds alike. All sum docs/physics.md's order, bit for bit alike.
// Without dampers (no damping, and not the reference) the kernels leave their term out.
class SpringTerm final : public ForceTerm {
 public:
  SpringTerm(const Body& body, const SpringConstants& constants, bool dampers,
             SpringKernel kernel = SpringKernel::Fastest);
  // A joined body's (Body::parts): each part's springs with its own constants.
  SpringTerm(const Body& body, std::vector<SpringConstants> byPart, bool dampers,
             SpringKernel kernel = SpringKernel::Fastest);
  const std::vector<Spring>& springs() const { return body_.springs; }
  // The constants of the springs of part `part` (0 for one body).
  const SpringConstants& constants(int part = 0) const { return c_[part]; }
  // Whether the row kernel computes the forces; whether the spring list does (else the row or the
  // grid kernel).
  bool rowKernel() const { return rowKernel_; }
  bool listKernel() const { return !rowKernel_ && grids_.empty(); }
  // The slots the kernel computes for a range of points (its cost, for splitting a body between
  // threads): for the spring list, each point's springs.
  long long costOf(PointRange points) const;
  // The slots a range after the first computes again (the grid kernel's warm-up), about.
  long long warmUpCost() const;
  // The spring list in two passes, for several threads: each spring's force on its end a, for the
  // springs [first, end), into springForce (3 doubles a spring, xyz); then on a range of points,
  // each point's springs' forces from it, added in the list's order: what addForcesOn adds there,
  // bit for bit.
  void listSpringForces(int first, int end, const double* p, const double* v,
                        double* springForce) const;
  void addListedForces(PointRange points, const double* springForce, double* force) const;

  bool isPairTerm() const override { return true; }
  std::vector<std::pair<int, int>> pairs() const override;
  std::size_t pairCount() const override { return springs().size(); }
  bool mayReach(const Bounds&) const override { return true; }
  void addForcesOn(PointRange points, const double* p, const double* v, const Bounds* box,
                   double* force) const override;
  void addJacobian(const double* p, const double* v, JacobianSink* sink) const override;
  void addEnergy(const double* p, double* energy) const override;
  void summarise(std::vector<std::string>* kept, std::vector<std::string>* leftOut) const override;
  std::vector<TermLine> describe(const double* p) const override;

 private:
  void addListForces(PointRange points, const double* p, const double* v, double* force) const;
  void addGridForces(PointRange points, const double* p, const double* v, double* force) const;
  // The points of `points` in grid part `part`, numbered from its first point (in *first).
  PointRange inPart(std::size_t part, PointRange points, int* first) const;
  // Adds to each point of `points` its springs' forces forceOf(spring), in the list's order.
  template <class ForceOf>
  void gather(PointRange points, const ForceOf& forceOf, double* force) const;

  const Body& body_;
  std::vector<SpringConstants> c_;  // by part
  bool dampers_, rowKernel_;
  std::array<double, kSpringOffsets.size()> rests_;  // m, restLength of each offset
  // Each point's springs, in their order: springsOf_[springsStart_[q] .. springsStart_[q + 1]).
  std::vector<int> springsStart_, springsOf_;
  // The grid kernel's layout and constants, a part each (none: the row kernel or the list).
  std::vector<SpringGrid> grids_;
  std::vector<OffsetConstants> offsetConstants_;
};

}  // namespace jello
