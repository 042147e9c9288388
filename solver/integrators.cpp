// integrators.cpp: the time steppers of docs/physics.md over an ODE system, and the
// integrator table that names and describes them.

#include "solver/integrators.h"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string_view>

#include "core/assert.h"
#include "solver/jacobian.h"

namespace jello {

namespace {

// Dormand-Prince 5(4): the stages' coefficients, the fifth-order weights (the last stage's row,
// so that the last derivative is the next step's first: "first same as last") and the
// difference between the fifth- and fourth-order weights, which estimates the local error.
constexpr int kStages = 7;
constexpr double kA[kStages][kStages] = {
    {},
    {1.0 / 5},
    {3.0 / 40, 9.0 / 40},
    {44.0 / 45, -56.0 / 15, 32.0 / 9},
    {19372.0 / 6561, -25360.0 / 2187, 64448.0 / 6561, -212.0 / 729},
    {9017.0 / 3168, -355.0 / 33, 46732.0 / 5247, 49.0 / 176, -5103.0 / 18656},
    {35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84},
};
constexpr double kErrorWeights[kStages] = {
    71.0 / 57600, 0, -71.0 / 16695, 71.0 / 1920, -17253.0 / 339200, 22.0 / 525, -1.0 / 40};
constexpr double kSafety = 0.9, kMinShrink = 0.2, kMaxGrowth = 5.0;
// A PI step-size controller (Gustafsson; the exponents of Hairer's DOPRI5): the last accepted
// error damps the oscillation of the step at the stability limit of a stiff world, where a
// plain controller alternates between too long (rejected) and too short.
constexpr double kErrorExponent = 0.17, kPreviousErrorExponent = 0.04,
                 kSmallestPreviousError = 1e-4;

// Newton's iterations of IMPLICIT: stop when the update is this small against the velocities,
// or after this many.
constexpr double kNewtonTolerance = 1e-12;
constexpr int kMaxNewtonIterations = 10;
// Each Newton system is solved to a relative residual that makes the update's own error a tenth
// of the Newton tolerance, and never tighter than kLinearTolerance: a solve more accurate than
// the test it feeds buys nothing, and one near convergence (a small residual) needs few digits.
constexpr double kLinearTolerance = 1e-12;
constexpr double kLinearShareOfTolerance = 0.1;
constexpr double kLoosestLinearTolerance = 0.1;
// When the next update is expected within this many times the Newton tolerance it is the
// test's confirmation: it comes from the matrix and preconditioner made for the previous update
// (a chord step, which near the solution converges as fast as the test needs), not new ones.
constexpr double kKeepMatrixWithin = 100;

void sized(std::vector<double>& buffer, std::size_t n) {
  if (buffer.size() != n) buffer.assign(n, 0.0);
}

// body(begin, end) on ranges covering [0, n): the system's threads', or [0, n) here.
template <class Body>
void forRanges(const OdeSystem& system, std::size_t n, const Body& body) {
  if (!system.inRanges) return body(std::size_t{0}, n);
  system.inRanges(n, RangeBody{[](const void* context, std::size_t begin, std::size_t end) {
                                 (*static_cast<const Body*>(context))(begin, end);
                               },
                               &body});
}

// out = y + h * k
void axpy(const OdeSystem& system, const std::vector<double>& y, double h,
          const std::vector<double>& k, std::vector<double>& out) {
  forRanges(system, y.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) out[i] = y[i] + h * k[i];
  });
}

bool allFinite(const std::vector<double>& y) {
  for (double x : y)
    if (!std::isfinite(x)) return false;
  return true;
}

}  // namespace

double rmsNorm(const double* x, std::size_t n) {
  double sumSquares = 0;
  for (std::size_t i = 0; i < n; ++i) sumSquares += x[i] * x[i];
  if (sumSquares >= std::numeric_limits<double>::min() &&
      sumSquares <= std::numeric_limits<double>::max())
    return std::sqrt(sumSquares / n);
  // Out of range, or a NaN: scaled by the largest term, which makes every square at most 1.
  double largest = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (std::isnan(x[i])) return NAN;
    largest = std::max(largest, std::fabs(x[i]));
  }
  if (largest == 0 || std::isinf(largest)) return largest;
  double scaledSum = 0;
  for (std::size_t i = 0; i < n; ++i) scaledSum += (x[i] / largest) * (x[i] / largest);
  return largest * std::sqrt(scaledSum / n);
}

