// model/term.h: what every force term of the model is (docs/physics.md describes each).
//
// A term owns everything about one kind of force: the force itself on every point, its
// Jacobian blocks, the energy it stores, a test of whether it may act at all on a cube inside
// a given box, and its lines in the model's description. ForceTerms (model.h) is the list of
// the terms a world needs; the force kernel, the Jacobian, the divergence guard and
// `createWorld --describe` iterate that list and know no term by name.
//
// Units: metres, seconds, kilograms, newtons; a Jacobian block dF/dp is in N/m, dF/dv in N s/m.
// Signs: a term's force is the force ON a point; its blocks are derivatives of that force.
// Arrays of positions, velocities and forces are per-point arrays (world.h, coordIndex).
// This file links no GL and pulls in no Eigen.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "model/vec3.h"
#include "model/world.h"

namespace jello {

// An axis-aligned box holding points (m): the reach tests take the positions' bounds.
struct Bounds {
  Vec3 lower, upper;
};
// The bounds of the positions of p (a per-point array of `points` points). (With a NaN among them
// they mean little; such a state is caught as diverged after the step.)
Bounds boundsOf(const double* p, int points);

// The points [begin, end) a call works on: begin a multiple of kRangeAlignment (so that the loops
// 8 points at a time stay aligned; whole lattice rows in the course cube), end one too or the last
// point's. Every result is computed point by point in the same order whatever the range: the
// forces on a range are those of the whole call there, bit for bit, which lets two threads share
// an evaluation (core/threadpool.h).
struct PointRange {
  int begin = 0, end = 0;
};
constexpr int kRangeAlignment = 8;
// The end of the range's whole groups of `lanes` points (the rest, a body's last few points, are
// taken one by one).
constexpr int groupedEnd(PointRange r, int lanes) { return r.end - (r.end - r.begin) % lanes; }
// The bounds of the points of `range` alone (one point at least). For finite positions the
// bounds of several ranges' bounds are those of all of them, whatever the ranges.
Bounds boundsOf(const double* p, int points, PointRange range);

// printf into a std::string, for the terms' descriptions (up to 511 characters).
std::string textf(const char* pattern, ...) __attribute__((format(printf, 1, 2)));

// A 3x3 block of a Jacobian, row-major: m[3 * row + column].
struct Block3 {
  double m[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
};

// Where the terms put their Jacobian blocks (jacobian.cpp assembles them into sparse matrices).
class JacobianSink {
 public:
  virtual ~JacobianSink() = default;
  // The derivatives of a pair force F on point a (and -F on b) with respect to L = p_a - p_b and
  // to w = v_a - v_b. The pairs come in the order of the term's pairsAt(p).
  virtual void addPair(const Block3& dFdL, const Block3& dFdw) = 0;
  // The derivatives of a point force on q with respect to q's own position and velocity.
  virtual void addPoint(int q, const Block3& dFdp, const Block3& dFdv) = 0;
  // Adds to block k of the term's couplings() (the derivatives of the force on its row point with
  // respect to its column point's position and velocity), for terms whose forces join several
  // points at once (finite elements); a block may be added to many times.
  virtual void addCoupling(std::size_t k, const Block3& dFdp, const Block3& dFdv) = 0;
};

// One line of the scene's description: a label ("springs", "plane", ...) and the text after it.
struct TermLine {
  std::string label, text;
};

class ForceTerm {
 public:
  virtual ~ForceTerm() = default;

  // The number of points of the body it acts on (body.h): its arrays hold 3 * pointCount() doubles.
  int pointCount() const { return points_; }
  PointRange allPoints() const { return {0, points_}; }

  // Pair terms (the springs, the finite elements) join points; point terms (walls, plane, field)
  // act on each point alone, from its own position and velocity. The kernel sums the pair terms'
  // forces first, then adds the point terms' forces summed among themselves (the order
  // docs/physics.md gives, which every result reproduces bit for bit).
  virtual bool isPairTerm() const { return false; }
  // The pairs (a, b) a pair term joins, in the order of its Jacobian blocks; none for a point term.
  virtual std::vector<std::pair<int, int>> pairs() const { return {}; }
  // pairs().size(), without making the list (the Jacobian checks its pattern with it each time).
  virtual std::size_t pairCount() const { return 0; }
  // Whether the pairs depend on the positions (contact between bodies): then pairs() and
  // pairCount() are empty, and pairsAt(p) lists the pairs at positions p, in the order of the
  // Jacobian blocks addJacobian(p, ...) gives.
  virtual bool pairsMove() const { return false; }
  virtual std::vector<std::pair<int, int>> pairsAt(const double* /*p*/) const { return pairs(); }

  // The blocks (row, column) of the Jacobian of a term whose forces join several points at once
  // (finite elements), each once, fixed; none for the others. Its addJacobian gives them through
  // JacobianSink::addCoupling by their place in this list.
  virtual std::vector<std::pair<int, int>> couplings() const { return {}; }
  virtual std::size_t couplingCount() const { return 0; }

  // Whether the term may act on some point inside `box`. Conservative: true when unsure.
  virtual bool mayReach(const Bounds& box) const = 0;
  // How many of the points at positions p the term pushes as a contact (walls, plane). A contact
  // switches on where a point crosses a surface: its force has a kink there (a jump with
  // damping), across which no integrator keeps its order in dt (jello --report says so when a
  // fit shows it). 0 for the
  // terms whose force is smooth (springs, field) and for a contact that pushes with k = d = 0.
  virtual int pointsInContact(const double* /*p*/) const { return 0; }
  // Adds the term's force on the points of `points` to `force` (and nothing elsewhere); it may
  // read every point's position and velocity. `box` bounds all the positions, so that the term
  // can skip its parts out of reach; null makes it compute every part (the reference).
  virtual void addForcesOn(PointRange points, const double* p, const double* v, const Bounds* box,
                           double* force) const = 0;
  // The same on every point.
  void addForces(const double* p, const double* v, const Bounds* box, double* force) const {
    addForcesOn(allPoints(), p, v, box, force);
  }
  // Adds the term's Jacobian blocks at (p, v).
  virtual void addJacobian(const double* p, const double* v, JacobianSink* sink) const = 0;
  // Adds the energy the term stores at positions p, J (0 for a term that stores none).
  virtual void addEnergy(const double* p, double* energy) const = 0;
  // The largest force the term can exert without storing energy for it (a field's largest
  // node), N: the divergence guard's bound on the energy a term can supply.
  virtual double largestExternalForce() const { return 0; }

  // Its parts in the one-line scene summary: what it computes ("springs", "plane (when the
  // bounding box reaches it)") and what it leaves out, with why ("dampers (zero damping)").
  virtual void summarise(std::vector<std::string>* kept,
                         std::vector<std::string>* leftOut) const = 0;
  // Its lines in `createWorld --describe`, for a cube at positions p.
  virtual std::vector<TermLine> describe(const double* p) const = 0;

 protected:
  explicit ForceTerm(int points) : points_(points) {}
  // Point q of a per-point array of the body's, and f added to point q of one.
  Vec3 at(const double* a, int q) const { return load(a, q, points_); }
  void addAt(double* force, int q, Vec3 f) const {
    store(force, q, points_, load(force, q, points_) + f);
  }

 private:
  int points_;
};

}  // namespace jello
