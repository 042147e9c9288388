// analysis/recommend.cpp: what jello --report recommends (reportstudy.h): the cheapest settings
// within an error that --check calls stable, and the commands that run and keep them.

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <functional>
#include <sstream>

#include "analysis/reportstudy.h"
#include "analysis/stability.h"
#include "core/output.h"
#include "core/progress.h"
#include "io/scenereader.h"
#include "solver/integrators.h"
#include "solver/physics.h"
#include "solver/simulation.h"

namespace jello {

namespace {

// Whether --check calls the row's fixed step stable (the one definition: verdictFor, below the
// world's stable fraction of the integrator's limit). A run that did not diverge over T can
// still be marginal: the report recommends only steps --check would keep. The world's own
// setting is the user's already, and stays.
// RK45 is swept by its tolerance: its dt is only the cap its error control keeps the step under.
bool checkCallsStable(const ReportRow& row, const StabilityReport& stability) {
  return row.worldsOwn || sweepsTolerance(row.integrator) ||
         verdictFor(row.dt, stability.verdictLimit(row.integrator), stability.stableFraction) ==
             Verdict::Stable;
}

// The note on a cheaper run left out of a recommendation, e.g. "MIDPOINT dt=0.0009765625 is
// cheaper but left out: --check calls it marginal (100% of its limit 0.00098 s)".
std::string leftOutNote(const ReportRow& row, const StabilityReport& stability) {
  const double limit = stability.verdictLimit(row.integrator);
  return std::string(integratorName(row.integrator)) + " dt=" + reportNumber(row.dt) +
         " is cheaper but left out: --check calls it " +
         verdictName(verdictFor(row.dt, limit, stability.stableFraction)) +
         textf(" (%.0f%% of its limit %s s; stable is below %.0f%%)", 100 * row.dt / limit,
               reportNumber(limit).c_str(), 100 * stability.stableFraction);
}

Choice cheapestWithin(const std::vector<ReportRow>& rows, double limit,
                      const StabilityReport& stability) {
  auto cheapest = [&](bool inWorldFile, bool stable) {
    const ReportRow* best = nullptr;
    for (const ReportRow& row : rows)
      if (!row.diverged && row.rmsError <= limit && (!inWorldFile || worldFileHolds(row)) &&
          (!stable || checkCallsStable(row, stability)) && (!best || row.cost < best->cost))
        best = &row;
    return best;
  };
  Choice choice;
  choice.best = cheapest(false, true);
  if (choice.best && !worldFileHolds(*choice.best)) choice.inWorldFile = cheapest(true, true);
  const ReportRow* any = cheapest(false, false);
  if (any && any != choice.best) choice.leftOut = leftOutNote(*any, stability);
  return choice;
}

}  // namespace

void assignCosts(std::vector<ReportRow>& rows) {
  std::vector<double> paces;  // s an evaluation, of each explicit run
  for (const ReportRow& row : rows)
    if (row.integrator != Integrator::Implicit && row.evaluations > 0 && row.cpuSeconds > 0)
      paces.push_back(row.cpuSeconds / static_cast<double>(row.evaluations));
  double pace = NAN;
  if (!paces.empty()) {
    std::nth_element(paces.begin(), paces.begin() + paces.size() / 2, paces.end());
    pace = paces[paces.size() / 2];
  }
  for (ReportRow& row : rows)
    row.cost = row.integrator == Integrator::Implicit || std::isnan(pace)
                   ? row.cpuSeconds
                   : pace * static_cast<double>(row.evaluations);
}

Recommendations recommend(const std::vector<ReportRow>& rows, double visualTolerance,
                          const StabilityReport& stability) {
  Recommendations r;
  for (const ReportRow& row : rows)
    if (row.worldsOwn) r.own = &row;
  if (r.own && !r.own->diverged) r.asAccurate = cheapestWithin(rows, r.own->rmsError, stability);
  r.looksSame = cheapestWithin(rows, visualTolerance, stability);
  return r;
}

Advice advise(const std::string& worldPath, const std::string& reportDir, const ReportRow& row,
              const ReportRow* own) {
  Advice advice;
  advice.setting = settingText(row) + ": " + reportNumber(row.cpuSeconds) + " s, error " +
                   reportNumber(row.rmsError) + " m";
  if (own && !own->diverged && own->cost > 0 && row.cost > 0)
    advice.setting += ", " + speedAgainstOwn(own->cost, row.cost);
  advice.run = shellLine(runCommand(worldPath, row));
  if (isSceneFile(worldPath)) {
    if (worldFileHolds(row))
      advice.sceneKeys = "integrator = \"" + std::string(integratorName(row.integrator)) +
                         "\" and dt = " + exactNumber(row.dt);
    return advice;
  }
  const std::vector<std::string> keep = worldFileCommand(worldPath, reportDir, row);
  if (!keep.empty()) advice.keep = shellLine(keep);
  return advice;
}

}  // namespace jello
