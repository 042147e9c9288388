// analysis/stability.cpp: the stability verdict of a world (stability.h): the limits at rest, at
// the initial state and with a face on a wall, each integrator's verdict on the world's dt, and the
// step to suggest.

#include "analysis/stability.h"

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

#include "core/output.h"
#include "core/plot.h"
#include "core/progress.h"
#include "model/scenespec.h"
#include "solver/guard.h"
#include "solver/integrators.h"
#include "solver/simulation.h"

namespace jello {

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
  if (limit == 0) return "below " + figureText(kShortestResolvedStep);
  if (std::isnan(limit)) return "none (not finite)";
  return figureText(limit);
}

std::string stepAdvice(double critical, double stableFraction) {
  const double step = suggestedStep(critical, stableFraction);
  // --dt takes any finite step > 0; a subnormal one has lost precision, and 0 is refused.
  if (step >= std::numeric_limits<double>::min() && std::isfinite(step))
    return "try --dt " + figureText(step) + " or --integrator IMPLICIT";
  if (critical == 0) {
    return "no step will do: the stable limit is below " + figureText(kShortestResolvedStep) +
           " s (modes faster than about 1e18 rad/s); soften the world (kElastic, kCollision, mass) "
           "or try --integrator IMPLICIT";
  }
  return "no step will do: " + figureText(100 * stableFraction) + "% of " + figureText(critical) +
         " s is below the smallest normal double; soften the world or try --integrator IMPLICIT";
}

}  // namespace jello
