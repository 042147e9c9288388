// analysis/modes.cpp: a world's modes linearised at a state (modes.h): Lanczos iterations from
// both ends of the spectrum and inside it, the mirror blocks of a symmetric state, the rest
// lattice solved once and scaled, and the row-sum bound of a large body.

#include "analysis/modes.h"

#include <sys/stat.h>
#include <unistd.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <fstream>
#include <future>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <sstream>

#include "analysis/spectrum.h"
#include "analysis/steplimits.h"
#include "core/output.h"
#include "core/plot.h"
#include "core/progress.h"
#include "model/scenespec.h"
#include "solver/guard.h"
#include "solver/integrators.h"
#include "solver/jacobian.h"
#include "solver/simulation.h"

namespace jello {

namespace {

constexpr double kWallPress = 1e-3;  // m: how far the face is pressed into the wall
constexpr double kRigid = 1e-9;      // |omega^2| below this fraction of the largest: a rigid motion

// The fastest modes are taken kFastModes at first, and twice as many while the slowest of them
// is still within kCluster of the fastest's omega^2: the set then ends inside a cluster of modes
// about as fast, each damped its own way (a stiff wall's 64 contact modes, all faster than the
// springs'), and one just beyond it may limit an integrator more.
constexpr int kFastModes = 24;
constexpr int kMostFastModes = 192;
constexpr double kCluster = 0.97;
// The slowest oscillating modes taken, beyond the rigid motions (at most 6), which the same
// window above -rigid finds.
constexpr int kSlowModes = 24;
constexpr int kRigidMotions = 6;
constexpr int kMostSlowModes = 384;

// -(m + m^T) / 2: the symmetric part of an acceleration Jacobian, negated, so that a restoring
// stiffness is positive.
SparseMatrix negatedSymmetricPart(const SparseMatrix& m) {
  return SparseMatrix(-0.5 * (m + SparseMatrix(m.transpose())));
}

// The matrix on the free coordinates: a pinned point's rows and columns zeroed. Its rows of the
// Jacobian are zero already (it does not accelerate), but the symmetric part would take half of
// its column, coupling a point that cannot move: spurious modes, some of them "growing". With
// both zeroed its coordinates are zero eigenvalues, left out with the rigid motions.
SparseMatrix withoutPinned(SparseMatrix m, const std::vector<int>& pinned) {
  if (pinned.empty()) return m;
  const std::vector<char> isPinned = pinnedCoordinates(pinned, static_cast<int>(m.rows() / 3));
  m.prune([&](Eigen::Index row, Eigen::Index column, double) {
    return !isPinned[row] && !isPinned[column];
  });
  return m;
}

bool allFinite(const SparseMatrix& m) {
  return std::all_of(m.valuePtr(), m.valuePtr() + m.nonZeros(),
                     [](double x) { return std::isfinite(x); });
}

// The smallest over the rows of a_ii - sum over j != i of |a_ij| and the largest of a_ii + that
// sum: every eigenvalue of the symmetric matrix lies between them (Gershgorin's circles).
struct Interval {
  double lower, upper;
};
Interval gershgorin(const SparseMatrix& m) {
  Eigen::VectorXd diagonal = Eigen::VectorXd::Zero(m.rows()), off = diagonal;
  for (Eigen::Index column = 0; column < m.outerSize(); ++column)
    for (SparseMatrix::InnerIterator it(m, column); it; ++it)
      (it.row() == column ? diagonal[it.row()] : off[it.row()]) +=
          it.row() == column ? it.value() : std::fabs(it.value());
  return {(diagonal - off).minCoeff(), (diagonal + off).maxCoeff()};
}

// Adds a mode to `out`, with its highest frequency and damping range.
void addMode(const Mode& mode, Linearisation* out) {
  out->modes.push_back(mode);
  out->highestFrequency = std::max(out->highestFrequency, std::sqrt(mode.omegaSquared));
  out->lowestDamping = std::min(out->lowestDamping, mode.damping);
  out->highestDamping = std::max(out->highestDamping, mode.damping);
}

// Adds the eigenpairs' modes to `out` (omega^2 above `rigid`; the damping rate along each
// eigenvector), with their highest frequency and damping range.
void addModes(const Eigenpairs& pairs, const SparseMatrix& damping, double rigid,
              Linearisation* out) {
  for (Eigen::Index i = 0; i < pairs.values.size(); ++i) {
    const double w2 = pairs.values[i];
    if (w2 <= rigid) continue;
    const Eigen::VectorXd phi = pairs.vectors.col(i);
    addMode({w2, phi.dot(damping * phi)}, out);
  }
}

// A body of more unknowns than the course cube's is not factorised: the sparse LDL^T of a 3D
// lattice fills in (its cost grows faster than n^2), and a 10x10x10 lattice's analysis took 4 s,
// a 16^3 lattice's 147 s. Its slow modes come from Lanczos iterations, and no window inside the
// spectrum is opened (addInteriorModes' exact modes need the factorisation).
constexpr Eigen::Index kLargestFactorised = kNumCoords;
bool factorisable(const SparseMatrix& stiffness) { return stiffness.rows() <= kLargestFactorised; }

// The slowest modes without a factorisation: the largest eigenpairs of top I - stiffness, top
// Gershgorin's bound above every eigenvalue, are the stiffness's smallest. The growing modes are
// those among them below -rigid (all of them while fewer than those taken).
std::optional<AboveShift> slowestModesByLanczos(const SparseMatrix& stiffness, double rigid) {
  const double top = gershgorin(stiffness).upper;
  SparseMatrix identity(stiffness.rows(), stiffness.cols());
  identity.setIdentity();
  const SparseMatrix flipped = top * identity - stiffness;
  const int count = std::min<Eigen::Index>(kSlowModes + kRigidMotions, stiffness.rows() / 2);
  std::optional<Eigenpairs> pairs = largestEigenpairs(flipped, count);
  if (!pairs) return std::nullopt;
  AboveShift out;
  out.pairs.values = top - pairs->values.array();
  out.pairs.vectors = pairs->vectors;
  out.below = static_cast<int>((out.pairs.values.array() < -rigid).count());
  return out;
}

// The slowest oscillating modes: the eigenpairs just above -rigid, in a window widened until it
// holds kSlowModes beyond the rigid motions; and the count of growing modes (eigenvalues below
// -rigid), all of them, from the factorisation's inertia.
std::optional<AboveShift> slowestModes(const SparseMatrix& stiffness, double rigid) {
  if (!factorisable(stiffness)) return slowestModesByLanczos(stiffness, rigid);
  for (int count = kSlowModes + kRigidMotions;; count *= 2) {
    std::optional<AboveShift> slow = eigenpairsAbove(stiffness, -rigid, count);
    if (!slow) return std::nullopt;
    const auto oscillating = (slow->pairs.values.array() > rigid).count();
    if (oscillating >= kSlowModes || 2 * count > kMostSlowModes) return slow;
  }
}

// Explicit Euler's limit for a mode is about (c + kHorizonRate) / omega^2, so a mode inside the
// spectrum damped less for its speed than those at its ends can set it: a strained corner's (the
// tension across its springs is stiffness no damper follows), the cube's on deep contact springs
// (damped less for their stiffness than the lattice's springs). Such a mode lives where a point's
// own stiffness is damped least for its size, and is looked for from there (addInteriorModes):
//  - a start vector weighted to those points (hotspotStart);
//  - kRitzSteps Lanczos steps from it: a Ritz pair inside the spectrum is a mixture of the
//    eigenvectors near its value, dominated by those the start weighs most, so one whose own Euler
//    limit is below the modes' points at the frequency of such a mode;
//  - the kWindowModes eigenpairs nearest that frequency, exactly (shift-invert), added to the
//    modes; again while a Ritz pair outside the windows promises a lower limit than the modes'
//    (at most kMostWindows).
// Every mode added is an eigenpair of the stiffness, so a limit only comes nearer the one of every
// mode. The windows, the costly part, open only where a Ritz pair promises a lower limit.
constexpr double kHorizonRate = 2 * 0.6931471805599453 / kHorizon;  // 1/s: 2 ln 2 / kHorizon
constexpr int kRitzSteps = 100;
constexpr int kWindowModes = 24;
constexpr int kMostWindows = 2;
constexpr double kHotspotPower = 4;  // how sharply the start favours the least damped points
constexpr double kStartNoise = 0.3;  // a little of every coordinate, in case no point stands out

// Each point's direction in which its own 3x3 stiffness block is damped least for its size, and
// that ratio (s: (c + kHorizonRate) / k along it); infinite where the block is not positive.
struct LocalRatios {
  std::vector<double> ratio;
  std::vector<Eigen::Vector3d> direction;
};
LocalRatios localRatios(const SparseMatrix& stiffness, const SparseMatrix& damping) {
  const int n = static_cast<int>(stiffness.rows() / 3);
  LocalRatios out{std::vector<double>(n, INFINITY),
                  std::vector<Eigen::Vector3d>(n, Eigen::Vector3d::Zero())};
  for (int q = 0; q < n; ++q) {
    Eigen::Matrix3d k, c;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        k(a, b) = stiffness.coeff(coordIndex(q, a, n), coordIndex(q, b, n));
        c(a, b) = damping.coeff(coordIndex(q, a, n), coordIndex(q, b, n));
      }
    // k v = s (c + rate) v: the largest s is the least damped direction, 1 / s its ratio.
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix3d> local(
        k, c + kHorizonRate * Eigen::Matrix3d::Identity());
    if (local.info() != Eigen::Success || !(local.eigenvalues()[2] > 0)) continue;
    out.ratio[q] = 1 / local.eigenvalues()[2];
    out.direction[q] = local.eigenvectors().col(2).normalized();
  }
  return out;
}

// The start vector: each point's least damped direction weighted by (best ratio / its
// ratio)^kHotspotPower, plus kStartNoise of a fixed pseudo-random vector.
Eigen::VectorXd hotspotStart(const SparseMatrix& stiffness, const SparseMatrix& damping) {
  const LocalRatios local = localRatios(stiffness, damping);
  const double best = *std::min_element(local.ratio.begin(), local.ratio.end());
  const int n = static_cast<int>(stiffness.rows() / 3);
  Eigen::VectorXd start = Eigen::VectorXd::Zero(3 * n), noise(3 * n);
  for (int q = 0; q < n && std::isfinite(best); ++q)
    for (int a = 0; a < 3; ++a)
      start[coordIndex(q, a, n)] =
          std::pow(best / local.ratio[q], kHotspotPower) * local.direction[q][a];
  unsigned seed = 12345;  // a linear congruential generator: the same vector every run
  for (Eigen::Index i = 0; i < noise.size(); ++i) {
    seed = seed * 1103515245u + 12345u;
    noise[i] = double(seed >> 8) / double(1u << 24) - 0.5;
  }
  if (start.norm() > 0) start.normalize();
  return start + kStartNoise * noise.normalized();
}

// The Ritz pairs from hotspotStart. The converged ones (residual within Spectra's tolerance) are
// eigenpairs: added to `out` as modes. The others are returned as (their Euler limit in s, omega^2
// in 1/s^2), lowest limit first.
std::vector<std::pair<double, double>> ritzCandidates(const SparseMatrix& stiffness,
                                                      const SparseMatrix& damping, double rigid,
                                                      Linearisation* out) {
  constexpr double kConverged = 1e-10;  // residual / |omega^2|
  const RitzPairs ritz = ritzPairs(stiffness, hotspotStart(stiffness, damping), kRitzSteps);
  std::vector<std::pair<double, double>> candidates;
  for (Eigen::Index i = 0; i < ritz.pairs.values.size(); ++i) {
    const double w2 = ritz.pairs.values[i];
    if (w2 <= rigid) continue;
    if (ritz.residuals[i] <= kConverged * w2) {
      addModes({ritz.pairs.values.segment(i, 1), ritz.pairs.vectors.col(i)}, damping, rigid, out);
      continue;
    }
    const Eigen::VectorXd y = ritz.pairs.vectors.col(i);
    candidates.push_back({criticalStep(Integrator::Euler, {Mode{w2, y.dot(damping * y)}}), w2});
  }
  std::sort(candidates.begin(), candidates.end());
  return candidates;
}

// Adds the modes inside the spectrum that may set explicit Euler's limit (see above) to `out`,
// which holds those at its ends; `rigid` as there.
void addInteriorModes(const SparseMatrix& stiffness, const SparseMatrix& damping, double rigid,
                      Linearisation* out) {
  const std::vector<std::pair<double, double>> candidates =
      ritzCandidates(stiffness, damping, rigid, out);
  double limit = criticalStep(Integrator::Euler, out->modes);
  std::vector<std::pair<double, double>> windows;  // omega^2 from, to
  for (const auto& [h, w2] : candidates) {
    // Lowest first: once one promises no lower limit, none after it does.
    if (h >= limit || static_cast<int>(windows.size()) == kMostWindows) break;
    // Its eigenvectors, the window's modes, are known already.
    if (std::any_of(windows.begin(), windows.end(), [w2 = w2](const auto& window) {
          return window.first <= w2 && w2 <= window.second;
        }))
      continue;
    const std::optional<Eigenpairs> window = eigenpairsNear(stiffness, w2, kWindowModes);
    if (!window) continue;
    windows.push_back({window->values.minCoeff(), window->values.maxCoeff()});
    addModes(*window, damping, rigid, out);
    limit = criticalStep(Integrator::Euler, out->modes);
  }
}

// The modes at both ends of the spectrum, by Lanczos iterations, and those inside it that may set
// explicit Euler's limit. The fastest set the limits of the integrators stable on undamped modes
// (RK4's is 2.83 / omega), and every limit where the modes are damped alike. Explicit Euler's and
// the midpoint rule's follow each mode's damping ratio (Euler's is about c / omega^2), so a mode
// damped less for its speed than the rest sets them: the slowest, at a wall (the cube on its
// contact springs) or in a collapsed cube; one in the middle of the spectrum (a strained
// corner's: addInteriorModes). Nothing when an iteration does not converge.
std::optional<Linearisation> lineariseByLanczos(const SparseMatrix& stiffness,
                                                const SparseMatrix& damping) {
  std::optional<Eigenpairs> fast = largestEigenpairs(stiffness, kFastModes);
  if (!fast) return std::nullopt;
  // The dense analysis's threshold: kRigid of the largest eigenvalue in size; a growing mode
  // larger than the fastest is looked for below.
  double rigid = kRigid * std::fabs(fast->values[0]);
  std::optional<AboveShift> slow = slowestModes(stiffness, rigid);
  if (!slow) return std::nullopt;
  // No eigenvalue lies below the smallest a_ii - sum |a_ij| of a row (Gershgorin): only when that
  // is below minus the fastest's can a growing mode be the larger.
  if (slow->below > 0 && -gershgorin(stiffness).lower > std::fabs(fast->values[0])) {
    std::optional<Eigenpairs> mostNegative = largestEigenpairs(-stiffness, 1);
    if (!mostNegative) return std::nullopt;
    if (mostNegative->values[0] > std::fabs(fast->values[0])) {
      rigid = kRigid * mostNegative->values[0];
      if (!(slow = slowestModes(stiffness, rigid))) return std::nullopt;
    }
  }
  // (A body too large to factorise keeps the first set: its spectrum's top is one long cluster.)
  while (factorisable(stiffness) && fast->values.size() < kMostFastModes &&
         fast->values[fast->values.size() - 1] > kCluster * fast->values[0]) {
    fast = largestEigenpairs(stiffness, static_cast<int>(2 * fast->values.size()));
    if (!fast) return std::nullopt;
  }
  Linearisation out;
  out.lowestDamping = INFINITY;
  addModes(*fast, damping, rigid, &out);
  addModes(slow->pairs, damping, rigid, &out);
  out.growing = slow->below;
  if (!out.modes.empty() && factorisable(stiffness))
    addInteriorModes(stiffness, damping, rigid, &out);
  if (out.modes.empty()) out.lowestDamping = 0;
  return out;
}

// The analysis as it was: a dense eigensolver on the whole stiffness (seconds), every mode.
// Only when a Lanczos iteration fails.
Linearisation lineariseDensely(const SparseMatrix& stiffness, const SparseMatrix& damping) {
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver{Eigen::MatrixXd(stiffness)};
  Linearisation out;
  out.lowestDamping = INFINITY;
  const double rigid = kRigid * solver.eigenvalues().cwiseAbs().maxCoeff();
  out.growing = static_cast<int>((solver.eigenvalues().array() < -rigid).count());
  out.allModes = true;
  addModes({solver.eigenvalues(), solver.eigenvectors()}, damping, rigid, &out);
  if (out.modes.empty()) out.lowestDamping = 0;
  return out;
}

// Every mode, as the dense analysis took them, from the eigenvalues of the stiffness and the
// damping's quotients along its eigenvectors (mirrorSymmetricQuotients).
Linearisation everyMode(const Eigenquotients& all) {
  Linearisation out;
  out.lowestDamping = INFINITY;
  const double rigid = kRigid * all.values.cwiseAbs().maxCoeff();
  out.growing = static_cast<int>((all.values.array() < -rigid).count());
  out.allModes = true;
  for (Eigen::Index i = 0; i < all.values.size(); ++i)
    if (all.values[i] > rigid) addMode({all.values[i], all.quotients[i]}, &out);
  if (out.modes.empty()) out.lowestDamping = 0;
  return out;
}

// Gershgorin's interval for the symmetric part of N - I (N: `blocks`, newtonBlocks' matrix) on
// the coordinates not pinned, from its blocks alone: a 48^3 lattice's sparse Jacobian and its
// symmetric part took 1.2 GB and 10 s. The symmetric part's entry (|m_ij + m_ji|) / 2 is counted
// as (|m_ij| + |m_ji|) / 2, equal where the block is symmetric (a spring's stiffness at rest), so
// the interval holds the exact one. Where the points' masses differ (NewtonBlocks::rowScale), the
// matrix taken is M^(1/2) (N - I) M^(-1/2), of the same eigenvalues: a block joining points a and
// b is scaled by sqrt(s_a s_b), s = 1 / mass, and one on a point's diagonal by s.
// Row i of |B|, and column j.
double rowSum(const Block3& b, int i) {
  return std::fabs(b.m[3 * i]) + std::fabs(b.m[3 * i + 1]) + std::fabs(b.m[3 * i + 2]);
}
double columnSum(const Block3& b, int j) {
  return std::fabs(b.m[j]) + std::fabs(b.m[3 + j]) + std::fabs(b.m[6 + j]);
}
// Row (and column) i of (|B| + |B^T|) / 2.
double offSum(const Block3& b, int i) { return (rowSum(b, i) + columnSum(b, i)) / 2; }

// Each point's diagonal block of the matrix below and each coordinate's sum of its row's
// off-diagonal magnitudes outside that block.
struct GershgorinSums {
  std::vector<Block3> diagonal;
  std::vector<double> off;
};

// The coupling blocks' part (finite elements): (r, c) and (c, r) are listed apart; each adds half
// of its rows to r's sums and half of its columns to c's.
void addCouplingSums(const NewtonBlocks& blocks, const std::vector<char>& isPinned,
                     GershgorinSums* sums) {
  const int n = blocks.points();
  auto scale = [&](int q) { return blocks.rowScale.empty() ? 1.0 : blocks.rowScale[q]; };
  for (std::size_t k = 0; k < blocks.couplings.size(); ++k) {
    const auto [r, c] = blocks.couplings[k];
    const Block3& block = blocks.coupling[k];
    if (r == c) {
      for (int e = 0; e < 9; ++e) sums->diagonal[r].m[e] += scale(r) * block.m[e];
      continue;
    }
    if (isPinned[coordIndex(r, 0, n)] || isPinned[coordIndex(c, 0, n)]) continue;
    const double joint = std::sqrt(scale(r) * scale(c));
    for (int i = 0; i < 3; ++i) {
      sums->off[coordIndex(r, i, n)] += joint * rowSum(block, i) / 2;
      sums->off[coordIndex(c, i, n)] += joint * columnSum(block, i) / 2;
    }
  }
}

Interval blockInterval(const NewtonBlocks& blocks) {
  const int n = blocks.points();
  const std::vector<char> isPinned = pinnedCoordinates(blocks.pinned, n);
  auto scale = [&](int q) { return blocks.rowScale.empty() ? 1.0 : blocks.rowScale[q]; };
  GershgorinSums sums{blocks.point, std::vector<double>(3 * static_cast<std::size_t>(n), 0.0)};
  std::vector<Block3>& diagonal = sums.diagonal;  // a point's block of N - I: + B of its pairs
  for (Block3& d : diagonal)
    for (int axis = 0; axis < 3; ++axis) d.m[4 * axis] -= 1;
  for (std::size_t k = 0; k < blocks.pairs.size(); ++k) {
    const auto [a, b] = blocks.pairs[k];
    const Block3& block = blocks.pair[k];
    for (int e = 0; e < 9; ++e) {
      diagonal[a].m[e] += scale(a) * block.m[e];
      diagonal[b].m[e] += scale(b) * block.m[e];
    }
    if (isPinned[coordIndex(a, 0, n)] || isPinned[coordIndex(b, 0, n)]) continue;
    const double joint = std::sqrt(scale(a) * scale(b));
    for (int i = 0; i < 3; ++i) {
      sums.off[coordIndex(a, i, n)] += joint * offSum(block, i);
      sums.off[coordIndex(b, i, n)] += joint * offSum(block, i);
    }
  }
  addCouplingSums(blocks, isPinned, &sums);
  Interval out{INFINITY, -INFINITY};  // (empty when every point is pinned)
  for (int q = 0; q < n; ++q) {
    if (isPinned[coordIndex(q, 0, n)]) continue;
    for (int i = 0; i < 3; ++i) {
      const double centre = diagonal[q].m[4 * i];
      const double radius =
          sums.off[coordIndex(q, i, n)] + offSum(diagonal[q], i) - std::fabs(centre);
      if (!std::isfinite(centre + radius)) return {NAN, NAN};
      out.lower = std::min(out.lower, centre - radius);
      out.upper = std::max(out.upper, centre + radius);
    }
  }
  return out;
}

}  // namespace

