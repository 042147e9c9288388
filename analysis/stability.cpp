// stability.cpp: predicted stable steps from the linearised forces.

#include "analysis/stability.h"

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
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "analysis/spectrum.h"
#include "core/output.h"
#include "core/plot.h"
#include "core/progress.h"
#include "model/scenespec.h"
#include "solver/guard.h"
#include "solver/integrators.h"
#include "solver/jacobian.h"
#include "solver/simulation.h"

namespace jello {

const std::vector<Integrator> kExplicitIntegrators = integratorsWithStepLimit();

namespace {

constexpr double kWallPress = 1e-3;  // m: how far the face is pressed into the wall
constexpr double kRigid = 1e-9;      // |omega^2| below this fraction of the largest: a rigid motion
constexpr double kLargestStep = 1.0;  // s: no limit beyond this is reported
// A mode counts as bounded when it grows by less than a factor of 2 over kHorizon: explicit
// Euler amplifies an undamped slow mode (a field's slight restoring force, say) at any step,
// but by so little that no run would see it.
constexpr double kHorizon = 10.0;  // s
constexpr int kBisections = 60;

// Spectral radius of the one-step map of x'' = -w2 x - c x' under `integrator` at step h,
// found by stepping the two unit states with the integrator's own code.
double spectralRadius(Integrator integrator, const Mode& mode, double h) {
  OdeSystem system;
  system.derivative = [&mode](const double* y, double* dydt) {
    dydt[0] = y[1];
    dydt[1] = -mode.omegaSquared * y[0] - mode.damping * y[1];
  };
  // RK45 with tolerances that accept any step: one Dormand-Prince step of exactly h.
  const Tolerances accept{1e300, 1e300};
  double m[2][2];
  for (int column = 0; column < 2; ++column) {
    std::vector<double> y{column == 0 ? 1.0 : 0.0, column == 1 ? 1.0 : 0.0};
    Stepper stepper(integrator, accept);
    stepper.step(system, y, h);
    m[0][column] = y[0];
    m[1][column] = y[1];
  }
  double trace = m[0][0] + m[1][1], det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
  std::complex<double> root = std::sqrt(std::complex<double>(trace * trace / 4 - det));
  return std::max(std::abs(trace / 2 + root), std::abs(trace / 2 - root));
}

bool stableAt(Integrator integrator, const Mode& mode, double h) {
  double radius = spectralRadius(integrator, mode, h);
  return std::isfinite(radius) && radius <= std::pow(2.0, h / kHorizon) * (1 + 1e-12);
}

double modeLimit(Integrator integrator, const Mode& mode) {
  if (stableAt(integrator, mode, kLargestStep)) return kLargestStep;
  double low = 0, high = kLargestStep;
  for (int i = 0; i < kBisections; ++i) {
    double middle = low == 0 ? high / 2 : std::sqrt(low * high);
    (stableAt(integrator, mode, middle) ? low : high) = middle;
    if (low > 0 && high / low < 1 + 1e-6) break;
  }
  return low;
}

// x rounded to an integer, clamped in floating point to long long's range first (NaN to 0): a
// mode of an extreme world (omega^2 or damping near 1e308) never reaches an undefined conversion.
long long roundedKey(double x) {
  constexpr double kLimit = 9e18;
  return std::isnan(x) ? 0 : std::llround(std::clamp(x, -kLimit, kLimit));
}

std::string number(double x) {
  if (std::isinf(x)) return "unbounded";
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", x);
  return text;
}

// --check's table: a line per integrator of the integrator table, its limits or "unbounded".
std::string limitTable(const StabilityReport& r) {
  std::string out =
      "\n  integrator   largest stable dt (s)   at the initial state   with a face on a wall\n";
  char line[256];
  for (std::size_t i = 0; i < kExplicitIntegrators.size(); ++i) {
    std::snprintf(line, sizeof line, "  %-12s %-23s %-22s %s\n",
                  integratorName(kExplicitIntegrators[i]), limitText(r.criticalRest[i]).c_str(),
                  limitText(r.criticalInitial[i]).c_str(),
                  r.courseWalls ? limitText(r.criticalFaceOnWall[i]).c_str() : "(no course walls)");
    out += line;
  }
  for (const IntegratorInfo& row : integratorTable()) {
    if (row.boundedStableStep) continue;
    std::snprintf(line, sizeof line, "  %-12s unbounded (A-stable)\n", row.name());
    out += line;
  }
  return out + "\n";
}

}  // namespace

namespace {

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
// the interval holds the exact one.
Interval blockInterval(const NewtonBlocks& blocks) {
  const int n = blocks.points();
  const std::vector<char> isPinned = pinnedCoordinates(blocks.pinned, n);
  std::vector<Block3> diagonal = blocks.point;  // a point's block of N - I: + B of its pairs
  for (Block3& d : diagonal)
    for (int axis = 0; axis < 3; ++axis) d.m[4 * axis] -= 1;
  std::vector<double> off(3 * static_cast<std::size_t>(n), 0.0);
  auto offSum = [](const Block3& b, int i) {  // row (and column) i of (|B| + |B^T|) / 2
    double sum = 0;
    for (int j = 0; j < 3; ++j) sum += (std::fabs(b.m[3 * i + j]) + std::fabs(b.m[3 * j + i])) / 2;
    return sum;
  };
  for (std::size_t k = 0; k < blocks.pairs.size(); ++k) {
    const auto [a, b] = blocks.pairs[k];
    const Block3& block = blocks.pair[k];
    for (int e = 0; e < 9; ++e) {
      diagonal[a].m[e] += block.m[e];
      diagonal[b].m[e] += block.m[e];
    }
    if (isPinned[coordIndex(a, 0, n)] || isPinned[coordIndex(b, 0, n)]) continue;
    for (int i = 0; i < 3; ++i) {
      off[coordIndex(a, i, n)] += offSum(block, i);
      off[coordIndex(b, i, n)] += offSum(block, i);
    }
  }
  Interval out{INFINITY, -INFINITY};  // (empty when every point is pinned)
  for (int q = 0; q < n; ++q) {
    if (isPinned[coordIndex(q, 0, n)]) continue;
    for (int i = 0; i < 3; ++i) {
      const double centre = diagonal[q].m[4 * i];
      const double radius = off[coordIndex(q, i, n)] + offSum(diagonal[q], i) - std::fabs(centre);
      if (!std::isfinite(centre + radius)) return {NAN, NAN};
      out.lower = std::min(out.lower, centre - radius);
      out.upper = std::max(out.upper, centre + radius);
    }
  }
  return out;
}

// A step at which every mode of the state is stable, in a second for a 48^3 lattice instead of
// the analysis's minutes. Each mode's omega^2 (a Rayleigh quotient of the stiffness) is at most
// the top of its Gershgorin interval, and its damping rate lies within the damping's. Over that
// rectangle the limit has no simple extreme (it falls with omega^2 for a lightly damped mode and
// rises for an overdamped one, whose fast root tends to -c), so the smallest of a grid of modes
// is taken: omega^2 halved kRowSumOctaves times from the top, the damping at kRowSumDampings
// points across its interval.
constexpr int kRowSumOctaves = 16;
constexpr int kRowSumDampings = 8;
struct RowSumBound {
  double limit;    // s; NaN where the derivatives are not finite, infinite if no point is free
  double fastest;  // rad/s: the square root of the stiffness's top
};
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

}  // namespace

Linearisation linearise(const Model& model, const State& state) {
  AccelerationJacobian jacobian;
  accelerationJacobian(model, state.p(), state.v(), nullptr, &jacobian);
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

namespace {

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
  if (!std::isfinite(world.kElastic / world.mass) || !std::isfinite(world.dElastic / world.mass)) {
    out.finite = false;
    return out;
  }
  out.lowestDamping = INFINITY;
  out.allModes = true;
  const double rigid = kRigid * unitLattice.cwiseAbs().maxCoeff();
  for (Eigen::Index i = 0; i < unitLattice.size(); ++i) {
    double mu = unitLattice[i];
    if (mu <= rigid) continue;
    Mode m{mu * world.kElastic / world.mass, mu * world.dElastic / world.mass};
    if (m.omegaSquared > 0) addMode(m, &out);
  }
  if (out.modes.empty()) out.lowestDamping = 0;
  return out;
}

}  // namespace

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
    bodyOnly->boundsPresent = false;
    springs.scene = bodyOnly;
    springs.hasPlane = false;
    springs.field = {};
    const State rest = restState(bodyOf(world));
    return linearise(makeModel(springs, rest), rest);
  }
  return freeLatticeAtRest(world);
}

