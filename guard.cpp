// guard.cpp: energy bounds for the runtime guard.

#include "guard.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace jello {

namespace {

constexpr double kEnergyMargin = 4;     // the state may hold 4 times the bound: rounding, integrators' drift
constexpr double kEnergyFloor = 1e-6;   // J: below this nothing is judged

}  // namespace

double mechanicalEnergy(const Model& model, const State& state) {
  const World& w = model.world;
  double energy = 0;
  for (int q = 0; q < kNumPoints; ++q) energy += 0.5 * w.mass * dot(load(state.v(), q), load(state.v(), q));
  for (const Spring& s : model.springs) {
    double stretch = length(load(state.p(), s.a) - load(state.p(), s.b)) - s.rest;
    energy += 0.5 * w.kElastic * stretch * stretch;
  }
  for (int c = 0; c < kNumCoords; ++c) {
    double beyond = std::max(0.0, std::fabs(state.p()[c]) - kBoxHalfSize);
    energy += 0.5 * w.kCollision * beyond * beyond;
  }
  if (w.hasPlane) {
    // The normalised plane: its squared normal neither overflows nor underflows.
    const Plane& pl = model.plane;
    double norm2 = pl.a * pl.a + pl.b * pl.b + pl.c * pl.c;
    for (int q = 0; q < kNumPoints; ++q) {
      double s = planeValue(pl, load(state.p(), q));
      if (s * model.planeSide < 0) energy += 0.5 * w.kCollision * s * s / norm2;
    }
  }
  return energy;
}

DivergenceGuard::DivergenceGuard(const Model& model, const State& initial) : model_(model) {
  double largestField = 0;
  const std::vector<double>& f = model.world.field.forces;
  for (std::size_t i = 0; i + 2 < f.size(); i += 3)
    largestField = std::max(largestField, std::sqrt(f[i] * f[i] + f[i + 1] * f[i + 1] + f[i + 2] * f[i + 2]));
  energyRate_ = largestField * std::sqrt(kNumPoints / (2 * model.world.mass));
  restart(initial, 0);
}

void DivergenceGuard::restart(const State& state, double time) {
  rootEnergy_ = std::sqrt(mechanicalEnergy(model_, state));
  start_ = time;
}

std::string DivergenceGuard::check(const State& state, double time) const {
  int bad = findDivergedPoint(state);
  if (bad >= 0) {
    Vec3 p = load(state.p(), bad), v = load(state.v(), bad);
    bool finite = std::isfinite(dot(p, p)) && std::isfinite(dot(v, v));
    return "point p" + latticeLabel(bad) + (finite ? " is more than 100 m from the origin" : " is no longer finite");
  }
  double bound = rootEnergy_ + energyRate_ * (time - start_);
  double energy = mechanicalEnergy(model_, state);
  if (energy > kEnergyMargin * bound * bound + kEnergyFloor) {
    char text[160];
    std::snprintf(text, sizeof text, "its energy, %.3g J, is beyond what the world's forces can supply (%.3g J)", energy,
                  bound * bound);
    return text;
  }
  return "";
}

}  // namespace jello
