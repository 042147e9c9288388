// analysis/stepverdict.cpp: the verdict on a run's step (stepverdict.h).

#include "analysis/stepverdict.h"

#include <cmath>
#include <limits>

#include "analysis/modes.h"
#include "analysis/steplimits.h"
#include "model/model.h"
#include "solver/integrators.h"

namespace jello {

namespace {

// The verdict's line: what it is, the step against the limit, and what to do about it.
std::string verdictText(const StepVerdict& v, const RunSettings& run) {
  const std::string name = integratorName(run.integrator);
  if (std::isinf(v.limit)) return "stable: " + name + " is stable at every step";
  if (std::isnan(v.limit)) return "unstable: the forces are not finite at this state";
  const std::string limit =
      std::string(v.bound ? "the bound on " : "") + name + "'s limit " + limitText(v.limit) + " s";
  std::string text = std::string(verdictName(v.verdict)) + ": dt " + figureText(run.dt) + " s is ";
  text += v.verdict == Verdict::Unstable
              ? "above " + limit
              : figureText(std::round(100 * run.dt / v.limit)) + "% of " + limit;
  if (v.verdict != Verdict::Stable)
    text += v.suggested > 0 ? "; try dt " + figureText(v.suggested) + " s" : "; no step will do";
  return text;
}

}  // namespace

StepVerdict judgeStep(const World& world, const State& state, const RunSettings& run) {
  StepVerdict v;
  double fraction = kStableFraction;
  if (const std::string beyond = beyondDoubles(world, state); !beyond.empty()) {
    v.limit = 0;
  } else if (!integratorInfo(run.integrator).boundedStableStep) {
    v.limit = INFINITY;  // IMPLICIT: no analysis needed
  } else if (bodyOf(world).count() > kMostPointsAnalysedLive) {
    const RowSumBound rows = rowSumBound(makeModel(world, state), state, run.integrator);
    v.limit = rows.limit;
    v.bound = true;
    if (!rows.useful()) {  // EULER, MIDPOINT on a large body: marginal, and no step to suggest
      v.verdict = Verdict::NearLimit;
      v.text = std::string("marginal: ") + integratorName(run.integrator) +
               " is stable only as far as damping holds the modes, which the bound for a body " +
               "this large cannot measure; try RK4 or IMPLICIT";
      return v;
    }
  } else {
    const StabilityReport report = analyseStability(world, state);
    v.limit = report.verdictLimit(run.integrator);
    fraction = report.stableFraction;
  }
  v.verdict = std::isnan(v.limit) ? Verdict::Unstable : verdictFor(run.dt, v.limit, fraction);
  const double step = std::isfinite(v.limit) ? suggestedStep(v.limit, fraction) : 0;
  v.suggested = step >= std::numeric_limits<double>::min() && std::isfinite(step) ? step : 0;
  v.text = verdictText(v, run);
  return v;
}

}  // namespace jello