// A step at which every mode of the state is stable, in a second for a 48^3 lattice instead of
// the analysis's minutes. Each mode's omega^2 (a Rayleigh quotient of the stiffness) is at most
// the top of its Gershgorin interval, and its damping rate lies within the damping's. Over that
// rectangle the limit has no simple extreme (it falls with omega^2 for a lightly damped mode and
// rises for an overdamped one, whose fast root tends to -c), so the smallest of a grid of modes
// is taken: omega^2 halved kRowSumOctaves times from the top, the damping at kRowSumDampings
// points across its interval.
constexpr int kRowSumOctaves = 16;
constexpr int kRowSumDampings = 8;
RowSumBound rowSumBound(const Model& model, const State& state, Integrator integrator) {
  NewtonBlocks blocks;  // N - I = -dA/dp, then -dA/dv
  newtonBlocks(model, state.p(), state.v(), nullptr, 0, 1, &blocks);
  const Interval stiffness = blockInterval(blocks);
  newtonBlocks(model, state.p(), state.v(), nullptr, 1, 0, &blocks);
  const Interval damping = blockInterval(blocks);
  if (std::isnan(stiffness.upper) || std::isnan(damping.upper)) return {NAN, NAN};
  if (stiffness.upper < stiffness.lower) return {INFINITY, 0};  // no coordinate free
  const double low = std::max(0.0, damping.lower), high = std::max(low, damping.upper);
  std::vector<Mode> grid;
  for (int octave = 0; octave < kRowSumOctaves; ++octave)
    for (int i = 0; i < kRowSumDampings; ++i)
      grid.push_back(
          {std::ldexp(stiffness.upper, -octave), low + (high - low) * i / (kRowSumDampings - 1)});
  return {criticalStep(integrator, grid), std::sqrt(std::max(0.0, stiffness.upper))};
}

