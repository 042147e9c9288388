// report.h: error against run time for a world (jello --report): a work-precision study of
// every integrator, written as CSV, a log-log plot (gnuplot) and a Markdown summary.
#pragma once

#include <string>
#include <vector>

#include "app/headless.h"

namespace jello {

struct ReportOptions {
  std::string dir;
  double time = 1.0;                    // s: every run goes from the world's start to this time
  std::vector<Integrator> integrators;  // empty: all of them
  double visualTolerance = 1e-4;        // m RMS: "looks the same"
  bool overwrite = false;               // replace the report files DIR already holds
};

// One run of the study.
struct ReportRow {
  Integrator integrator;
  double dt = 0;         // s; for RK45 the first and largest step
  double tolerance = 0;  // RK45 only (rtol = atol)
  long long steps = 0, evaluations = 0;
  double wallSeconds = 0;
  double rmsError = 0, maxError = 0;  // m, positions at the end against the reference
  bool diverged = false;
  bool worldsOwn = false;  // the world's own integrator and dt
};

// The CSV of the report (README: Error against run time), header included.
std::string reportCsv(const std::vector<ReportRow>& rows);

// Least-squares slope of log(error) against log(dt) (RK45: against log(tolerance)) over the
// rows of one integrator that did not diverge and whose error is above `floor`; NaN with
// fewer than two such rows.
double fittedOrder(const std::vector<ReportRow>& rows, Integrator integrator, double floor);

// Runs the study, writes DIR/report.csv, DIR/report.png and DIR/report.md, prints where they
// are on stdout, and says how it went (outcome.h).
Outcome runReport(const RunOptions& run, const ReportOptions& report);

}  // namespace jello
