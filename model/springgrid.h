// model/springgrid.h: the springs of a grid body (a lattice of any size, a sheet, a body of
// voxels) laid out for the force kernel, which streams through the grid as the course cube's row
// kernel streams through its rows (docs/performance.md, "The spring kernel").
//
// Units: metres, seconds, newtons; k in N/m, d in N s/m. Sign convention (springs.h): a spring's
// force is the force ON its end a, the node with the lower number; its end b gets minus that.
//
// The kernel goes through the grid's nodes in their order (i, j, k ascending, k fastest) a unit of
// kLanes consecutive nodes at a time (one vector register: 8 nodes with AVX-512, 4 with AVX, 2
// with SSE2), and for each unit through the 16 offsets in table order, keeping the unit's total
// force in registers: for each offset it computes the unit's slots (node q's spring to node
// q + delta, delta = (di * ny + dj) * nz + dk) and adds, lane by lane, (total - in) + out, where
// `out` is the spring starting at the node and `in` the one ending there, a slot of the unit
// delta nodes back, kept in the offset's ring. That is docs/physics.md's order of summation (each
// point's springs offset by offset, the one ending at it before the one starting at it), so the
// sums are the spring list's bit for bit. A slot is kept when its spring exists (both nodes are
// points and the neighbour is inside the grid): a byte of lane bits a unit and offset. A body
// whose grid has nodes that are not points (voxels) is copied onto its grid for each call (a
// window of nodes, zero where there is no point); a lattice's points are its nodes, and the
// kernel reads the state's own arrays.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "model/body.h"
#include "model/term.h"

namespace jello {

// Each offset's constants (kSpringOffsets' order): -k and -d of its kind, its rest length, m.
struct OffsetConstants {
  std::array<double, kSpringOffsets.size()> minusK{}, minusD{}, rest{};
};

// The arrays a call reads and adds to: per-point arrays whose axis a starts at base + a * stride,
// the body's point q at [q] of each axis (a part of a joined body: base points at its first).
struct BodyArrays {
  const double* p;  // m
  const double* v;  // m/s
  double* force;    // N
  int stride;
};

class SpringGrid {
 public:
  // The springs of a body that is not joined (a joined body has a grid a part).
  explicit SpringGrid(const Body& body);
  // Whether the kernel computes the body's springs: those of a grid body, in the order
  // latticeBody and voxelBody give them (by offset in table order, each offset's by end a), of
  // their offset's rest length; a body without springs too.
  bool represents() const { return represents_; }
  int points() const { return points_; }
  // Adds to arrays.force, on the points of `points` (the body's point numbers, any range within
  // it), the forces of their springs, as the spring list adds them, bit for bit; without dampers
  // their term is left out. Other points' forces are not touched, so that threads may share a
  // call's arrays, a range each. (A slot that is no spring adds +0 where the list adds nothing: the
  // same bits for every force but -0, which a sum that starts from the kernel's +0 never is.)
  void addForces(PointRange points, const BodyArrays& arrays, const OffsetConstants& c,
                 bool dampers) const;
  // Slots the kernel computes in the units that hold the points of `points` (the cost of a range,
  // for splitting a body between threads; a range after the first computes again some of the
  // slots of the units before it, whose springs end in it).
  long long slotsFor(PointRange points) const;
  // The slots a range after the first computes again, before it (whose springs end in it), about.
  long long warmUpSlots() const;

 private:
  struct Span {  // the units a call goes through: warm-up, then its own
    int warm, begin, end;
  };
  Span unitsFor(int nodeBegin, int nodeEnd) const;
  void addOnWindow(PointRange points, const BodyArrays& arrays, const OffsetConstants& c,
                   bool dampers) const;

  int points_ = 0, nodes_ = 0;
  bool represents_ = true, compact_ = true;  // every node a point: node q is point q
  std::array<int, kSpringOffsets.size()> delta_{}, ringUnits_{}, ringFirst_{}, unitsBack_{};
  std::array<bool, kSpringOffsets.size()> present_{};  // the offset has springs in this body
  int ringDoubles_ = 0, reachUnits_ = 0, farthest_ = 0;
  std::vector<std::uint8_t> keep_;  // [unit * 16 + offset]: bit l, node unit * lanes + l's spring
  std::vector<int> nodeOf_;         // a body with empty nodes: each point's node, ascending
};

}  // namespace jello
