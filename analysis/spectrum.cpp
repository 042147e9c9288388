// spectrum.cpp: Lanczos iterations through Spectra, and the mirror-symmetric block solve.

#include "analysis/spectrum.h"

#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Spectra/SymEigsShiftSolver.h>
#include <Spectra/SymEigsSolver.h>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "core/assert.h"

namespace jello {

namespace {

// Spectra's defaults: a Ritz value has converged when its residual is below kTolerance times its
// size. Restarts are cheap here (one sparse product per basis vector): kMaxRestarts only stops a
// run that would never converge.
constexpr double kTolerance = 1e-10;
constexpr int kMaxRestarts = 1000;

// The Krylov basis Spectra keeps: twice the eigenvalues wanted and some, as its manual advises;
// fewer restarts for a little more memory.
int basisSize(int count, Eigen::Index n) {
  return static_cast<int>(std::min<Eigen::Index>(n, 2 * count + 20));
}

// Spectra's shift-solve operation, y = (matrix - shift I)^-1 x, by a sparse LDL^T factorisation
// (about twice as fast here as Spectra's own SparseLU, and its pivots give the inertia).
class ShiftSolve {
 public:
  using Scalar = double;
  explicit ShiftSolve(const SparseMatrix& matrix) : matrix_(matrix) {}
  Eigen::Index rows() const { return matrix_.rows(); }
  Eigen::Index cols() const { return matrix_.cols(); }
  void set_shift(double shift) {
    SparseMatrix identity(rows(), cols());
    identity.setIdentity();
    factor_.compute(SparseMatrix(matrix_ - shift * identity));
  }
  void perform_op(const double* in, double* out) const {
    Eigen::Map<Eigen::VectorXd>(out, rows()) =
        factor_.solve(Eigen::Map<const Eigen::VectorXd>(in, rows()));
  }
  // False when a pivot was zero or not finite: the shift is (numerically) an eigenvalue.
  bool factorised() const {
    return factor_.info() == Eigen::Success && factor_.vectorD().allFinite() &&
           (factor_.vectorD().array() != 0).all();
  }
  int negativePivots() const { return static_cast<int>((factor_.vectorD().array() < 0).count()); }