// What the step functions share: a Stepper's buffers, its tolerances and counts, RK45's memory.
struct StepWork {
  explicit StepWork(Tolerances t) : tolerances(t) {}
  std::vector<double> k[kStages], temp, next;
  // IMPLICIT: the Newton matrix and its solvers. The exact Jacobian is not symmetric (a
  // damper's force turns with its spring, so it depends on the positions through the direction)
  // and the Newton matrix need not be definite (a compressed spring's geometric term), which
  // rules out Cholesky and conjugate gradients. BiCGSTAB with a Jacobi preconditioner solves it
  // in a few milliseconds (the diagonal blocks dominate for the steps a user takes), where a
  // sparse LU of the 3D lattice fills in and takes 100-200 ms here. (A 3x3 block-Jacobi
  // preconditioner took as many iterations: what slows BiCGSTAB at large steps is the lattice's
  // stiffness, dt^2 k/m, which no per-point preconditioner touches.) SparseLU stays as the
  // fallback for the rare system BiCGSTAB does not converge on. BiCGSTAB is written here, as
  // Eigen's is, around the Newton matrix's blocks (NewtonBlocks), whose product reads a third
  // of the data a sparse matrix's does.
  NewtonBlocks newton;
  Eigen::VectorXd inverseDiagonal;          // the Jacobi preconditioner
  Eigen::VectorXd r, r0, p, v, s, t, y, z;  // BiCGSTAB's vectors
  SparseMatrix fallback;                    // the Newton matrix for the direct solver
  Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>> lu;
  bool analysed = false;
  Eigen::VectorXd residual, update;

  Tolerances tolerances;
  StepStats stats;
  double rk45Step = 0;   // RK45's last successful substep, the first guess of the next step
  double rk45Error = 1;  // RK45's last accepted error norm, for the step-size controller
};

namespace {

// out = f(at), counted.
void evaluate(StepWork& w, const OdeSystem& system, const std::vector<double>& at,
              std::vector<double>& out) {
  system.derivative(at.data(), out.data());
  ++w.stats.evaluations;
}

// p += dt v_old, v += dt a(p_old, v_old): the starter's explicit Euler.
void stepEuler(StepWork& w, const OdeSystem& system, std::vector<double>& y, double dt) {
  std::vector<double>& k1 = w.k[0];
  evaluate(w, system, y, k1);
  forRanges(system, y.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) y[i] += dt * k1[i];
  });
  ++w.stats.steps;
}

// Semi-implicit Euler: the velocities first, then the positions with the new velocities.
void stepSymplectic(StepWork& w, const OdeSystem& system, std::vector<double>& y, double dt) {
  const std::size_t half = y.size() / 2;
  JELLO_ASSERT(y.size() == 2 * half);  // y = [p; v], taken in halves
  std::vector<double>& k1 = w.k[0];
  evaluate(w, system, y, k1);
  for (std::size_t i = 0; i < half; ++i) y[half + i] += dt * k1[half + i];
  for (std::size_t i = 0; i < half; ++i) y[i] += dt * y[half + i];
  ++w.stats.steps;
}

void stepMidpoint(StepWork& w, const OdeSystem& system, std::vector<double>& y, double dt) {
  std::vector<double>&k1 = w.k[0], &k2 = w.k[1];
  evaluate(w, system, y, k1);
  axpy(system, y, dt / 2, k1, w.temp);
  evaluate(w, system, w.temp, k2);
  forRanges(system, y.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) y[i] += dt * k2[i];
  });
  ++w.stats.steps;
}

