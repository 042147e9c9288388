// forces/springs.h: the damped springs of the lattice (structural, shear, bend), a pair term.
//
// Units: metres, seconds, newtons; k in N/m, d in N s/m. Sign convention: a spring's force is
// the force ON its end a; its end b gets minus that. L = p_a - p_b points from b to a.
#pragma once

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
extern const std::vector<SpringOffset> kSpringOffsets;  // 16 rows, 6220 springs

struct Spring {
  int a, b;     // point indices, see pointIndex()
  double rest;  // m, from the ideal lattice
  SpringKind kind;
};

// The springs of one row of kSpringOffsets, for the force kernel: point q is joined to point
// q + delta for every q in the spans where mask[q] is 1. A span is a run of whole lattice rows
// (fixed i and j) whose neighbours' rows exist; inside a row, a neighbour beyond the last k
// has mask 0: the kernel computes that slot and discards it, which keeps its loops regular
// (6,826 slots for 6,220 springs).
struct SpringGroup {
  struct Span {
    int begin, end;  // point indices, end exclusive
  };
  int delta = 0;  // pointIndex(di, dj, dk), > 0 for every row of the table
  double rest = 0;
  SpringKind kind = SpringKind::Structural;
  std::vector<Span> spans;
  std::vector<double> mask;  // kNumPoints entries, 1.0 or 0.0
};
std::vector<SpringGroup> buildSpringGroups();
// The springs one by one (6,220), grouped by offset in the order of kSpringOffsets: the
// groups' kept slots.
std::vector<Spring> buildSprings();

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
  void addForces(const double* p, const double* v, const Bounds* box, double* force) const override;
  void addJacobian(const double* p, const double* v, JacobianSink* sink) const override;
  void addEnergy(const double* p, double* energy) const override;
  void summarise(std::vector<std::string>* kept, std::vector<std::string>* leftOut) const override;
  std::vector<TermLine> describe(const double* p) const override;

 private:
  double k_, d_;
  bool dampers_;
  std::vector<SpringGroup> groups_;
  std::vector<Spring> springs_;
};

}  // namespace jello
