// analysis/report.cpp: the work-precision study of jello --report.
//
// Every run starts from the world's initial state and ends at the same time T, so that all
// of them are compared at one instant with one reference: RK4 at a much smaller step, whose
// own error is estimated against a run at twice its step (see Reference). Steps are T/2^k, so
// that every run lands on T exactly (the world's own dt need not: its last step is shortened,
// see simulate).

#include "analysis/report.h"

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
#include "analysis/runqueue.h"
#include "analysis/stability.h"
#include "core/output.h"
#include "core/plot.h"
#include "core/progress.h"
#include "io/scenereader.h"
#include "solver/integrators.h"
#include "solver/physics.h"
#include "solver/simulation.h"

namespace jello {

namespace {

// The lines on stdout for one recommendation ("as accurate as the world's own"): the setting,
// the command that runs it, and the one that keeps it in a world file.
void printChoice(const std::string& what, const std::string& worldPath,
                 const std::string& reportDir, const Choice& choice, const ReportRow* own) {
  const std::string leftOut = choice.leftOut.empty() ? "" : "  (" + choice.leftOut + ")\n";
  if (!choice.best) {
    std::printf("%s: none of the runs\n%s", what.c_str(), leftOut.c_str());
    return;
  }
  if (choice.best == own) {
    std::printf("%s: nothing cheaper than the world's own setting\n%s", what.c_str(),
                leftOut.c_str());
    return;
  }
  auto print = [&](const ReportRow& row) {
    const Advice advice = advise(worldPath, reportDir, row, own);
    std::printf("  run it:  %s\n", advice.run.c_str());
    if (!advice.keep.empty()) std::printf("  keep it: %s\n", advice.keep.c_str());
    if (!advice.sceneKeys.empty())
      std::printf("  keep it: %s in %s\n", advice.sceneKeys.c_str(), printable(worldPath).c_str());
  };
  std::printf("%s: %s\n", what.c_str(),
              advise(worldPath, reportDir, *choice.best, own).setting.c_str());
  print(*choice.best);
  std::printf("%s", leftOut.c_str());
  if (worldFileHolds(*choice.best)) return;
  std::printf("  (%s)\n", noWorldFileNote().c_str());
  if (!choice.inWorldFile || choice.inWorldFile == own) {
    std::printf("  the cheapest setting a world file can hold: %s\n",
                choice.inWorldFile ? "the world's own" : "none of the runs");
    return;
  }
  std::printf("  the cheapest setting a world file can hold: %s\n",
              advise(worldPath, reportDir, *choice.inWorldFile, own).setting.c_str());
  print(*choice.inWorldFile);
}

// The lines on stdout: where the report is, and what it recommends.
void printReportSummary(const std::string& worldPath, const ReportOptions& options, bool drawn,
                        std::size_t runs, const Reference& reference,
                        const std::vector<OrderCheck>& orders, const Recommendations& recommended) {
  std::printf(
      "%s: report in %s/ (report.csv, report.md%s): %zu runs to T=%g s; reference RK4 dt=%g, its "
      "error %.3g m\n",
      printable(worldPath).c_str(), printable(options.dir).c_str(), drawn ? ", report.png" : "",
      runs, options.time, reference.step, reference.error);
  for (const OrderCheck& c : orders)
    if (c.far) std::printf("note: %s\n", orderWarningLine(c, reference.contacts).c_str());
  const bool first = recommended.own && !recommended.own->diverged;
  if (first)
    printChoice("as accurate as the world's own", worldPath, options.dir, recommended.asAccurate,
                recommended.own);
  const std::string within = "within " + reportNumber(options.visualTolerance) + " m";
  // The same setting twice: its commands once (a second createWorld would refuse its file).
  if (first && recommended.looksSame.best && recommended.looksSame.best != recommended.own &&
      recommended.looksSame.best == recommended.asAccurate.best)
    std::printf("%s: the same setting\n", within.c_str());
  else
    printChoice(within, worldPath, options.dir, recommended.looksSame, recommended.own);
}

// Each row's error against the reference: RMS and largest over the points at T.
void measureErrors(Measured* measured) {
  std::vector<ReportRow>& rows = measured->rows;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (!rows[i].diverged)
      rows[i].rmsError = rms(measured->ends[i], measured->reference.end, &rows[i].maxError);
  }
}

}  // namespace

Outcome runReport(const RunOptions& runOptions, const ReportOptions& options) {
  WorldFile file;
  if (Outcome loaded = loadRun(runOptions, &file); !loaded.ok()) return loaded;
  const World& world = file.world;
  const RunSettings& own = file.run;
  const Model model = makeModel(world, file.state);
  const double T = options.time;
  // The world's own setting runs to T at the world's dt (the sweeps' steps are T / 2^k).
  if (!stepsForTime(T, own.dt)) return failed("--report: " + tooManyStepsMessage(T, own.dt));
  std::vector<Integrator> integrators = options.integrators;
  if (integrators.empty())
    for (const IntegratorInfo& row : integratorTable()) integrators.push_back(row.integrator);

  // Claim the folder and check every file before the long work, not after it.
  FolderClaim claim;
  const Existing existing = options.overwrite ? Existing::Replace : Existing::Refuse;
  const bool made = ::access(options.dir.c_str(), F_OK) != 0;  // removed again if left empty
  try {
    claim =
        claimOutputs(options.dir, {"report.csv", "report.md", "report.gp", "report.png"}, existing);
  } catch (const OutputError& e) {
    return failed(std::string("--report: ") + e.what());
  }

  ReportProgress progress(reportItemCount(integrators));
  const Study study{model, file.state, T, progress};
  Measured measured;
  measureAll(study, integrators, own, runOptions.tolerances, &measured);
  const Reference& reference = measured.reference;
  if (reference.diverged) {
    if (made) ::rmdir(options.dir.c_str());  // only when empty: the folder this run made
    return diverged("--report: the reference run (RK4 at dt=" + reportNumber(reference.step) +
                    ") diverged; no report");
  }
  std::vector<ReportRow>& rows = measured.rows;
  measureErrors(&measured);
  assignCosts(rows);
  // The stability verdicts of --check, which every recommended step must pass.
  const StabilityReport stability = analyseStability(world, file.state);
  const Recommendations recommended = recommend(rows, options.visualTolerance, stability);
  std::vector<OrderCheck> orders;
  for (Integrator integrator : integrators)
    orders.push_back(checkOrder(rows, integrator, reference.error, reference.contacts));
  progress.finish();

  try {
    writeReportFiles(runOptions.worldPath, options, integrators, rows, reference, orders,
                     recommended);
  } catch (const OutputError& e) {
    return failed(e.what());
  }
  const std::string whyNotDrawn = drawWithGnuplot(options.dir, "report.gp", "report.png", existing);
  const bool drawn = whyNotDrawn.empty();
  printReportSummary(runOptions.worldPath, options, drawn, rows.size(), reference, orders,
                     recommended);
  if (drawn) return succeeded();
  // Without gnuplot the data files are the report; a gnuplot that failed is a failure.
  const std::string notDrawn = "report.png was not drawn: " + whyNotDrawn;
  return whyNotDrawn == kGnuplotMissing ? succeeded(notDrawn) : failed(notDrawn);
}

}  // namespace jello