// Velocity Verlet. The forces also depend on the velocities (dampers), so the new acceleration
// is taken at an Euler prediction of the new velocities; without dampers this is exactly the
// symplectic velocity Verlet, and with them it stays second order.
void stepVerlet(StepWork& w, const OdeSystem& system, std::vector<double>& y, double dt) {
  const std::size_t half = y.size() / 2;
  JELLO_ASSERT(y.size() == 2 * half);  // y = [p; v], taken in halves
  std::vector<double>&k1 = w.k[0], &k2 = w.k[1];
  evaluate(w, system, y, k1);
  for (std::size_t i = 0; i < half; ++i) {
    w.temp[i] = y[i] + dt * y[half + i] + dt * dt / 2 * k1[half + i];
    w.temp[half + i] = y[half + i] + dt * k1[half + i];
  }
  evaluate(w, system, w.temp, k2);
  for (std::size_t i = 0; i < half; ++i) {
    y[i] = w.temp[i];
    y[half + i] += dt / 2 * (k1[half + i] + k2[half + i]);
  }
  ++w.stats.steps;
}

void stepRk4(StepWork& w, const OdeSystem& system, std::vector<double>& y, double dt) {
  std::vector<double>&k1 = w.k[0], &k2 = w.k[1], &k3 = w.k[2], &k4 = w.k[3];
  evaluate(w, system, y, k1);
  axpy(system, y, dt / 2, k1, w.temp);
  evaluate(w, system, w.temp, k2);
  axpy(system, y, dt / 2, k2, w.temp);
  evaluate(w, system, w.temp, k3);
  axpy(system, y, dt, k3, w.temp);
  evaluate(w, system, w.temp, k4);
  forRanges(system, y.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
      y[i] += dt / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
  });
  ++w.stats.steps;
}

// One Dormand-Prince substep of h from y: the stages into w.k[1..], the fifth-order result
// into w.next, and the norm of the scaled error estimate (via w.temp) returned.
double dormandPrinceSubstep(StepWork& w, const OdeSystem& system, const std::vector<double>& y,
                            double h) {
  const std::size_t n = y.size();
  for (int s = 1; s < kStages; ++s) {
    std::vector<double>& at = s == kStages - 1 ? w.next : w.temp;
    for (std::size_t i = 0; i < n; ++i) {
      double sum = 0;
      for (int j = 0; j < s; ++j) sum += kA[s][j] * w.k[j][i];
      at[i] = y[i] + h * sum;
    }
    evaluate(w, system, at, w.k[s]);
  }
  // The scaled errors go into w.temp (the stages are done with it). Their squares overflow
  // below a tolerance of about 1e-160: rmsNorm keeps the norm finite then.
  for (std::size_t i = 0; i < n; ++i) {
    double error = 0;
    for (int j = 0; j < kStages; ++j) error += kErrorWeights[j] * w.k[j][i];
    double scale =
        w.tolerances.atol + w.tolerances.rtol * std::max(std::fabs(y[i]), std::fabs(w.next[i]));
    w.temp[i] = h * error / scale;
  }
  return rmsNorm(w.temp.data(), n);
}

// Substeps within [0, dt], none longer than dt, the first as long as the last success.
void stepRk45(StepWork& w, const OdeSystem& system, std::vector<double>& y, double dt) {
  double h = w.rk45Step > 0 ? std::min(w.rk45Step, dt) : dt, t = 0;
  evaluate(w, system, y, w.k[0]);
  while (t < dt) {
    bool last = h >= dt - t - 1e-12 * dt;
    if (last) h = dt - t;
    double norm = dormandPrinceSubstep(w, system, y, h);
    if (!std::isfinite(norm)) {
      if (!allFinite(w.next)) {  // the state blew up: hand it back, the caller stops
        y = w.next;
        ++w.stats.steps;
        return;
      }
      norm = INFINITY;  // an error beyond measure on a finite state: rejected, never accepted
    }
    double factor = norm == 0 ? kMaxGrowth
                              : std::clamp(kSafety * std::pow(norm, -kErrorExponent) *
                                               std::pow(w.rk45Error, kPreviousErrorExponent),
                                           kMinShrink, kMaxGrowth);
    if (norm <= 1) {
      w.rk45Error = std::max(norm, kSmallestPreviousError);
      y.swap(w.next);
      std::swap(w.k[0], w.k[kStages - 1]);  // first same as last
      t = last ? dt : t + h;
      ++w.stats.steps;
      w.rk45Step = std::min(h * factor, dt);
    } else {
      ++w.stats.rejected;
      if (h <= kSmallestSubstep * dt) {  // no substep a double can take meets the tolerance
        ++w.stats.failed;
        std::fill(y.begin(), y.end(), NAN);
        return;
      }
      factor = std::min(factor, 1.0);
    }
    h = std::max(std::min(h * factor, dt), std::min(kSmallestSubstep * dt, h));
  }
}