// M^(1/2) A M^(-1/2) for the acceleration Jacobian A = M^-1 dF: the same eigenvalues, and
// symmetric where dF is (M^-1/2 dF M^-1/2), so that its symmetric part keeps them when the points'
// masses differ (a jelly of finite elements, jellies of different masses). Unchanged when every
// point has one mass.
SparseMatrix massSymmetric(const Model& model, SparseMatrix a) {
  if (model.commonMass != 0) return a;
  const int n = model.points();
  for (int column = 0; column < a.outerSize(); ++column)
    for (SparseMatrix::InnerIterator it(a, column); it; ++it)
      it.valueRef() *= std::sqrt(model.pointMass[it.row() % n] / model.pointMass[column % n]);
  return a;
}

Linearisation linearise(const Model& model, const State& state) {
  AccelerationJacobian jacobian;
  accelerationJacobian(model, state.p(), state.v(), nullptr, &jacobian);
  jacobian.dAdp = massSymmetric(model, std::move(jacobian.dAdp));
  jacobian.dAdv = massSymmetric(model, std::move(jacobian.dAdv));
  // An eigensolver on an inf or a NaN takes minutes to say nothing.
  if (!allFinite(jacobian.dAdp) || !allFinite(jacobian.dAdv)) {
    Linearisation out;
    out.finite = false;
    return out;
  }
  const SparseMatrix stiffness = withoutPinned(negatedSymmetricPart(jacobian.dAdp), model.pinned);
  const SparseMatrix damping = withoutPinned(negatedSymmetricPart(jacobian.dAdv), model.pinned);
  // A state the three mirrors of the lattice leave as it is (the rest lattice moved, or scaled
  // about its centre as tornado.w's compressed cube): every mode, exactly, from 8 blocks, in
  // less time than the Lanczos iterations. (A degenerate mode's eigenvector is any in its
  // space, here one within a block, as the dense solver's was one of its own choosing.)
  if (model.body().courseLattice)
    if (std::optional<Eigenquotients> all = mirrorSymmetricQuotients(stiffness, damping))
      return everyMode(*all);
  std::optional<Linearisation> ends = lineariseByLanczos(stiffness, damping);
  return ends ? *ends : lineariseDensely(stiffness, damping);
}