double criticalStep(Integrator integrator, const std::vector<Mode>& modes) {
  if (!integratorInfo(integrator).boundedStableStep) return INFINITY;
  // The lattice's symmetry repeats modes; each distinct one (to 1e-9) is examined once.
  std::map<std::pair<long long, long long>, Mode> distinct;
  for (const Mode& m : modes) {
    auto key = std::pair{roundedKey(std::log(m.omegaSquared) * 1e9), roundedKey(m.damping * 1e6)};
    distinct.emplace(key, m);
  }
  double limit = kLargestStep;
  // Fastest first: the fast modes set the limit, and the slower ones, mostly stable at it, are
  // each passed after one check instead of a bisection.
  for (auto at = distinct.rbegin(); at != distinct.rend(); ++at) {
    const Mode& mode = at->second;
    // A mode already stable at the current limit cannot lower it.
    if (stableAt(integrator, mode, limit)) continue;
    limit = std::min(limit, modeLimit(integrator, mode));
  }
  return limit;
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

std::string beyondDoubles(const World& world, const State& initial) {
  double largestField = 0;
  for (double f : world.field.forces) largestField = std::max(largestField, std::fabs(f));
  const struct {
    const char* name;
    double value;
  } parameters[] = {{"kElastic", world.kElastic},
                    {"dElastic", world.dElastic},
                    {"kCollision", world.kCollision},
                    {"dCollision", world.dCollision},
                    {"the largest field force", largestField}};
  char text[200];
  for (const auto& parameter : parameters) {
    const double perKilogram = parameter.value / world.mass;
    if (!std::isfinite(perKilogram * kHeadroom)) {
      std::snprintf(
          text, sizeof text, "%s / mass = %g / %g gives %g%s", parameter.name, parameter.value,
          world.mass, perKilogram,
          std::isfinite(perKilogram) ? ", too near double's largest number to take a step" : "");
      return text;
    }
  }
  const int n = initial.points();
  for (int q = 0; q < n; ++q) {
    const Vec3 v = load(initial.v(), q, n);
    if (!std::isfinite(dot(v, v) * kHeadroom)) {
      std::snprintf(text, sizeof text,
                    "the velocity of p%s, (%g, %g, %g) m/s: its square (kinetic energy) overflows",
                    bodyOf(world).label(q).c_str(), v.x, v.y, v.z);
      return text;
    }
  }
  return "";
}

double largestStrain(const Body& body, const State& state) {
  const int n = body.count();
  double largest = 0;
  for (const Spring& s : body.springs)
    largest = std::max(
        largest, std::fabs(length(load(state.p(), s.a, n) - load(state.p(), s.b, n)) / s.rest - 1));
  return largest;
}

double stableFraction(const World& world, const State& initial, const Linearisation* rest) {
  // How damped the fastest mode is for its speed. For the course cube the free lattice's tells
  // it, pins or not (they hold a few points of 512, and their lattice's solve takes a second):
  // at rest a mode's damping rate is its omega^2 dElastic / kElastic, the fastest's over omega.
  // Another body's, or springs of different kinds: the fastest of its own modes at rest.
  double dampingPerRadian = 0;
  if (hasCourseSprings(world)) {
    const Linearisation free = freeLatticeAtRest(world);
    if (!free.finite || free.modes.empty()) return kStableFraction;
    dampingPerRadian = free.highestFrequency * world.dElastic / world.kElastic;
  } else {
    const Linearisation own = rest ? Linearisation{} : lineariseAtRest(world);
    const Linearisation& modes = rest ? *rest : own;
    if (!modes.finite || modes.modes.empty()) return kStableFraction;
    const Mode fastest = *std::max_element(
        modes.modes.begin(), modes.modes.end(),
        [](const Mode& a, const Mode& b) { return a.omegaSquared < b.omegaSquared; });
    dampingPerRadian = fastest.damping / std::sqrt(fastest.omegaSquared);
  }
  const bool lightlyDamped = dampingPerRadian < kLightDamping;
  return lightlyDamped && largestStrain(bodyOf(world), initial) > kDeformed
             ? kLargeMotionStableFraction
             : kStableFraction;
}

double StabilityReport::verdictLimit(Integrator integrator) const {
  const double atRest = critical(integrator);
  auto at = std::find(kExplicitIntegrators.begin(), kExplicitIntegrators.end(), integrator);
  if (at == kExplicitIntegrators.end() || criticalInitial.empty()) return atRest;
  const double atStart =
      criticalInitial[static_cast<std::size_t>(at - kExplicitIntegrators.begin())];
  return std::isnan(atStart) ? atRest : std::min(atRest, atStart);
}

double StabilityReport::critical(Integrator integrator) const {
  auto at = std::find(kExplicitIntegrators.begin(), kExplicitIntegrators.end(), integrator);
  if (at == kExplicitIntegrators.end()) return INFINITY;
  if (!beyond.empty()) return NAN;
  return criticalRest[static_cast<std::size_t>(at - kExplicitIntegrators.begin())];
}

StabilityReport analyseStability(const World& world, const State& initial) {
  StabilityReport report;
  report.beyond = beyondDoubles(world, initial);
  if (!report.beyond.empty()) return report;  // nothing to analyse, in microseconds
  Model model = makeModel(world, initial);
  // The two states' analyses are independent (linearise reads the model only): the face on the
  // wall on a second thread halves the wait where a second core is free.
  // The rest lattice's solve (once a process, or a pinned lattice's each time) goes with it.
  // A scene without the course's walls (none, or a box of its own) has no wall at x = -2.
  report.courseWalls = hasCourseWalls(world.scene.get());
  Linearisation wall;
  std::future<void> other = std::async(std::launch::async, [&] {
    report.rest = lineariseAtRest(world);
    if (report.courseWalls) wall = linearise(model, faceOnWallState(model.body()));
  });
  report.initial = linearise(model, initial);
  other.get();
  report.largestStrain = largestStrain(model.body(), initial);
  report.stableFraction = stableFraction(world, initial, &report.rest);
  for (Integrator integrator : kExplicitIntegrators) {
    report.criticalInitial.push_back(
        report.initial.finite ? criticalStep(integrator, report.initial.modes) : NAN);
    report.criticalRest.push_back(criticalStep(integrator, report.rest.modes));
    report.criticalFaceOnWall.push_back(report.courseWalls ? criticalStep(integrator, wall.modes)
                                                           : NAN);
  }
  return report;
}

double predictedLimit(const World& world, const State& initial, Integrator integrator) {
  if (!integratorInfo(integrator).boundedStableStep) return INFINITY;
  Model model = makeModel(world, initial);
  // As in analyseStability, the face on the wall on a second thread.
  std::future<Linearisation> onWall = std::async(
      std::launch::async, [&model] { return linearise(model, faceOnWallState(model.body())); });
  const Linearisation atStart = linearise(model, initial);
  const Linearisation wall = onWall.get();
  if (!atStart.finite) return NAN;
  return std::min(criticalStep(integrator, atStart.modes), criticalStep(integrator, wall.modes));
}

namespace {

// The end of a divergence message for a body too large to analyse while the user waits.
constexpr double kUsefulRowSumBound = 0.01;  // of 1 / fastest; RK4's undamped limit is 2.8
std::string largeBodyAdvice(const World& world, const State& initial, int points) {
  const char* name = integratorName(world.integrator);
  const std::string head = "dt=" + number(world.dt) + " with " + name + " on a body of " +
                           std::to_string(points) + " points";
  const std::string check = " (jello --check finds the limit itself, slowly for a body this large)";
  const auto [bound, fastest] = rowSumBound(makeModel(world, initial), initial, world.integrator);
  if (std::isnan(bound)) {
    return head +
           ": the forces' derivatives at the initial state are not finite numbers; no step "
           "will do";
  }
  if (bound == 0) return head + ": " + stepAdvice(0);
  // An integrator unstable on an undamped oscillation (EULER, MIDPOINT) is held by the damping
  // alone, of which row sums promise nothing for the slower modes: its bound is then far below
  // its limit, and a step suggested from it would be useless.
  if (bound * fastest < kUsefulRowSumBound) {
    return head + ": " + name + " is stable only as far as damping holds the modes, which row " +
           "sums cannot bound" + check + "; try --integrator RK4 or --integrator IMPLICIT";
  }
  if (world.dt > bound) {
    return head + ": the initial state's modes are stable below " + limitText(bound) +
           " (a bound from its row sums)" + check + "; " + stepAdvice(bound);
  }
  return head + " is below " + limitText(bound) +
         ", where the initial state's modes are stable (a bound from its row sums), but the "
         "motion left it (a harder contact?)" +
         check + "; " + stepAdvice(world.dt);
}

}  // namespace

std::string divergenceMessage(const World& world, const State& initial, long long step, double time,
                              const std::string& reason) {
  char head[160];
  std::snprintf(head, sizeof head, "diverged at step %lld (t=%.6g s): ", step, time);
  std::string out = head + reason + "; ";
  const char* name = integratorName(world.integrator);
  // Checks of microseconds first: an eigen-analysis of such a world would say nothing, slowly.
  if (findDivergedPoint(initial) >= 0) {
    return out +
           "the initial state is already beyond the guard (not finite, or more than 100 m from the "
           "origin): no step will do; start the cube inside the box";
  }
  const std::string beyond = beyondDoubles(world, initial);
  if (!beyond.empty()) {
    return out + "the world's numbers are beyond what double arithmetic can simulate (" + beyond +
           "): no step will do";
  }
  // A body larger than the course cube's is analysed by Lanczos iterations alone (slowestModes),
  // which take seconds at 10^3 points and minutes at 48^3: the message gives the step its row
  // sums guarantee instead, at once. (An integrator without a limit needs no analysis: below.)
  const int points = bodyOf(world).count();
  if (points > kNumPoints && integratorInfo(world.integrator).boundedStableStep)
    return out + largeBodyAdvice(world, initial, points);
  // The rest lattice's limit takes milliseconds; when it is already below what the analysis
  // resolves, the springs alone rule every step out and the eigensolves are spared.
  if (integratorInfo(world.integrator).boundedStableStep &&
      criticalStep(world.integrator, lineariseAtRest(world).modes) == 0)
    return out + "dt=" + number(world.dt) + " with " + name + ": " + stepAdvice(0);
  double limit = predictedLimit(world, initial, world.integrator);
  if (limit == 0) return out + "dt=" + number(world.dt) + " with " + name + ": " + stepAdvice(0);
  if (std::isnan(limit)) {
    return out +
           "the forces' derivatives at the initial state are not finite numbers: the world's "
           "numbers are beyond what double arithmetic can simulate, and no step will do";
  }
  if (!std::isfinite(limit)) {
    return out + "dt=" + number(world.dt) + " with " + name + ", which has no stability limit; " +
           (world.dt / 2 >= std::numeric_limits<double>::min()
                ? "try a smaller --dt"
                : "no step will do (dt is the smallest a double holds)");
  }
  if (world.dt > limit) {
    return out + "dt=" + number(world.dt) + " exceeds " + name + "'s stable limit " +
           limitText(limit) + " for this world; " + stepAdvice(limit);
  }
  return out + "dt=" + number(world.dt) + " is within " + name + "'s predicted limit " +
         number(limit) +
         " for this world, but the motion left it (a harder contact than a face on a wall?); " +
         stepAdvice(world.dt);
}

double observedLimit(const Model& model, const State& start, Integrator integrator, double time,
                     double guess) {
  // The smallest step tried is guess / 3: its runs must be a countable number of steps.
  if (!(guess > 0) || !stepsForTime(time, guess / 3)) return NAN;
  // Runs of `time` seconds (stepsForTime's count: every dt tried is above guess / 3), checked
  // as every run is (simulation.h).
  auto stable = [&](double dt) {
    return Simulation(model, start, integrator, dt).advance(*stepsForTime(time, dt)).ran();
  };
  double low = guess / 3, high = guess * 3;
  if (!stable(low) || stable(high)) return NAN;
  for (int i = 0; i < 9; ++i) {
    double middle = std::sqrt(low * high);
    (stable(middle) ? low : high) = middle;
  }
  return low;
}

namespace {

// The map's numbers: the CSV, and per integrator the gnuplot data lines "kElastic dt".
struct StiffnessSweep {
  std::string csv;
  std::map<std::string, std::string> predictedRows, observedRows;
};

// kElastic from 1/8 to 8 times the world's (500 N/m when it has none): the predicted limit of
// every explicit integrator, and the observed one of three of them (real runs are slow).
StiffnessSweep sweepStiffness(const World& world, const State& initial, double time) {
  const double base = world.kElastic > 0 ? world.kElastic : 500;
  const std::vector<Integrator> observed = {Integrator::Euler, Integrator::Midpoint,
                                            Integrator::RK4};
  StiffnessSweep sweep;
  sweep.csv = "kElastic,integrator,predicted_dt,observed_dt\n";
  Progress progress;
  for (int e = -3; e <= 3; ++e) {
    World w = world;
    w.kElastic = base * std::pow(2.0, e);
    if (world.scene && world.scene->springs) {  // a scene's springs by kind scale alike
      auto scaled = std::make_shared<SceneSpec>(*world.scene);
      for (double& k : scaled->springs->k) k *= std::pow(2.0, e);
      w.scene = scaled;
    }
    Linearisation rest = lineariseAtRest(w);
    Model model = makeModel(w, initial);
    for (Integrator integrator : kExplicitIntegrators) {
      double predicted = criticalStep(integrator, rest.modes);
      bool measured = std::find(observed.begin(), observed.end(), integrator) != observed.end();
      double seen = measured ? observedLimit(model, initial, integrator, time, predicted) : NAN;
      char line[160];
      std::snprintf(line, sizeof line, "%.6g,%s,%.6g,%s\n", w.kElastic, integratorName(integrator),
                    predicted, std::isnan(seen) ? "" : number(seen).c_str());
      sweep.csv += line;
      std::snprintf(line, sizeof line, "%.6g %.6g\n", w.kElastic, predicted);
      sweep.predictedRows[integratorName(integrator)] += line;
      if (!std::isnan(seen)) {
        std::snprintf(line, sizeof line, "%.6g %.6g\n", w.kElastic, seen);
        sweep.observedRows[integratorName(integrator)] += line;
      }
    }
    char done[64];
    std::snprintf(done, sizeof done, "map: kElastic %g done", w.kElastic);
    progress.show(done);
  }
  return sweep;
}

// stability-map.gp: the data inline, so that the script alone draws the picture again.
std::string mapScript(const StiffnessSweep& sweep, const std::string& worldPath,
                      const World& world) {
  std::ostringstream gp;
  gp << "# Made by jello --check --map; `gnuplot stability-map.gp` here draws stability-map.png "
        "again.\n";
  std::string plots;
  int style = 0;
  for (const auto& [name, rows] : sweep.predictedRows) {
    std::string lt = " lt " + std::to_string(++style);  // one colour an integrator
    gp << "$P_" << name << " << EOD\n" << rows << "EOD\n";
    plots += (plots.empty() ? "" : ", ") + std::string("$P_") + name + " with lines lw 2" + lt +
             " title '" + name + " predicted'";
    if (auto observed = sweep.observedRows.find(name); observed != sweep.observedRows.end()) {
      gp << "$O_" << name << " << EOD\n" << observed->second << "EOD\n";
      plots += ", $O_" + name + " with points pt 7 ps 1.3" + lt + " title '" + name + " observed'";
    }
  }
  gp << "set terminal pngcairo size 960,640 font ',11'\n"
     << "if (!exists(\"png\")) png = 'stability-map.png'\nset output png\n"
     << "set title "
     << gnuplotString(worldPath +
                      ": largest stable step against spring stiffness (stable below each line)")
     << "\n"
     << "set logscale xy\nset xlabel 'kElastic (N/m)'\nset ylabel 'dt (s)'\nset grid\nset key "
        "outside right top\n"
     << "plot " << plots << ", '-' with points pt 6 ps 3 lc 'black' title \"the world's own\"\n"
     << world.kElastic << " " << world.dt << "\ne\n";
  return gp.str();
}

}  // namespace

Outcome writeStabilityMap(const std::string& dir, const std::string& worldPath, const World& world,
                          const State& initial, double time, bool overwrite) {
  FolderClaim claim;
  const Existing existing = overwrite ? Existing::Replace : Existing::Refuse;
  try {
    claim =
        claimOutputs(dir, {"stability-map.csv", "stability-map.gp", "stability-map.png"}, existing);
  } catch (const OutputError& e) {
    return failed(std::string("--map: ") + e.what());
  }
  const StiffnessSweep sweep = sweepStiffness(world, initial, time);
  try {
    writeFileWhole(dir + "/stability-map.csv", sweep.csv, existing);
    writeFileWhole(dir + "/stability-map.gp", mapScript(sweep, worldPath, world), existing);
  } catch (const OutputError& e) {
    return failed(e.what());
  }
  const std::string whyNotDrawn =
      drawWithGnuplot(dir, "stability-map.gp", "stability-map.png", existing);
  const bool drawn = whyNotDrawn.empty();
  std::printf("%s: stability map in %s/ (stability-map.csv%s)\n", worldPath.c_str(), dir.c_str(),
              drawn ? ", stability-map.png" : "");
  if (drawn) return succeeded();
  // Without gnuplot the CSV is the map; a gnuplot that failed is a failure.
  const std::string notDrawn = "stability-map.png was not drawn: " + whyNotDrawn;
  return whyNotDrawn == kGnuplotMissing ? succeeded(notDrawn) : failed(notDrawn);
}

Verdict verdictFor(double dt, double critical, double stableFraction) {
  if (dt > critical) return Verdict::Unstable;
  if (dt > stableFraction * critical) return Verdict::NearLimit;
  return Verdict::Stable;
}

const char* verdictName(Verdict verdict) {
  switch (verdict) {
    case Verdict::Stable:
      return "stable";
    case Verdict::NearLimit:
      return "marginal";
    case Verdict::Unstable:
      return "unstable";
  }
  return "unstable";  // not reached: every verdict is named above
}

double suggestedStep(double critical, double stableFraction) {
  double target = stableFraction * critical;
  double decade = std::pow(10.0, std::floor(std::log10(target)));
  for (double m : {5.0, 2.0, 1.0})
    if (m * decade <= target) return m * decade;
  return decade;
}

std::string limitText(double limit) {
  if (limit == 0) return "below " + number(kShortestResolvedStep);
  if (std::isnan(limit)) return "none (not finite)";
  return number(limit);
}

std::string stepAdvice(double critical, double stableFraction) {
  const double step = suggestedStep(critical, stableFraction);
  // --dt takes any finite step > 0; a subnormal one has lost precision, and 0 is refused.
  if (step >= std::numeric_limits<double>::min() && std::isfinite(step))
    return "try --dt " + number(step) + " or --integrator IMPLICIT";
  if (critical == 0) {
    return "no step will do: the stable limit is below " + number(kShortestResolvedStep) +
           " s (modes faster than about 1e18 rad/s); soften the world (kElastic, kCollision, mass) "
           "or try --integrator IMPLICIT";
  }
  return "no step will do: " + number(100 * stableFraction) + "% of " + number(critical) +
         " s is below the smallest normal double; soften the world or try --integrator IMPLICIT";
}

namespace {
// Why a step below the limit is only marginal (see kStableFraction).
std::string marginalNote(const StabilityReport& r) {
  char text[400];
  if (r.stableFraction < kStableFraction) {
    std::snprintf(
        text, sizeof text,
        "  marginal: the cube starts deformed (a spring strained by %.0f%%) and its fast modes are "
        "nearly undamped, so its large motion can pump them at steps the limits call stable (runs "
        "diverged at 0.58 of the limit for a cube stretched by 30%%); below %.0f%% of the limit a "
        "step is called stable\n",
        100 * r.largestStrain, 100 * r.stableFraction);
  } else {
    std::snprintf(
        text, sizeof text,
        "  marginal: within %.0f%% of the limit, which holds for small motions about the state "
        "analysed; a large motion can lower the real one (an undamped cube with a corner pulled "
        "out by 0.35 m diverged at 0.82 of it)\n",
        100 * (1 - r.stableFraction));
  }
  return text;
}
}  // namespace

namespace {

// --check's lines on the modes: at rest, at the initial state, and those that grow.
std::string modesText(const StabilityReport& r) {
  std::string out;
  char line[256];
  // The count only where every mode was found (not only the spectrum's ends)
  const std::string count =
      r.rest.allModes ? " " + std::to_string(r.rest.modes.size()) + " oscillating modes," : "";
  std::snprintf(line, sizeof line,
                "  at rest:%s highest frequency %.4g rad/s (%.4g Hz), damping rates %.3g to %.3g "
                "1/s\n",
                count.c_str(), r.rest.highestFrequency, r.rest.highestFrequency / (2 * kPi),
                r.rest.lowestDamping, r.rest.highestDamping);
  out += line;
  std::snprintf(
      line, sizeof line,
      "  at the initial state: highest frequency %.4g rad/s, damping rates %.3g to %.3g 1/s\n",
      r.initial.highestFrequency, r.initial.lowestDamping, r.initial.highestDamping);
  out +=
      r.initial.finite
          ? line
          : "  at the initial state: the forces' derivatives are not finite numbers (beyond double "
            "arithmetic): no analysis\n";
  if (r.initial.growing) {
    out += "  " + std::to_string(r.initial.growing) +
           " modes of the initial state grow whatever the step (negative stiffness: buckling "
           "springs, a repelling "
           "field): physics, not numerics\n";
  }
  return out;
}

// --check's verdict on the world's own dt, with the note and the advice it calls for.
std::string verdictText(const World& world, const StabilityReport& r) {
  const double critical = r.verdictLimit(world.integrator);
  // Named when it differs in print from the headline one (the two eigensolves differ in the last
  // bits).
  const char* which =
      number(critical) != number(r.critical(world.integrator)) ? " at the initial state" : "";
  Verdict verdict = verdictFor(world.dt, critical, r.stableFraction);
  std::string out = "  the world's dt " + number(world.dt) + " with " +
                    integratorName(world.integrator) + ": " + verdictName(verdict);
  if (critical == 0) {
    out += " (the limit is " + limitText(critical) + " s)";
  } else if (std::isfinite(critical)) {
    char line[256];
    std::snprintf(line, sizeof line, " (%.0f%% of the limit %s%s)", 100 * world.dt / critical,
                  number(critical).c_str(), which);
    out += line;
  }
  out += "\n";
  if (verdict == Verdict::NearLimit) out += marginalNote(r);
  if (verdict != Verdict::Stable && std::isfinite(critical))
    out += "  " + stepAdvice(critical, r.stableFraction) + "\n";
  return out;
}

// --check's warnings when the world's dt is above the limit at the start or against a wall.
std::string otherLimitsText(const World& world, const StabilityReport& r) {
  std::string out;
  auto at = std::find(kExplicitIntegrators.begin(), kExplicitIntegrators.end(), world.integrator);
  if (at != kExplicitIntegrators.end()) {
    std::size_t i = static_cast<std::size_t>(at - kExplicitIntegrators.begin());
    // Only a limit below the headline one (at rest) says something the verdict has not.
    if (world.dt > r.criticalInitial[i] && r.criticalInitial[i] < r.criticalRest[i]) {
      out += "  at the initial state the limit is " + limitText(r.criticalInitial[i]) +
             " s: the start's deformation may destabilise this step for a while\n";
    }
    if (world.dt > r.criticalFaceOnWall[i] && r.criticalFaceOnWall[i] < r.criticalRest[i]) {
      out += "  while a face presses on a wall the limit is " + limitText(r.criticalFaceOnWall[i]) +
             " s: contact may destabilise this step\n";
    }
  }
  return out;
}

}  // namespace

std::string stabilityText(const std::string& worldPath, const World& world,
                          const StabilityReport& r) {
  if (!r.beyond.empty()) {
    return worldPath +
           ": the world's numbers are beyond what double arithmetic can simulate: " + r.beyond +
           "\n  its first step overflows, or leaves the guard's 100 m: no practical step of any "
           "integrator will do, and no stability analysis was made\n";
  }
  std::string out =
      worldPath + ": the largest stable step of each integrator, from the linearised forces\n";
  out += modesText(r);
  out += limitTable(r);
  out += verdictText(world, r);
  out += otherLimitsText(world, r);
  return out;
}

std::string stabilityJson(const std::string& worldPath, const World& world,
                          const StabilityReport& r) {
  nlohmann::json j;
  j["world"] = worldPath;
  j["dt"] = world.dt;
  j["integrator"] = integratorName(world.integrator);
  if (!r.beyond.empty()) {
    j["beyond_double_arithmetic"] = r.beyond;
    j["verdict"] = "beyond double arithmetic";
    j["critical_dt"] = nullptr;
    return j.dump(2) + "\n";
  }
  j["modes"] = r.rest.modes.size();
  j["highest_frequency"] = r.rest.highestFrequency;
  j["damping_rates"] = {r.rest.lowestDamping, r.rest.highestDamping};
  j["initial_state"] = {{"highest_frequency", r.initial.highestFrequency},
                        {"damping_rates", {r.initial.lowestDamping, r.initial.highestDamping}},
                        {"growing_modes", r.initial.growing}};
  auto finite = [](double x) {
    return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
  };
  for (std::size_t i = 0; i < kExplicitIntegrators.size(); ++i) {
    Integrator integrator = kExplicitIntegrators[i];
    j["integrators"][integratorName(integrator)] = {
        {"critical_dt", finite(r.critical(integrator))},
        {"initial_state", finite(r.criticalInitial[i])},
        {"face_on_wall", finite(r.criticalFaceOnWall[i])}};
  }
  for (const IntegratorInfo& row : integratorTable())
    if (!row.boundedStableStep)
      j["integrators"][row.name()] = {{"critical_dt", nullptr}, {"unbounded", true}};
  double critical = r.critical(world.integrator), verdictLimit = r.verdictLimit(world.integrator);
  j["verdict"] = verdictName(verdictFor(world.dt, verdictLimit, r.stableFraction));
  j["critical_dt"] = finite(critical);
  j["verdict_limit_dt"] =
      finite(verdictLimit);  // the smaller of the limits at rest and at the start
  j["stable_below_dt"] = finite(r.stableFraction * verdictLimit);
  return j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

}  // namespace jello