// The residual of backward Euler at the velocities w.next, -(v' - v - dt a(p + dt v', v')),
// into w.residual; the state there in w.temp. Returns its largest magnitude.
double implicitResidual(StepWork& w, const OdeSystem& system, const std::vector<double>& y,
                        double dt) {
  const std::size_t half = y.size() / 2;
  const std::vector<double>& velocity = w.next;
  for (std::size_t i = 0; i < half; ++i) {
    w.temp[i] = y[i] + dt * velocity[i];
    w.temp[half + i] = velocity[i];
  }
  evaluate(w, system, w.temp, w.k[0]);
  double largest = 0;
  for (std::size_t i = 0; i < half; ++i) {
    w.residual[i] = -(velocity[i] - y[half + i] - dt * w.k[0][half + i]);
    largest = std::max(largest, std::fabs(w.residual[i]));
  }
  return largest;
}

// Newton's first iterate: the old velocities, or one fixed-point step from them, v + dt a(p +
// dt v, v) (their residual added), whichever leaves the smaller residual. For the steps a user
// takes the fixed-point step is close to the answer, and one Newton update then meets the
// tolerance; for large steps, where the stiff springs make the fixed-point map expand, the old
// velocities stay. The residual at the iterate is left in w.residual, its state in w.temp; returns
// its largest magnitude.
double firstIterate(StepWork& w, const OdeSystem& system, const std::vector<double>& y, double dt) {
  const std::size_t half = y.size() / 2;
  std::copy(y.begin() + half, y.end(), w.next.begin());
  const double atOld = implicitResidual(w, system, y, dt);
  for (std::size_t i = 0; i < half; ++i) w.next[i] += w.residual[i];
  const double atStep = implicitResidual(w, system, y, dt);
  if (atStep <= atOld) return atStep;
  std::copy(y.begin() + half, y.end(), w.next.begin());
  return implicitResidual(w, system, y, dt);
}

// The Newton matrix I - dt dA/dv - dt^2 dA/dp at the state in w.temp, and BiCGSTAB's Jacobi
// preconditioner for it (1 where a diagonal entry is 0, as Eigen's).
void assembleNewton(StepWork& w, const OdeSystem& system, double dt) {
  system.newtonMatrix(w.temp.data(), dt, dt * dt, w.newton);
  ++w.stats.jacobians;
  w.inverseDiagonal.resize(w.residual.size());
  w.newton.diagonal(w.inverseDiagonal.data());
  for (double& d : w.inverseDiagonal) d = d != 0 ? 1 / d : 1;
}

