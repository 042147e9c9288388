// guard.cpp: energy bounds for the runtime guard.

#include "solver/guard.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/assert.h"

namespace jello {

namespace {

constexpr double kEnergyMargin =
    4;  // the state may hold 4 times the bound: rounding, integrators' drift
constexpr double kEnergyFloor = 1e-6;  // J: below this nothing is judged

}  // namespace

double mechanicalEnergy(const Model& model, const State& state) {
  double energy = 0;
  const int n = model.points();
  for (int q = 0; q < n; ++q)
    energy += 0.5 * model.pointMass[q] * dot(load(state.v(), q, n), load(state.v(), q, n));
  for (const auto& term : model.forces.terms) term->addEnergy(state.p(), &energy);
  return energy;
}

DivergenceGuard::DivergenceGuard(const Model& model, const State& initial) : model_(&model) {
  JELLO_ASSERT(initial.points() == model.points());
  // The reader's rule, every mass > 0: the energy rate divides by the lightest.
  const double lightest = *std::min_element(model.pointMass.begin(), model.pointMass.end());
  JELLO_ASSERT(lightest > 0);
  double largestForce = 0;
  for (const auto& term : model.forces.terms) largestForce += term->largestExternalForce();
  energyRate_ = largestForce * std::sqrt(model.points() / (2 * lightest));
  restart(initial, 0);
}

void DivergenceGuard::restart(const State& state, double time) {
  rootEnergy_ = std::sqrt(mechanicalEnergy(*model_, state));
  start_ = time;
}

std::string DivergenceGuard::check(const State& state, double time) const {
  int bad = findDivergedPoint(state);
  if (bad >= 0) {
    const int n = state.points();
    Vec3 p = load(state.p(), bad, n), v = load(state.v(), bad, n);
    bool finite = std::isfinite(dot(p, p)) && std::isfinite(dot(v, v));
    return "point p" + model_->body().label(bad) +
           (finite ? " is more than 100 m from the origin" : " is no longer finite");
  }
  double bound = rootEnergy_ + energyRate_ * (time - start_);
  double energy = mechanicalEnergy(*model_, state);
  if (energy > kEnergyMargin * bound * bound + kEnergyFloor) {
    char text[160];
    std::snprintf(text, sizeof text,
                  "its energy, %.3g J, is beyond what the world's forces can supply (%.3g J)",
                  energy, bound * bound);
    return text;
  }
  return "";
}

}  // namespace jello
