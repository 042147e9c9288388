// integrators.cpp: explicit time steppers over a derivative function.

#include "integrators.h"

#include <stdexcept>

namespace jello {

namespace {

void resize(std::vector<double>& buffer, std::size_t n) {
  if (buffer.size() != n) buffer.assign(n, 0.0);
}

// out = y + h * k
void axpy(const std::vector<double>& y, double h, const std::vector<double>& k, std::vector<double>& out) {
  for (std::size_t i = 0; i < y.size(); ++i) out[i] = y[i] + h * k[i];
}

}  // namespace

void eulerStep(const DerivativeFn& f, std::vector<double>& y, double dt, Workspace& ws) {
  resize(ws.k1, y.size());
  f(y.data(), ws.k1.data());
  for (std::size_t i = 0; i < y.size(); ++i) y[i] += dt * ws.k1[i];
}

void rk4Step(const DerivativeFn& f, std::vector<double>& y, double dt, Workspace& ws) {
  const std::size_t n = y.size();
  for (auto* buffer : {&ws.k1, &ws.k2, &ws.k3, &ws.k4, &ws.temp}) resize(*buffer, n);
  f(y.data(), ws.k1.data());
  axpy(y, dt / 2, ws.k1, ws.temp);
  f(ws.temp.data(), ws.k2.data());
  axpy(y, dt / 2, ws.k2, ws.temp);
  f(ws.temp.data(), ws.k3.data());
  axpy(y, dt, ws.k3, ws.temp);
  f(ws.temp.data(), ws.k4.data());
  for (std::size_t i = 0; i < n; ++i) {
    y[i] += dt / 6 * (ws.k1[i] + 2 * ws.k2[i] + 2 * ws.k3[i] + ws.k4[i]);
  }
}

bool isImplemented(Integrator integrator) {
  return integrator == Integrator::Euler || integrator == Integrator::RK4;
}

void step(const Model& model, Integrator integrator, double dt, State& state, Workspace& ws, const Pull* pull) {
  DerivativeFn f = [&model, pull](const double* y, double* dydt) { derivative(model, y, dydt, pull); };
  switch (integrator) {
    case Integrator::Euler:
      eulerStep(f, state.y, dt, ws);
      return;
    case Integrator::RK4:
      rk4Step(f, state.y, dt, ws);
      return;
    default:
      throw std::logic_error(std::string("integrator not implemented: ") + integratorName(integrator));
  }
}

}  // namespace jello
