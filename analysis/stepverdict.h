// analysis/stepverdict.h: the verdict on a run's step for a world at a state, as jello --check
// gives it: what the window's panel says of a change before it is applied (stable, marginal or
// unstable, and the largest stable step). It takes what --check takes (a fraction of a second for
// the course cube, 1 to 3 s for a body of a few thousand points), so the panel runs it on a worker
// thread.
//
// Units: seconds.
#pragma once

#include <string>

#include "analysis/stability.h"
#include "model/world.h"

namespace jello {

// A body of more points than this is judged by the row-sum bound (modes.h, rowSumBound: a second at
// 48^3), not the analysis, which would take minutes.
constexpr int kMostPointsAnalysedLive = 4096;

struct StepVerdict {
  Verdict verdict = Verdict::Stable;
  double limit = 0;      // s: the largest stable step of the integrator; infinite for IMPLICIT
  double suggested = 0;  // s: a round step safely below it (suggestedStep); 0 when none will do
  bool bound = false;    // the limit is the row-sum bound (a lower bound), not the analysis's
  std::string text;      // "unstable: dt 0.002 s is above RK4's limit 0.00118 s; try dt 0.0009 s"
};

// The verdict on `run`'s integrator and dt for `world` starting from `state` (which holds the
// world's body's points). A world beyond what doubles resolve is unstable at every step.
StepVerdict judgeStep(const World& world, const State& state, const RunSettings& run);

}  // namespace jello
