// analysis/reportfiles.cpp: jello --report's files (reportstudy.h): report.csv, report.md and the
// gnuplot script of report.png.

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
#include "core/plot.h"
#include "core/progress.h"
#include "io/scenereader.h"
#include "solver/integrators.h"
#include "solver/physics.h"
#include "solver/simulation.h"

namespace jello {

namespace {

// The y axis of the plot: the errors drawn and the visual tolerance, with room around them (a
// line on the plot's edge is not seen).
std::string yRange(const std::vector<ReportRow>& rows, double visualTolerance) {
  double lowest = visualTolerance, highest = visualTolerance;
  for (const ReportRow& r : rows)
    if (!r.diverged && r.rmsError > 0)
      lowest = std::min(lowest, r.rmsError), highest = std::max(highest, r.rmsError);
  std::ostringstream range;
  range << "set yrange [" << lowest / 4 << ":" << highest * 4 << "]\n";
  return range.str();
}

std::string gnuplotScript(const std::vector<ReportRow>& rows,
                          const std::vector<Integrator>& integrators, double floor,
                          double visualTolerance, const std::string& title) {
  std::ostringstream gp;
  gp << "# Made by jello --report; run `gnuplot report.gp` in this folder to draw report.png "
        "again.\n";
  std::string plots;
  for (Integrator integrator : integrators) {
    std::string name = integratorName(integrator);
    gp << "$" << name << " << EOD\n";
    int points = 0;
    for (const ReportRow& r : rows)
      if (r.integrator == integrator && !r.diverged && r.rmsError > 0 && !r.worldsOwn) {
        gp << r.cpuSeconds << " " << r.rmsError << "\n";
        ++points;
      }
    gp << "EOD\n";
    if (points == 0) continue;
    plots += (plots.empty() ? "" : ", ") + std::string("$") + name +
             " using 1:2 with linespoints lw 2 pt 7 title " +
             gnuplotString(legendLabel(integrator, fittedOrder(rows, integrator, floor)));
  }
  gp << "$OWN << EOD\n";
  int ownPoints = 0;
  for (const ReportRow& r : rows)
    if (r.worldsOwn && !r.diverged && r.rmsError > 0) {
      gp << r.cpuSeconds << " " << r.rmsError << "\n";
      ++ownPoints;
    }
  gp << "EOD\n";
  if (ownPoints > 0)
    plots +=
        (plots.empty() ? "" : ", ") +
        std::string("$OWN using 1:2 with points pt 6 ps 3 lc 'black' title \"the world's own\"");
  // Every error 0 (a body at rest under no force: every run exact to the bit): no point has a
  // place on a log scale, so the axes are given and the picture says why it is empty.
  const bool empty = plots.empty();
  if (empty) {
    gp << "set xrange [1e-6:10]\nset yrange [" << visualTolerance * 1e-6 << ":"
       << visualTolerance * 10 << "]\n"
       << "set label 1 'every run ended exactly where the reference did (error 0 m): nothing to "
          "draw on a log scale' at graph 0.5, 0.5 center\n";
  } else {
    gp << yRange(rows, visualTolerance);
  }
  gp << "set terminal pngcairo size 960,640 font ',11'\n"
     << "if (!exists(\"png\")) png = 'report.png'\n"
     << "set output png\n"
     << "set title " << gnuplotString(title) << " noenhanced\n"
     << "set logscale xy\n"
     << "set format x '10^{%L}'\nset format y '10^{%L}'\n"
     << "set xlabel 'CPU time of the run (s)'\n"
     << "set ylabel 'RMS position error at the end (m)'\n"
     << "set grid\nset key outside right top\n"
     << "plot " << plots << (empty ? "" : ", ") << visualTolerance
     << " with lines dt 2 lc 'gray40' title 'visual tolerance'\n";
  return gp.str();
}

// `text` as a Markdown code span, whatever backquotes it holds.
std::string codeSpan(const std::string& text) {
  std::size_t longest = 0, run = 0;
  for (char c : text) longest = std::max(longest, run = c == '`' ? run + 1 : 0);
  const std::string fence(longest + 1, '`');
  return fence + (longest ? " " + text + " " : text) + fence;
}

// RK45's tolerances in report.md's table: "1e-06" when rtol = atol, as the sweep sets them.
std::string toleranceCell(const ReportRow& r) {
  if (r.integrator != Integrator::RK45) return "";
  const Tolerances& t = r.tolerances;
  return t.rtol == t.atol ? reportNumber(t.rtol)
                          : "rtol " + reportNumber(t.rtol) + ", atol " + reportNumber(t.atol);
}

// report.md's head and its table of runs.
std::string markdownRuns(const std::string& worldPath, double T, const Reference& reference,
                         const std::vector<ReportRow>& rows) {
  std::ostringstream md;
  md << "# Error against run time: " << worldPath << "\n\n"
     << "Every run goes from the world's initial state to T = " << reportNumber(T)
     << " s. Error: RMS over the 512 points of the distance to the reference positions at T (max: "
        "the largest "
        "distance). Time: the least CPU time of the stepping's thread over repeated runs, after a "
        "warm-up (runs over "
     << kRepeatBelowSeconds << " s are timed once).\n\n"
     << "Reference: RK4 at dt = " << reportNumber(reference.step) << " s (" << reference.steps
     << " steps); its own error is at most its difference from RK4 at dt = "
     << reportNumber(2 * reference.step) << " s, " << reportNumber(reference.error) << " m RMS ("
     << (reference.contacts.inContact > 0
             ? "about all of it: across the run's contacts RK4 is of order about 1"
             : "a fifteenth of it where rounding does not make most of it, RK4 being of order 4 "
               "on smooth forces; the two runs are extrapolated to dt = 0 that way, Richardson's, "
               "for the reference")
     << "). Errors below " << reportNumber(kFitFloor * reference.error)
     << " m are at the reference's limit and are left out of the fitted orders.\n\n"
     << "![error against run time](report.png)\n\n"
     << "| integrator | dt (s) | tolerance | steps | evaluations | CPU (s) | RMS error (m) | max "
        "error (m) | status |\n"
     << "|---|---|---|---|---|---|---|---|---|\n";
  for (const ReportRow& r : rows) {
    md << "| " << integratorName(r.integrator) << (r.worldsOwn ? " (the world's own)" : "") << " | "
       << exactNumber(r.dt) << " | " << toleranceCell(r) << " | " << r.steps << " | "
       << r.evaluations << " | " << reportNumber(r.cpuSeconds) << " | "
       << (r.diverged ? "" : reportNumber(r.rmsError)) << " | "
       << (r.diverged ? "" : reportNumber(r.maxError)) << " | " << (r.diverged ? "diverged" : "ok")
       << " |\n";
  }
  return md.str();
}

// report.md's fitted orders: each integrator's law, error ∝ dt^p (RK45: tolerance^p), and why a
// fit far from its theory is, as far as the runs show.
std::string markdownOrders(const std::vector<OrderCheck>& orders, const ContactActivity& contacts) {
  std::ostringstream md;
  md << "\n## Fitted orders\n\nThe slope p of log(error) against log(dt): error \u221d dt^p. "
        "RK45 sweeps its tolerance at one largest step, so its slope is against log(tolerance), "
        "error \u221d tolerance^p, and says nothing of an order in dt.\n\n"
     << "| integrator | fitted | theory |\n|---|---|---|\n";
  for (const OrderCheck& c : orders) {
    md << "| " << integratorName(c.integrator) << " | " << fittedLaw(c.integrator, c.fitted)
       << (c.far ? " (far from its theory: see below)" : "") << " | "
       << (sweepsTolerance(c.integrator) ? std::string("none in the tolerance")
                                         : "error \u221d dt^" + std::to_string(c.theory))
       << " |\n";
  }
  for (const OrderCheck& c : orders)
    if (c.far) md << "\n" << orderWarning(c, contacts);
  return md.str();
}

// report.md's lines for one recommended run, as a list under its item.
void markdownAdvice(const std::string& worldPath, const std::string& reportDir,
                    const ReportRow& row, const ReportRow* own, std::ostringstream& md) {
  const Advice advice = advise(worldPath, reportDir, row, own);
  md << advice.setting << ".\n  - Run it: " << codeSpan(advice.run) << "\n";
  if (!advice.keep.empty()) md << "  - Keep it in a world file: " << codeSpan(advice.keep) << "\n";
  if (!advice.sceneKeys.empty())
    md << "  - Keep it in the scene file: " << codeSpan(advice.sceneKeys) << "\n";
}

// report.md's recommendations.
std::string markdownRecommendations(const std::string& worldPath, const std::string& reportDir,
                                    const Recommendations& recommended, double visualTolerance) {
  const ReportRow* own = recommended.own;
  std::ostringstream md;
  md << "\n## Recommendations\n\n";
  if (own) {
    md << "The world's own setting, " << settingText(*own) << ", "
       << (own->diverged ? std::string("diverges before T.")
                         : "takes " + reportNumber(own->cpuSeconds) + " s for an error of " +
                               reportNumber(own->rmsError) + " m.")
       << "\n\n";
  }
  auto recommendation = [&](const std::string& what, const Choice& choice) {
    md << "- **" << what << "**: ";
    if (!choice.best) {
      md << "none of the runs.\n";
    } else if (choice.best == own) {
      md << "the world's own setting; nothing cheaper is as accurate.\n";
    } else {
      markdownAdvice(worldPath, reportDir, *choice.best, own, md);
    }
    if (!choice.leftOut.empty()) md << "  - " << choice.leftOut << ".\n";
    if (!choice.best || worldFileHolds(*choice.best)) return;
    md << "  - " << noWorldFileNote() << ". The cheapest setting a world file can hold: ";
    if (!choice.inWorldFile)
      md << "none of the runs.\n";
    else if (choice.inWorldFile == own)
      md << "the world's own.\n";
    else
      markdownAdvice(worldPath, reportDir, *choice.inWorldFile, own, md);
  };
  if (own && own->diverged)
    md << "- **The cheapest setting at least as accurate as the world's own**: the world's own "
          "diverges, so any run that does not is more accurate; see the next.\n";
  else
    recommendation("The cheapest setting at least as accurate as the world's own",
                   recommended.asAccurate);
  recommendation("The cheapest setting within the visual tolerance (" +
                     reportNumber(visualTolerance) + " m RMS)",
                 recommended.looksSame);
  return md.str();
}

}  // namespace

std::string reportCsv(const std::vector<ReportRow>& rows) {
  std::ostringstream csv;
  csv << "integrator,dt,tolerance,steps,evaluations,cpu_s,rms_error,max_error,status\n";
  for (const ReportRow& r : rows) {
    char line[256];
    std::snprintf(
        line, sizeof line, "%s,%.9g,%s,%lld,%lld,%.6g,%s,%s,%s\n", integratorName(r.integrator),
        r.dt, r.integrator == Integrator::RK45 ? reportNumber(r.tolerances.rtol).c_str() : "",
        r.steps, r.evaluations, r.cpuSeconds, r.diverged ? "" : reportNumber(r.rmsError).c_str(),
        r.diverged ? "" : reportNumber(r.maxError).c_str(), r.diverged ? "diverged" : "ok");
    csv << line;
  }
  return csv.str();
}

// Why a recommended RK45 run has no createWorld command.
std::string noWorldFileNote() {
  const Tolerances defaults;
  return "a world file holds RK45 and its dt but not its tolerances (RK45 from a world file runs "
         "at rtol=" +
         exactNumber(defaults.rtol) + " atol=" + exactNumber(defaults.atol) +
         "): give --rtol and --atol each time";
}

// report.csv, report.md and report.gp into the claimed folder. Throws OutputError.
void writeReportFiles(const std::string& worldPath, const ReportOptions& options,
                      const std::vector<Integrator>& integrators,
                      const std::vector<ReportRow>& rows, const Reference& reference,
                      const std::vector<OrderCheck>& orders, const Recommendations& recommended) {
  const Existing existing = options.overwrite ? Existing::Replace : Existing::Refuse;
  const double T = options.time, floor = kFitFloor * reference.error;
  const std::string title = worldPath + ": error at T = " + reportNumber(T) + " s against run time";
  const std::string md =
      markdownRuns(worldPath, T, reference, rows) + markdownOrders(orders, reference.contacts) +
      markdownRecommendations(worldPath, options.dir, recommended, options.visualTolerance);
  writeFileWhole(options.dir + "/report.csv", reportCsv(rows), existing);
  writeFileWhole(options.dir + "/report.md", md, existing);
  writeFileWhole(options.dir + "/report.gp",
                 gnuplotScript(rows, integrators, floor, options.visualTolerance, title), existing);
}

}  // namespace jello