// The free lattice's modes at rest, scaled from the unit lattice's (see lineariseAtRest).
Linearisation freeLatticeAtRest(const World& world) {
  // Eigenvalues of the lattice with unit stiffness and unit mass, computed once: all of them,
  // by the lattice's mirror symmetries (spectrum.h), in milliseconds.
  static const Eigen::VectorXd unitLattice = [] {
    World unit;
    unit.kElastic = 1;
    unit.mass = 1;
    const State rest = restState(courseBody());
    Model model = makeModel(unit, rest);
    AccelerationJacobian jacobian;
    accelerationJacobian(model, rest.p(), rest.v(), nullptr, &jacobian);
    return mirrorSymmetricEigenvalues(negatedSymmetricPart(jacobian.dAdp));
  }();
  Linearisation out;
  // The springs' constants as the model has them: a scene may give every kind the same stiffness
  // by kind (stiffness = { structural = 800, shear = 800, bend = 800 }) and leave kElastic as it
  // was.
  const SpringConstants springs = springConstantsOf(world);
  const double k = springs.k[0], d = springs.d[0];
  if (!std::isfinite(k / world.mass) || !std::isfinite(d / world.mass)) {
    out.finite = false;
    return out;
  }
  out.lowestDamping = INFINITY;
  out.allModes = true;
  const double rigid = kRigid * unitLattice.cwiseAbs().maxCoeff();
  for (Eigen::Index i = 0; i < unitLattice.size(); ++i) {
    double mu = unitLattice[i];
    if (mu <= rigid) continue;
    Mode m{mu * k / world.mass, mu * d / world.mass};
    if (m.omegaSquared > 0) addMode(m, &out);
  }
  if (out.modes.empty()) out.lowestDamping = 0;
  return out;
}