 private:
  const SparseMatrix& matrix_;
  Eigen::SimplicialLDLT<SparseMatrix> factor_;
};

// Below this many unknowns every eigenpair comes from one dense solve: cheaper than Lanczos at
// that size, and Lanczos cannot give n - 1 or more pairs of n (a body of 8 points has 24).
constexpr Eigen::Index kDenseBelow = 300;

bool solvesDensely(const SparseMatrix& matrix, int count) {
  return matrix.rows() < kDenseBelow || count >= matrix.rows() - 1;
}

// Every eigenpair of `matrix` from one dense solve; none when it fails.
std::optional<Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>> denseSolve(
    const SparseMatrix& matrix) {
  const Eigen::MatrixXd dense(matrix);
  if (!dense.allFinite()) return std::nullopt;
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(dense);
  if (solver.info() != Eigen::Success) return std::nullopt;
  return solver;
}

// The `count` eigenpairs of a dense solve whose key(value) comes first, largest first; values
// descending, as every Eigenpairs.
template <class Key>
Eigenpairs denseChoice(const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>& solver, int count,
                       Key key) {
  const Eigen::VectorXd& values = solver.eigenvalues();
  std::vector<Eigen::Index> order(static_cast<std::size_t>(values.size()));
  for (std::size_t n = 0; n < order.size(); ++n) order[n] = static_cast<Eigen::Index>(n);
  std::stable_sort(order.begin(), order.end(),
                   [&](Eigen::Index a, Eigen::Index b) { return key(values[a]) > key(values[b]); });
  order.resize(std::min(order.size(), static_cast<std::size_t>(std::max(count, 0))));
  std::sort(order.begin(), order.end(),
            [&](Eigen::Index a, Eigen::Index b) { return values[a] > values[b]; });
  const auto chosen = static_cast<Eigen::Index>(order.size());
  Eigenpairs pairs{Eigen::VectorXd(chosen), Eigen::MatrixXd(values.size(), chosen)};
  for (Eigen::Index n = 0; n < chosen; ++n) {
    pairs.values[n] = values[order[static_cast<std::size_t>(n)]];
    pairs.vectors.col(n) = solver.eigenvectors().col(order[static_cast<std::size_t>(n)]);
  }
  return pairs;
}

// Spectra reports some failures by throwing (its tridiagonal solve of a matrix with entries
// beyond a double's range): a failed solve, never an error of its own words.
template <class Solve>
auto guarded(Solve solve) -> decltype(solve()) {
  try {
    return solve();
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

}  // namespace

std::optional<Eigenpairs> largestEigenpairs(const SparseMatrix& matrix, int count) {
  JELLO_ASSERT(count > 0);
  if (solvesDensely(matrix, count)) {
    auto solver = denseSolve(matrix);
    if (!solver) return std::nullopt;
    return denseChoice(*solver, count, [](double v) { return v; });
  }
  return guarded([&]() -> std::optional<Eigenpairs> {
    Spectra::SparseSymMatProd<double> product(matrix);
    Spectra::SymEigsSolver<Spectra::SparseSymMatProd<double>> solver(
        product, count, basisSize(count, matrix.rows()));
    solver.init();
    solver.compute(Spectra::SortRule::LargestAlge, kMaxRestarts, kTolerance);
    if (solver.info() != Spectra::CompInfo::Successful) return std::nullopt;
    return Eigenpairs{solver.eigenvalues(), solver.eigenvectors()};
  });
}

namespace {

// Shift-and-invert Lanczos: the `count` eigenpairs whose 1 / (lambda - shift) comes first by
// `rule`, and the number of negative pivots of matrix - shift I (its eigenvalues below the shift).
std::optional<AboveShift> shiftInverted(const SparseMatrix& matrix, double shift, int count,
                                        Spectra::SortRule rule) {
  JELLO_ASSERT(count > 0);
  if (solvesDensely(matrix, count)) {
    auto solver = denseSolve(matrix);
    if (!solver) return std::nullopt;
    const bool magnitude = rule == Spectra::SortRule::LargestMagn;
    Eigenpairs pairs = denseChoice(*solver, count, [&](double v) {
      return magnitude ? std::fabs(1 / (v - shift)) : 1 / (v - shift);
    });
    return AboveShift{std::move(pairs),
                      static_cast<int>((solver->eigenvalues().array() < shift).count())};
  }
  return guarded([&]() -> std::optional<AboveShift> {
    ShiftSolve inverse(matrix);
    // The solver's constructor factorises matrix - shift I.
    Spectra::SymEigsShiftSolver<ShiftSolve> solver(inverse, count, basisSize(count, matrix.rows()),
                                                   shift);
    if (!inverse.factorised()) return std::nullopt;
    solver.init();
    solver.compute(rule, kMaxRestarts, kTolerance);
    if (solver.info() != Spectra::CompInfo::Successful) return std::nullopt;
    return AboveShift{{solver.eigenvalues(), solver.eigenvectors()}, inverse.negativePivots()};
  });
}

}  // namespace

std::optional<AboveShift> eigenpairsAbove(const SparseMatrix& matrix, double shift, int count) {
  // 1 / (lambda - shift) is largest for the eigenvalues just above the shift; those below it
  // give negative values, left out.
  return shiftInverted(matrix, shift, count, Spectra::SortRule::LargestAlge);
}

std::optional<Eigenpairs> eigenpairsNear(const SparseMatrix& matrix, double shift, int count) {
  // 1 / (lambda - shift) is largest in size for the eigenvalues nearest the shift, on both sides.
  std::optional<AboveShift> near =
      shiftInverted(matrix, shift, count, Spectra::SortRule::LargestMagn);
  if (!near) return std::nullopt;
  return std::move(near->pairs);
}

RitzPairs ritzPairs(const SparseMatrix& matrix, const Eigen::VectorXd& start, int steps) {
  JELLO_ASSERT(steps > 0 && start.size() == matrix.rows());
  steps = static_cast<int>(std::min<Eigen::Index>(steps, matrix.rows()));  // a small body's all
  Eigen::MatrixXd basis(matrix.rows(), steps);
  Eigen::VectorXd diagonal(steps), offDiagonal(steps);
  basis.col(0) = start.normalized();
  int size = 0;
  while (size < steps) {
    const int j = size++;
    Eigen::VectorXd next = matrix * basis.col(j);
    diagonal[j] = basis.col(j).dot(next);
    // Against every earlier vector, twice: the basis stays orthonormal to rounding, so no
    // spurious copies of converged values appear.
    for (int pass = 0; pass < 2; ++pass)
      next.noalias() -= basis.leftCols(size) * (basis.leftCols(size).transpose() * next);
    offDiagonal[j] = next.norm();
    // Zero: the space is invariant, every Ritz pair exact.
    if (!(offDiagonal[j] > kTolerance * std::fabs(diagonal[j]))) break;
    if (size < steps) basis.col(size) = next / offDiagonal[j];
  }
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> tridiagonal;
  tridiagonal.computeFromTridiagonal(diagonal.head(size), offDiagonal.head(size - 1));
  // Each Ritz vector's residual is the last off-diagonal times its last coordinate.
  const Eigen::VectorXd residuals =
      (offDiagonal[size - 1] * tridiagonal.eigenvectors().row(size - 1)).cwiseAbs().transpose();
  // Ascending from the solver: reversed, as every Eigenpairs.
  return RitzPairs{{tridiagonal.eigenvalues().reverse(),
                    basis.leftCols(size) * tridiagonal.eigenvectors().rowwise().reverse()},
                   residuals.reverse()};
}

namespace {

constexpr int kMirrors = 3;                         // x, y, z
constexpr int kSectors = 1 << kMirrors;             // even or odd under each mirror
constexpr int kHalf = kLatticeSize / 2;             // an orbit's representative: i, j, k < kHalf
constexpr int kSectorSize = kNumCoords / kSectors;  // 192 unknowns a block
static_assert(kLatticeSize % 2 == 0, "no point lies on a mirror: every orbit has 8 points");

// A basis vector: kSectors entries of +-1/sqrt(kSectors), one on each mirror image of a point.
struct MirrorVector {
  std::array<int, kSectors> coordinate;
  std::array<double, kSectors> value;
};

// The orthonormal basis, kSectorSize vectors a sector, one per (representative point, axis):
// the sum over the 8 mirror images g of chi(g) g(e), where e moves the representative along the
// axis, g(e) moves its image (negated along each of g's mirrors' axes) and chi(g) = -1 for each
// of g's mirrors the sector is odd under. Each vector is even or odd under every mirror, so a
// matrix commuting with the mirrors maps it into its own sector.
std::vector<MirrorVector> mirrorBasis(int sector) {
  std::vector<MirrorVector> basis;
  const double scale = 1 / std::sqrt(double(kSectors));
  for (int i = 0; i < kHalf; ++i)
    for (int j = 0; j < kHalf; ++j)
      for (int k = 0; k < kHalf; ++k)
        for (int axis = 0; axis < 3; ++axis) {
          MirrorVector v;
          for (int mirrors = 0; mirrors < kSectors; ++mirrors) {
            const std::array<int, 3> at = {i, j, k};
            std::array<int, 3> image = at;
            double sign = scale;
            for (int m = 0; m < kMirrors; ++m) {
              if (!(mirrors >> m & 1)) continue;
              image[m] = kLatticeSize - 1 - at[m];
              if (m == axis) sign = -sign;        // the displacement is mirrored too
              if (sector >> m & 1) sign = -sign;  // odd under this mirror
            }
            v.coordinate[mirrors] = coordIndex(pointIndex(image[0], image[1], image[2]), axis);
            v.value[mirrors] = sign;
          }
          basis.push_back(v);
        }
  return basis;
}

// basis^T matrix basis, dense: each column from the matrix times one basis vector (8 of the
// matrix's sparse columns), dotted with every basis vector of the sector.
Eigen::MatrixXd projected(const SparseMatrix& matrix, const std::vector<MirrorVector>& basis) {
  const int size = static_cast<int>(basis.size());
  Eigen::MatrixXd block(size, size);
  Eigen::VectorXd image = Eigen::VectorXd::Zero(matrix.rows());
  for (int c = 0; c < size; ++c) {
    image.setZero();
    for (int e = 0; e < kSectors; ++e)
      for (SparseMatrix::InnerIterator it(matrix, basis[c].coordinate[e]); it; ++it)
        image[it.row()] += it.value() * basis[c].value[e];
    for (int r = 0; r < size; ++r) {
      double sum = 0;
      for (int e = 0; e < kSectors; ++e) sum += basis[r].value[e] * image[basis[r].coordinate[e]];
      block(r, c) = sum;
    }
  }
  return block;
}

}  // namespace

namespace {

// The 8 sectors' blocks of `matrix` and their bases; nothing when the blocks do not hold all of
// the matrix (it does not commute with the mirrors: the squared norms differ by more than
// kCommuting of the matrix's, where rounding alone leaves about 1e-16).
constexpr double kCommuting = 1e-12;
struct MirrorBlocks {
  std::array<std::vector<MirrorVector>, kSectors> bases;
  std::array<Eigen::MatrixXd, kSectors> blocks;
};
std::optional<MirrorBlocks> mirrorBlocks(const SparseMatrix& matrix) {
  JELLO_ASSERT(matrix.rows() == kNumCoords && matrix.cols() == kNumCoords);
  MirrorBlocks out;
  double inBlocks = 0;
  for (int s = 0; s < kSectors; ++s) {
    out.bases[s] = mirrorBasis(s);
    out.blocks[s] = projected(matrix, out.bases[s]);
    inBlocks += out.blocks[s].squaredNorm();
  }
  // The basis is orthonormal: the blocks hold all of a commuting matrix.
  if (std::fabs(matrix.squaredNorm() - inBlocks) > kCommuting * matrix.squaredNorm())
    return std::nullopt;
  return out;
}

}  // namespace

Eigen::VectorXd mirrorSymmetricEigenvalues(const SparseMatrix& matrix) {
  const std::optional<MirrorBlocks> split = mirrorBlocks(matrix);
  JELLO_ASSERT(split);
  Eigen::VectorXd values(kNumCoords);
  for (int s = 0; s < kSectors; ++s) {
    values.segment(s * kSectorSize, kSectorSize) =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(split->blocks[s], Eigen::EigenvaluesOnly)
            .eigenvalues();
  }
  std::sort(values.begin(), values.end());
  return values;
}

std::optional<Eigenquotients> mirrorSymmetricQuotients(const SparseMatrix& matrix,
                                                       const SparseMatrix& other) {
  const std::optional<MirrorBlocks> split = mirrorBlocks(matrix), otherSplit = mirrorBlocks(other);
  if (!split || !otherSplit) return std::nullopt;
  Eigenquotients out{Eigen::VectorXd(kNumCoords), Eigen::VectorXd(kNumCoords)};
  for (int s = 0; s < kSectors; ++s) {
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> block(split->blocks[s]);
    const Eigen::MatrixXd& y = block.eigenvectors();
    // y's columns are unit vectors of the sector's orthonormal basis: their quotients of `other`
    // are those of its block.
    out.values.segment(s * kSectorSize, kSectorSize) = block.eigenvalues();
    out.quotients.segment(s * kSectorSize, kSectorSize) =
        (y.transpose() * otherSplit->blocks[s] * y).diagonal();
  }
  return out;
}

}  // namespace jello
