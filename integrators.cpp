// integrators.cpp: the time steppers of SPEC.md sections 2 and 3 over an ODE system.

#include "integrators.h"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

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
constexpr double kErrorWeights[kStages] = {71.0 / 57600,  0, -71.0 / 16695, 71.0 / 1920, -17253.0 / 339200,
                                           22.0 / 525, -1.0 / 40};
constexpr double kSafety = 0.9, kMinShrink = 0.2, kMaxGrowth = 5.0;
// A PI step-size controller (Gustafsson; the exponents of Hairer's DOPRI5): the last accepted
// error damps the oscillation of the step at the stability limit of a stiff world, where a
// plain controller alternates between too long (rejected) and too short.
constexpr double kErrorExponent = 0.17, kPreviousErrorExponent = 0.04, kSmallestPreviousError = 1e-4;

// Newton's iterations of IMPLICIT: stop when the update is this small against the velocities,
// or after this many.
constexpr double kNewtonTolerance = 1e-12;
constexpr int kMaxNewtonIterations = 10;
constexpr double kLinearTolerance = 1e-12;  // relative residual of each Newton system

void sized(std::vector<double>& buffer, std::size_t n) {
  if (buffer.size() != n) buffer.assign(n, 0.0);
}

// out = y + h * k
void axpy(const std::vector<double>& y, double h, const std::vector<double>& k, std::vector<double>& out) {
  for (std::size_t i = 0; i < y.size(); ++i) out[i] = y[i] + h * k[i];
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

struct Stepper::Buffers {
  std::vector<double> k[kStages], temp, next;
  // IMPLICIT: the Jacobian, the Newton matrix and its solvers. The exact Jacobian is not
  // symmetric (a damper's force turns with its spring, so it depends on the positions through
  // the direction) and the Newton matrix need not be definite (a compressed spring's geometric
  // term), which rules out Cholesky and conjugate gradients. BiCGSTAB with a Jacobi
  // preconditioner solves it in a few milliseconds (the diagonal blocks dominate for the steps
  // a user takes), where a sparse LU of the 3D lattice fills in and takes 100-200 ms here.
  // SparseLU stays as the fallback for the rare system BiCGSTAB does not converge on.
  AccelerationJacobian jacobian;
  SparseMatrix newton;
  Eigen::BiCGSTAB<SparseMatrix, Eigen::DiagonalPreconditioner<double>> iterative;
  Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>> lu;
  bool analysed = false;
  Eigen::VectorXd residual, update;
};

OdeSystem jelloSystem(const Model& model, const Pull* pull) {
  OdeSystem system;
  system.derivative = [&model, pull](const double* y, double* dydt) { derivative(model, y, dydt, pull); };
  system.jacobian = [&model, pull](const double* y, AccelerationJacobian& jacobian) {
    accelerationJacobian(model, y, y + kNumCoords, pull, &jacobian);
  };
  return system;
}

int orderOf(Integrator integrator) {
  switch (integrator) {
    case Integrator::Midpoint:
    case Integrator::Verlet:
      return 2;
    case Integrator::RK4:
      return 4;
    case Integrator::RK45:
      return 5;
    default:
      return 1;
  }
}

Stepper::Stepper(Integrator integrator, Tolerances tolerances)
    : integrator_(integrator), tolerances_(tolerances), buffers_(std::make_unique<Buffers>()) {}
Stepper::~Stepper() = default;
Stepper::Stepper(Stepper&&) noexcept = default;
Stepper& Stepper::operator=(Stepper&&) noexcept = default;

void Stepper::step(const Model& model, State& state, double dt, const Pull* pull) {
  step(jelloSystem(model, pull), state.y, dt);
}

void Stepper::step(const OdeSystem& system, std::vector<double>& y, double dt) {
  Buffers& b = *buffers_;
  const std::size_t n = y.size(), half = n / 2;
  for (auto& k : b.k) sized(k, n);
  sized(b.temp, n);
  sized(b.next, n);
  auto f = [&](const std::vector<double>& at, std::vector<double>& out) {
    system.derivative(at.data(), out.data());
    ++stats_.evaluations;
  };
  std::vector<double>&k1 = b.k[0], &k2 = b.k[1], &k3 = b.k[2], &k4 = b.k[3];

  switch (integrator_) {
    case Integrator::Euler:
      // p += dt v_old, v += dt a(p_old, v_old): the starter's explicit Euler.
      f(y, k1);
      for (std::size_t i = 0; i < n; ++i) y[i] += dt * k1[i];
      break;

    case Integrator::Midpoint:
      f(y, k1);
      axpy(y, dt / 2, k1, b.temp);
      f(b.temp, k2);
      for (std::size_t i = 0; i < n; ++i) y[i] += dt * k2[i];
      break;

    case Integrator::RK4:
      f(y, k1);
      axpy(y, dt / 2, k1, b.temp);
      f(b.temp, k2);
      axpy(y, dt / 2, k2, b.temp);
      f(b.temp, k3);
      axpy(y, dt, k3, b.temp);
      f(b.temp, k4);
      for (std::size_t i = 0; i < n; ++i) y[i] += dt / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
      break;

    case Integrator::Symplectic:
      // Semi-implicit Euler: the velocities first, then the positions with the new velocities.
      f(y, k1);
      for (std::size_t i = 0; i < half; ++i) y[half + i] += dt * k1[half + i];
      for (std::size_t i = 0; i < half; ++i) y[i] += dt * y[half + i];
      break;

    case Integrator::Verlet: {
      // Velocity Verlet. The forces also depend on the velocities (dampers), so the new
      // acceleration is taken at an Euler prediction of the new velocities; without dampers
      // this is exactly the symplectic velocity Verlet, and with them it stays second order.
      f(y, k1);
      for (std::size_t i = 0; i < half; ++i) {
        b.temp[i] = y[i] + dt * y[half + i] + dt * dt / 2 * k1[half + i];
        b.temp[half + i] = y[half + i] + dt * k1[half + i];
      }
      f(b.temp, k2);
      for (std::size_t i = 0; i < half; ++i) {
        y[i] = b.temp[i];
        y[half + i] += dt / 2 * (k1[half + i] + k2[half + i]);
      }
      break;
    }

    case Integrator::RK45: {
      // Substeps within [0, dt], none longer than dt, the first as long as the last success.
      double h = rk45Step_ > 0 ? std::min(rk45Step_, dt) : dt, t = 0;
      f(y, b.k[0]);
      while (t < dt) {
        bool last = h >= dt - t - 1e-12 * dt;
        if (last) h = dt - t;
        for (int s = 1; s < kStages; ++s) {
          for (std::size_t i = 0; i < n; ++i) {
            double sum = 0;
            for (int j = 0; j < s; ++j) sum += kA[s][j] * b.k[j][i];
            (s == kStages - 1 ? b.next : b.temp)[i] = y[i] + h * sum;
          }
          f(s == kStages - 1 ? b.next : b.temp, b.k[s]);
        }
        // The scaled errors go into b.temp (the stages are done with it). Their squares
        // overflow below a tolerance of about 1e-160: rmsNorm keeps the norm finite then.
        for (std::size_t i = 0; i < n; ++i) {
          double error = 0;
          for (int j = 0; j < kStages; ++j) error += kErrorWeights[j] * b.k[j][i];
          double scale = tolerances_.atol + tolerances_.rtol * std::max(std::fabs(y[i]), std::fabs(b.next[i]));
          b.temp[i] = h * error / scale;
        }
        double norm = rmsNorm(b.temp.data(), n);
        if (!std::isfinite(norm)) {
          if (!allFinite(b.next)) {  // the state blew up: hand it back, the caller stops
            y = b.next;
            ++stats_.steps;
            break;
          }
          norm = INFINITY;  // an error beyond measure on a finite state: rejected, never accepted
        }
        double factor =
            norm == 0 ? kMaxGrowth
                      : std::clamp(kSafety * std::pow(norm, -kErrorExponent) * std::pow(rk45Error_, kPreviousErrorExponent),
                                   kMinShrink, kMaxGrowth);
        if (norm <= 1) {
          rk45Error_ = std::max(norm, kSmallestPreviousError);
          y.swap(b.next);
          std::swap(b.k[0], b.k[kStages - 1]);  // first same as last
          t = last ? dt : t + h;
          ++stats_.steps;
          rk45Step_ = std::min(h * factor, dt);
        } else {
          ++stats_.rejected;
          if (h <= kSmallestSubstep * dt) {  // no substep a double can take meets the tolerance
            ++stats_.failed;
            std::fill(y.begin(), y.end(), NAN);
            break;
          }
          factor = std::min(factor, 1.0);
        }
        h = std::max(std::min(h * factor, dt), std::min(kSmallestSubstep * dt, h));
      }
      break;
    }

    case Integrator::Implicit: {
      // Backward Euler, v' = v + dt a(p + dt v', v'), by Newton's method on v' with the exact
      // Jacobian: (I - dt dA/dv - dt^2 dA/dp) dv' = -(v' - v - dt a).
      if (!system.jacobian) throw std::logic_error("IMPLICIT needs the Jacobian of the system");
      std::vector<double>& velocity = b.next;  // the Newton iterate v'
      std::copy(y.begin() + half, y.end(), velocity.begin());
      b.residual.resize(static_cast<Eigen::Index>(half));
      for (int iteration = 0; iteration < kMaxNewtonIterations; ++iteration) {
        for (std::size_t i = 0; i < half; ++i) {
          b.temp[i] = y[i] + dt * velocity[i];
          b.temp[half + i] = velocity[i];
        }
        f(b.temp, k1);
        system.jacobian(b.temp.data(), b.jacobian);
        ++stats_.jacobians;
        ++stats_.newtonIterations;
        for (std::size_t i = 0; i < half; ++i) b.residual[i] = -(velocity[i] - y[half + i] - dt * k1[half + i]);
        // I - dt dA/dv - dt^2 dA/dp, written into the Jacobians' own pattern.
        if (b.newton.nonZeros() != b.jacobian.dAdp.nonZeros()) b.newton = b.jacobian.dAdp;
        const double* dp = b.jacobian.dAdp.valuePtr();
        const double* dv = b.jacobian.dAdv.valuePtr();
        double* a = b.newton.valuePtr();
        for (Eigen::Index i = 0; i < b.newton.nonZeros(); ++i) a[i] = -dt * dv[i] - dt * dt * dp[i];
        for (int i : b.jacobian.diagonal) a[i] += 1;
        b.iterative.setTolerance(kLinearTolerance);
        b.iterative.compute(b.newton);
        b.update = b.iterative.solve(b.residual);
        if (b.iterative.info() != Eigen::Success) {
          if (!b.analysed) {
            b.lu.analyzePattern(b.newton);
            b.analysed = true;
          }
          b.lu.factorize(b.newton);
          if (b.lu.info() != Eigen::Success) {  // singular: no step can be taken
            std::fill(velocity.begin(), velocity.end(), NAN);
            break;
          }
          b.update = b.lu.solve(b.residual);
        }
        double largestUpdate = 0, largestVelocity = 0;
        for (std::size_t i = 0; i < half; ++i) {
          velocity[i] += b.update[i];
          largestUpdate = std::max(largestUpdate, std::fabs(b.update[i]));
          largestVelocity = std::max(largestVelocity, std::fabs(velocity[i]));
        }
        if (!(largestUpdate > kNewtonTolerance * (1 + largestVelocity))) break;
      }
      for (std::size_t i = 0; i < half; ++i) {
        y[i] += dt * velocity[i];
        y[half + i] = velocity[i];
      }
      break;
    }
  }
  if (integrator_ != Integrator::RK45) ++stats_.steps;
}

}  // namespace jello
