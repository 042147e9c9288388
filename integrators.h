// integrators.h: time steppers (SPEC.md section 2, "Time stepping").
//
// An integrator sees only the derivative dy/dt = f(y) of a flat state vector y; it knows
// nothing of springs or walls. For the jello, y = [p; v] (State::y) and f is derivative().
// One step advances time by dt (seconds).
#pragma once

#include <functional>
#include <vector>

#include "physics.h"
#include "world.h"

namespace jello {

// f(y, dydt): writes the derivative of y into dydt; both hold the same number of doubles.
using DerivativeFn = std::function<void(const double* y, double* dydt)>;

// Buffers reused from step to step, so that a step allocates nothing once they are sized.
struct Workspace {
  std::vector<double> k1, k2, k3, k4, temp;
};

// Explicit Euler: y += dt f(y). For the jello that is p += dt v_old, v += dt a(p_old, v_old).
void eulerStep(const DerivativeFn& f, std::vector<double>& y, double dt, Workspace& ws);
// Classic fourth-order Runge-Kutta.
void rk4Step(const DerivativeFn& f, std::vector<double>& y, double dt, Workspace& ws);

// True for the integrators this build can run.
bool isImplemented(Integrator integrator);

// Advances the jello state by one step of `integrator` (which must be implemented), with the
// user's pull when there is one.
void step(const Model& model, Integrator integrator, double dt, State& state, Workspace& ws,
          const Pull* pull = nullptr);

}  // namespace jello
