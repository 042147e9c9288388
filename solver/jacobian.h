// solver/jacobian.h: the Jacobians of a model's forces (model/model.h) with respect to the
// positions and the velocities, assembled from the terms' blocks (model/term.h), for the implicit
// integrator and for the stability analysis.
//
// Units: dF/dp in N/m, dF/dv in N s/m; the acceleration Jacobians divide by the mass. Signs
// follow model/term.h: each block is the derivative of the force ON a point.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <array>
#include <vector>

#include "solver/physics.h"

namespace jello {

using Mat3 = Eigen::Matrix3d;
using SparseMatrix = Eigen::SparseMatrix<double>;
using BlockSlots = std::array<int, 9>;

// 1 at each coordinate (coordIndex) of a pinned point, 0 elsewhere: 3 flags a point.
std::vector<char> pinnedCoordinates(const std::vector<int>& pinned, int points);

// A term's block as an Eigen matrix.
Mat3 toMatrix(const Block3& block);

// Jacobians (3n x 3n for n points) of the accelerations F/mass of all points with respect
// to all positions and all velocities. Their sparsity pattern is the same for both: a 3x3 block
// for every point (the diagonal) and for every pair of points a pair term joins, zeros kept. It
// is built on the first assembly, and again when the pairs in contact change (model/term.h
// pairsMove); other assemblies only write values.
struct AccelerationJacobian {
  SparseMatrix dAdp, dAdv;
  // Where each block's entries (row-major) are in the value arrays: the 4 blocks (aa, ab, ba,
  // bb) of every pair in order, then every coupling block, then the diagonal block of every point.
  // A block's rows are not adjacent in the per-point layout (see coordIndex), so each entry has its
  // own slot.
  std::vector<BlockSlots> blockSlots;
  // The pairs of the pair terms, in order, as the pattern was made for (model/term.h pairsAt).
  std::vector<std::pair<int, int>> pairs;
  // How many coupling blocks the terms have (model/term.h couplings; after the pairs' blocks in
  // blockSlots), and each one's row point.
  std::size_t couplings = 0;
  std::vector<int> couplingRows;
  std::vector<Block3> pointP,
      pointV;  // scratch: each point's diagonal block, summed over the terms
};
void accelerationJacobian(const Model& model, const double* p, const double* v, const Pull* pull,
                          AccelerationJacobian* out);

// The Newton matrix of an implicit step, N = I - cv dA/dv - cp dA/dp (backward Euler: cv = dt,
// cp = dt^2), kept as its blocks: a pair's four blocks are +B, -B, -B, +B of one block B, which
// is stored once, and each point's diagonal block (the identity, its point terms' blocks) once.
// Its product with a vector reads each block once: a third of the data of the sparse matrix,
// which stores every pair's block four times with an index per entry.
struct NewtonBlocks {
  std::vector<std::pair<int, int>> pairs;  // (a, b), in the pair terms' order
  std::vector<Block3> pair;                // B of each pair
  std::vector<Block3> point;               // each point's diagonal block, I included
  // The coupling terms' blocks (model/term.h couplings): N's block (row, column), in the terms'
  // order, scaled as B is.
  std::vector<std::pair<int, int>> couplings;
  std::vector<Block3> coupling;
  // Empty when every point has the same mass (then B holds 1 / mass); else 1 / each point's mass,
  // which scales B in the rows of the point (B then in force units).
  std::vector<double> rowScale;
  std::vector<Block3> pointP, pointV;  // scratch: the point terms' blocks, summed
  // The model's pinned points: their rows of dA are zero, so their rows of N are the identity's
  // (the blocks above still hold what the terms gave, multiply() and diagonal() override them).
  std::vector<int> pinned;
  int points() const { return static_cast<int>(point.size()); }
  // y = N x; x and y are per-point arrays of the points' 3n doubles, not the same.
  void multiply(const double* x, double* y) const;
  // The diagonal of N, a per-point array.
  void diagonal(double* d) const;
};
void newtonBlocks(const Model& model, const double* p, const double* v, const Pull* pull, double cv,
                  double cp, NewtonBlocks* out);
// N as a sparse matrix (the direct solver's fallback, the tests).
SparseMatrix sparseOf(const NewtonBlocks& blocks);

}  // namespace jello