Linearisation lineariseAtRest(const World& world) {
  // Pins change the lattice's modes (no rigid motions are left), and another body or springs of
  // different kinds have modes of their own: its springs and pins alone, at rest, through the
  // general analysis.
  if (!hasCourseSprings(world) || (world.scene && !world.scene->pinned.empty())) {
    World springs = world;
    auto bodyOnly = std::make_shared<SceneSpec>();
    bodyOnly->body = world.scene->body;
    bodyOnly->springs = world.scene->springs;
    bodyOnly->pinned = world.scene->pinned;
    bodyOnly->jellies = world.scene->jellies;  // each jelly's mass, springs and material
    bodyOnly->material = world.scene->material;
    bodyOnly->boundsPresent = false;
    springs.scene = bodyOnly;
    springs.hasPlane = false;
    springs.field = {};
    const State rest = restState(bodyOf(world));
    return linearise(makeModel(springs, rest), rest);
  }
  return freeLatticeAtRest(world);
}

State restState(const Body& body) {
  const int n = body.count();
  State s(n);
  for (int q = 0; q < n; ++q) store(s.p(), q, n, body.restPosition(q));
  return s;
}

State faceOnWallState(const Body& body) {
  State s = restState(body);
  for (int q = 0; q < body.count(); ++q)
    s.p()[coordIndex(q, 0, body.count())] += -kBoxHalfSize - kWallPress;
  return s;
}

}  // namespace jello