// BiCGSTAB from zero, preconditioned on the right by the diagonal: Eigen's algorithm (its restart
// when r0 and r turn orthogonal included), until |N x - b| <= tolerance |b|. x is w.update, b
// w.residual. False when it does not converge within twice its unknowns' count of iterations, as
// Eigen's.
bool bicgstab(StepWork& w, double tolerance) {
  const Eigen::VectorXd& b = w.residual;
  Eigen::VectorXd &x = w.update, &r = w.r, &r0 = w.r0, &p = w.p, &v = w.v, &s = w.s, &t = w.t,
                  &y = w.y, &z = w.z;
  const double rhsNorm2 = b.squaredNorm(),
               eps2 = Eigen::NumTraits<double>::epsilon() * Eigen::NumTraits<double>::epsilon();
  x.setZero(b.size());
  if (rhsNorm2 == 0) return true;
  r = b;
  r0 = r;
  double r0Norm2 = rhsNorm2, rho = 1, alpha = 1, omega = 1;
  v.setZero(b.size());
  p.setZero(b.size());
  t.resize(b.size());
  const double threshold = tolerance * tolerance * rhsNorm2;
  for (int i = 0, restarts = 0; r.squaredNorm() > threshold;) {
    if (i++ >= 2 * b.size()) return false;
    const double rhoOld = rho;
    rho = r0.dot(r);
    if (std::fabs(rho) < eps2 * r0Norm2) {  // r0 and r have turned orthogonal: restart
      r0 = r;
      rho = r0Norm2 = r.squaredNorm();
      if (restarts++ == 0) i = 0;
    }
    const double beta = (rho / rhoOld) * (alpha / omega);
    p = r + beta * (p - omega * v);
    y = w.inverseDiagonal.cwiseProduct(p);
    w.newton.multiply(y.data(), v.data());
    alpha = rho / r0.dot(v);
    s = r - alpha * v;
    z = w.inverseDiagonal.cwiseProduct(s);
    w.newton.multiply(z.data(), t.data());
    const double tt = t.squaredNorm();
    omega = tt > 0 ? t.dot(s) / tt : 0;
    x += alpha * y + omega * z;
    r = s - omega * t;
  }
  return true;
}

// w.update = the Newton matrix's solution for w.residual, to a relative residual that keeps the
// update's error below kLinearShareOfTolerance * `tolerance` (m/s). False when the matrix is
// singular.
bool solveNewton(StepWork& w, double tolerance) {
  const double residualNorm = w.residual.norm();
  const double relative = residualNorm > 0 ? kLinearShareOfTolerance * tolerance / residualNorm : 1;
  if (bicgstab(w, std::clamp(relative, kLinearTolerance, kLoosestLinearTolerance))) return true;
  w.fallback = sparseOf(w.newton);
  if (!w.analysed) {
    w.lu.analyzePattern(w.fallback);
    w.analysed = true;
  }
  w.lu.factorize(w.fallback);
  if (w.lu.info() != Eigen::Success) return false;
  w.update = w.lu.solve(w.residual);
  return true;
}

// The largest magnitude of the first `half` velocities.
double largestOf(const std::vector<double>& velocity, std::size_t half) {
  double largest = 0;
  for (std::size_t i = 0; i < half; ++i) largest = std::max(largest, std::fabs(velocity[i]));
  return largest;
}

// Backward Euler, v' = v + dt a(p + dt v', v'), by Newton's method on v' with the exact
// Jacobian: (I - dt dA/dv - dt^2 dA/dp) dv' = -(v' - v - dt a). Converged when an update is at
// most kNewtonTolerance (1 + |v'|). The next update is expected to be about the last one's
// ratio to its residual times the new residual; when that is within kKeepMatrixWithin of the
// tolerance the matrix is kept. A singular matrix leaves NaN velocities.
void stepImplicit(StepWork& w, const OdeSystem& system, std::vector<double>& y, double dt) {
  if (!system.newtonMatrix) throw std::logic_error("IMPLICIT needs the Jacobian of the system");
  const std::size_t half = y.size() / 2;
  JELLO_ASSERT(y.size() == 2 * half);      // y = [p; v], taken in halves
  std::vector<double>& velocity = w.next;  // the Newton iterate v'
  w.residual.resize(static_cast<Eigen::Index>(half));
  double residual = firstIterate(w, system, y, dt);
  double scale = 1 + largestOf(velocity, half), gain = INFINITY;
  for (int iteration = 0; iteration < kMaxNewtonIterations; ++iteration) {
    if (!(gain * residual <= kKeepMatrixWithin * kNewtonTolerance * scale))
      assembleNewton(w, system, dt);
    ++w.stats.newtonIterations;
    if (!solveNewton(w, kNewtonTolerance * scale)) {
      std::fill(velocity.begin(), velocity.end(), NAN);  // singular: no step can be taken
      break;
    }
    double update = 0;
    for (std::size_t i = 0; i < half; ++i) {
      velocity[i] += w.update[i];
      update = std::max(update, std::fabs(w.update[i]));
    }
    scale = 1 + largestOf(velocity, half);
    if (!(update > kNewtonTolerance * scale)) break;
    gain = update / residual;
    residual = implicitResidual(w, system, y, dt);
  }
  for (std::size_t i = 0; i < half; ++i) {
    y[i] += dt * velocity[i];
    y[half + i] = velocity[i];
  }
  ++w.stats.steps;
}

