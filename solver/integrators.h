// integrators.h: time steppers (docs/physics.md).
//
// An integrator sees only an ODE system: the derivative dy/dt = f(y) of a flat state vector y
// and, for IMPLICIT, the Jacobian of the accelerations. For the jello, y = [p; v] (State::y):
// the integrators that treat positions and velocities differently (SYMPLECTIC, VERLET,
// IMPLICIT) take the first half of y as positions and the second as velocities. One step
// advances time by dt (seconds); RK45 takes as many adaptive substeps as it needs within it.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "model/model.h"
#include "model/world.h"

namespace jello {

struct Workers;       // physics.h
struct NewtonBlocks;  // jacobian.h: only IMPLICIT's step needs its Eigen types

// A body to run on a range [begin, end) of a state's elements (OdeSystem::inRanges).
struct RangeBody {
  void (*call)(const void* context, std::size_t begin, std::size_t end);
  const void* context;
};

struct OdeSystem {
  // Writes f(y) into dydt; both hold the same number of doubles.
  std::function<void(const double* y, double* dydt)> derivative;
  // For y = [p; v]: the matrix I - cv dA/dv - cp dA/dp, A the accelerations. Needed by IMPLICIT
  // only.
  std::function<void(const double* y, double cv, double cp, NewtonBlocks& matrix)> newtonMatrix;
  // Runs body on ranges covering [0, n), on the threads that share the derivative (the jello's,
  // physics.h); empty: on [0, n) here. The integrators' element-wise loops go through it: each
  // element's arithmetic is the same whichever range it falls in, so the results are the same bits.
  std::function<void(std::size_t n, const RangeBody& body)> inRanges;
};

// Error control of RK45: a substep is accepted when its estimated local error, per component,
// is within atol + rtol * |y| in the root-mean-square sense.
struct Tolerances {
  double rtol = 1e-6;
  double atol = 1e-9;
};

// What the steps cost.
struct StepStats {
  long long steps = 0;        // accepted (sub)steps
  long long rejected = 0;     // RK45's rejected substeps
  long long evaluations = 0;  // derivative evaluations
  long long jacobians = 0;    // Jacobian assemblies (IMPLICIT)
  long long newtonIterations = 0;
  // RK45 steps abandoned: their error estimate stayed above the tolerance down to the smallest
  // substep, kSmallestSubstep * dt; such a step leaves NaN in the state (see Stepper::step).
  long long failed = 0;
};

// RK45's smallest substep, as a fraction of dt: 16 machine epsilons, as MATLAB's ode45 bounds
// its step by 16 eps |t|. Below it a substep is lost in the rounding of the time within the
// step, and the error estimate is rounding, not truncation: a tolerance the estimate still
// exceeds there (--rtol 1e-300) cannot be met by double arithmetic.
constexpr double kSmallestSubstep = 16 * 2.220446049250313e-16;

// The root mean square of x[0..n), computed without overflow or underflow: the plain sum of
// squares where it stays in range (bit for bit the usual formula), otherwise the sum of the
// squares of x / max|x| (as hypot does). Infinite when an x is, NaN when an x is NaN.
double rmsNorm(const double* x, std::size_t n);

// What a step function works with: its Stepper's buffers, tolerances, counts and RK45's memory
// of its last substep. Defined in integrators.cpp; a step function exists only there.
struct StepWork;
// One step of dt seconds of `system` from y, in place (see Stepper::step).
using StepFunction = void (*)(StepWork& work, const OdeSystem& system, std::vector<double>& y,
                              double dt);

// The integrator table: one row per integrator, the only source of their orders, help text,
// properties and steps (their names are model/integrator.h's). integrators.cpp holds the rows,
// indexed by the enum in its order, which is the order every listing uses (--help, --check,
// --report, --bench). A new integrator is an enumerator and a name in model/integrator.h and a
// row and a step function in integrators.cpp.
struct IntegratorInfo {
  Integrator integrator;
  int order;  // theoretical order of convergence in dt (RK45: of the solution it keeps)
  bool boundedStableStep;   // false when A-stable: no dt makes it diverge (IMPLICIT)
  bool needsJacobian;       // its steps use OdeSystem::jacobian
  const char* description;  // one line for help text, lower case, no final full stop
  StepFunction step;
  const char* name() const { return integratorName(integrator); }  // model/integrator.h's
};

// Every row, in enum order. Static storage: references stay valid for the whole program.
const std::array<IntegratorInfo, kIntegratorCount>& integratorTable();
const IntegratorInfo& integratorInfo(Integrator integrator);

// The theoretical order of convergence (the table's).
int orderOf(Integrator integrator);
// The integrators with a bounded stable step (all but the A-stable ones), in table order.
std::vector<Integrator> integratorsWithStepLimit();
// The lines of --help that list the integrators: name, order and description, one a line.
std::string integratorHelp();

// Advances a state one step at a time with one integrator, reusing its buffers: a step
// allocates nothing once they are sized (IMPLICIT's sparse solver excepted).
class Stepper {
 public:
  explicit Stepper(Integrator integrator, Tolerances tolerances = {});
  ~Stepper();
  Stepper(Stepper&&) noexcept;
  Stepper& operator=(Stepper&&) noexcept;

  // One step of dt. RK45 takes substeps; when one is rejected at the smallest substep
  // (kSmallestSubstep * dt), the step is abandoned: y becomes NaN, so that no caller takes it
  // for a result, and stats().failed counts it.
  void step(const OdeSystem& system, std::vector<double>& y, double dt);
  // The jello: one step of the model, with the user's pull if any (defined by physics.cpp).
  void step(const Model& model, State& state, double dt, const Pull* pull = nullptr,
            const Workers* workers = nullptr);

  // A new Stepper's memory (RK45's last step, IMPLICIT's solver, the statistics), the buffers of
  // the stages kept (their values are never read before a step writes them): the next steps are a
  // new Stepper's bit for bit, without allocating again (a large body's first touch of fresh
  // buffers costs as much as a step).
  void restart();
  Integrator integrator() const { return integrator_; }
  const StepStats& stats() const;

 private:
  Integrator integrator_;
  StepFunction step_;  // the table's, looked up once
  std::unique_ptr<StepWork> work_;
};

}  // namespace jello
