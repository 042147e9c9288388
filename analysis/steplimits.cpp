// analysis/steplimits.cpp: the largest stable steps over a world's modes (steplimits.h), found by
// running each integrator on each mode, and the limits observed in real runs.

#include "analysis/steplimits.h"

#include <sys/stat.h>
#include <unistd.h>

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

#include "analysis/stability.h"
#include "core/output.h"
#include "core/plot.h"
#include "core/progress.h"
#include "model/scenespec.h"
#include "solver/guard.h"
#include "solver/integrators.h"
#include "solver/simulation.h"

namespace jello {

const std::vector<Integrator> kExplicitIntegrators = integratorsWithStepLimit();

namespace {

constexpr double kLargestStep = 1.0;  // s: no limit beyond this is reported
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

}  // namespace

std::string figureText(double x) {
  if (std::isinf(x)) return "unbounded";
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", x);
  return text;
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
    const SpringConstants springs = springConstantsOf(world);  // a scene's by kind, all equal
    dampingPerRadian = free.highestFrequency * springs.d[0] / springs.k[0];
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

}  // namespace jello