// The table. Its order is the enum's (checked below), so that a row is found by indexing.
constexpr std::array<IntegratorInfo, kIntegratorCount> kTable = {{
    {Integrator::Euler, 1, true, false, "the course starter's explicit Euler", stepEuler},
    {Integrator::Symplectic, 1, true, false,
     "semi-implicit Euler: the velocities first, then the positions with them", stepSymplectic},
    {Integrator::Midpoint, 2, true, false, "explicit midpoint (RK2)", stepMidpoint},
    {Integrator::Verlet, 2, true, false, "velocity Verlet, symplectic without dampers", stepVerlet},
    {Integrator::RK4, 4, true, false, "the classic fourth-order Runge-Kutta", stepRk4},
    {Integrator::RK45, 5, true, false,
     "Dormand-Prince 5(4): adaptive substeps within each dt to --rtol and --atol", stepRk45},
    {Integrator::Implicit, 1, false, true,
     "backward Euler, Newton with the exact Jacobian: no stability limit on dt", stepImplicit},
}};

constexpr bool tableFollowsTheEnum() {
  for (int i = 0; i < kIntegratorCount; ++i)
    if (static_cast<int>(kTable[i].integrator) != i) return false;
  return true;
}
static_assert(tableFollowsTheEnum(),
              "the integrator table must have one row per enumerator, in enum order");

}  // namespace

const std::array<IntegratorInfo, kIntegratorCount>& integratorTable() { return kTable; }

const IntegratorInfo& integratorInfo(Integrator integrator) {
  const auto index = static_cast<std::size_t>(integrator);
  if (index >= kTable.size()) throw std::logic_error("an integrator without a row in the table");
  return kTable[index];
}

int orderOf(Integrator integrator) { return integratorInfo(integrator).order; }

std::vector<Integrator> integratorsWithStepLimit() {
  std::vector<Integrator> out;
  for (const IntegratorInfo& row : kTable)
    if (row.boundedStableStep) out.push_back(row.integrator);
  return out;
}

std::string integratorHelp() {
  std::string help;
  for (const IntegratorInfo& row : kTable) {
    char line[200];
    std::snprintf(line, sizeof line, "  %-11s order %d  %s\n", integratorName(row.integrator),
                  row.order, row.description);
    help += line;
  }
  return help;
}

Stepper::Stepper(Integrator integrator, Tolerances tolerances)
    : integrator_(integrator),
      step_(integratorInfo(integrator).step),
      work_(std::make_unique<StepWork>(tolerances)) {}
Stepper::~Stepper() = default;
Stepper::Stepper(Stepper&&) noexcept = default;
Stepper& Stepper::operator=(Stepper&&) noexcept = default;

void Stepper::restart() {
  auto fresh = std::make_unique<StepWork>(work_->tolerances);
  for (int s = 0; s < kStages; ++s) fresh->k[s].swap(work_->k[s]);
  fresh->temp.swap(work_->temp);
  fresh->next.swap(work_->next);
  work_ = std::move(fresh);
}

const StepStats& Stepper::stats() const { return work_->stats; }

void Stepper::step(const OdeSystem& system, std::vector<double>& y, double dt) {
  const std::size_t n = y.size();
  for (auto& k : work_->k) sized(k, n);
  sized(work_->temp, n);
  sized(work_->next, n);
  step_(*work_, system, y, dt);
}

}  // namespace jello
