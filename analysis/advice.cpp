// analysis/advice.cpp: the diagnosis of a diverged run (divergenceMessage, stability.h): where,
// why, and what to change.

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <fstream>
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

namespace {

// The end of a divergence message for a body too large to analyse while the user waits.
std::string largeBodyAdvice(const World& world, const State& initial, Integrator integrator,
                            double dt, int points) {
  const char* name = integratorName(integrator);
  const std::string head = "dt=" + figureText(dt) + " with " + name + " on a body of " +
                           std::to_string(points) + " points";
  const std::string check = " (jello --check finds the limit itself, slowly for a body this large)";
  const RowSumBound rows = rowSumBound(makeModel(world, initial), initial, integrator);
  const double bound = rows.limit;
  if (std::isnan(bound)) {
    return head +
           ": the forces' derivatives at the initial state are not finite numbers; no step "
           "will do";
  }
  if (bound == 0) return head + ": " + stepAdvice(0);
  if (!rows.useful()) {
    return head + ": " + name + " is stable only as far as damping holds the modes, which row " +
           "sums cannot bound" + check + "; try --integrator RK4 or --integrator IMPLICIT";
  }
  if (dt > bound) {
    return head + ": the initial state's modes are stable below " + limitText(bound) +
           " (a bound from its row sums)" + check + "; " + stepAdvice(bound);
  }
  return head + " is below " + limitText(bound) +
         ", where the initial state's modes are stable (a bound from its row sums), but the "
         "motion left it (a harder contact?)" +
         check + "; " + stepAdvice(dt);
}

}  // namespace

const char* const kStartBeyondGuard =
    "the initial state is already beyond the guard (not finite, or more than 100 m from the "
    "origin): no step will do; start the cube inside the box";

std::string divergenceMessage(const World& world, const State& initial, Integrator integrator,
                              double dt, long long step, double time, const std::string& reason) {
  char head[160];
  std::snprintf(head, sizeof head, "diverged at step %lld (t=%.6g s): ", step, time);
  std::string out = head + reason + "; ";
  const char* name = integratorName(integrator);
  // Checks of microseconds first: an eigen-analysis of such a world would say nothing, slowly.
  if (findDivergedPoint(initial) >= 0) return out + kStartBeyondGuard;
  const std::string beyond = beyondDoubles(world, initial);
  if (!beyond.empty()) {
    return out + "the world's numbers are beyond what double arithmetic can simulate (" + beyond +
           "): no step will do";
  }
  // A body larger than the course cube's is analysed by Lanczos iterations alone (slowestModes),
  // which take seconds at 10^3 points and minutes at 48^3: the message gives the step its row
  // sums guarantee instead, at once. (An integrator without a limit needs no analysis: below.)
  const int points = bodyOf(world).count();
  if (points > kNumPoints && integratorInfo(integrator).boundedStableStep)
    return out + largeBodyAdvice(world, initial, integrator, dt, points);
  // The rest lattice's limit takes milliseconds; when it is already below what the analysis
  // resolves, the springs alone rule every step out and the eigensolves are spared.
  if (integratorInfo(integrator).boundedStableStep &&
      criticalStep(integrator, lineariseAtRest(world).modes) == 0)
    return out + "dt=" + figureText(dt) + " with " + name + ": " + stepAdvice(0);
  double limit = predictedLimit(world, initial, integrator);
  if (limit == 0) return out + "dt=" + figureText(dt) + " with " + name + ": " + stepAdvice(0);
  if (std::isnan(limit)) {
    return out +
           "the forces' derivatives at the initial state are not finite numbers: the world's "
           "numbers are beyond what double arithmetic can simulate, and no step will do";
  }
  if (!std::isfinite(limit)) {
    return out + "dt=" + figureText(dt) + " with " + name + ", which has no stability limit; " +
           (dt / 2 >= std::numeric_limits<double>::min()
                ? "try a smaller --dt"
                : "no step will do (dt is the smallest a double holds)");
  }
  if (dt > limit) {
    return out + "dt=" + figureText(dt) + " exceeds " + name + "'s stable limit " +
           limitText(limit) + " for this world; " + stepAdvice(limit);
  }
  return out + "dt=" + figureText(dt) + " is within " + name + "'s predicted limit " +
         figureText(limit) +
         " for this world, but the motion left it (a harder contact than a face on a wall?); " +
         stepAdvice(dt);
}

}  // namespace jello
