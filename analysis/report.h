// report.h: error against run time for a world (jello --report): a work-precision study of
// every integrator, written as CSV, a log-log plot (gnuplot) and a Markdown summary, with
// recommendations a user can run as printed.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "solver/run.h"

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
  double dt = 0;            // s; for RK45 the first and largest step
  Tolerances tolerances{};  // RK45 only: its rtol and atol (the sweep sets them equal)
  long long steps = 0, evaluations = 0;
  double cpuSeconds = 0;  // s: CPU time of the stepping (its thread's), the least of its timings
  // s: what recommendations compare (assignCosts, reportstudy.h): the work of an explicit run
  // at the explicit runs' common pace, IMPLICIT's own timing.
  double cost = 0;
  double rmsError = 0, maxError = 0;  // m, positions at the end against the reference
  bool diverged = false;
  bool worldsOwn = false;  // the world's own integrator and dt
};

// The CSV of the report (docs/running.md: Error against run time), header included. Its tolerance
// column is RK45's rtol.
std::string reportCsv(const std::vector<ReportRow>& rows);

// Least-squares slope of log(error) against log(dt) (RK45: against log(rtol), see
// fittedAgainst) over the rows of one integrator that did not diverge and whose error is above
// `floor`; NaN with fewer than two such rows.
double fittedOrder(const std::vector<ReportRow>& rows, Integrator integrator, double floor);

// The contacts (walls, plane: ForceTerm::pointsInContact) seen after every step of the
// reference run, from the start to T. Where a contact switches on the force has a kink, and
// no integrator keeps its order in dt across it.
struct ContactActivity {
  long long steps = 0;               // states looked at: the start and the end of every step
  long long inContact = 0;           // of them, those with a point in contact
  double firstContact = NAN;         // s: the first such state's time; NaN: none
  std::vector<std::string> touched;  // the terms that pushed, as they name themselves: "plane"
};

// Errors below this many times the reference's own error are at the reference's limit and
// left out of the fitted orders.
constexpr double kFitFloor = 10;
// A fitted order further than this from the theory's is flagged, with its likely reasons.
constexpr double kOrderSlack = 0.5;
// The finest runs' errors within this factor of the reference's own error are measured with
// too blunt a ruler: the reference's error flattens the fitted line.
constexpr double kReferenceMargin = 100;

// An integrator's fitted order against the table's (integrators.h), and what the runs show of
// why it is far from it. RK45 has no order in its tolerance: never far.
struct OrderCheck {
  Integrator integrator;
  double fitted = NAN;  // fittedOrder; NaN with too few runs
  int theory = 0;       // orderOf
  bool far = false;     // |fitted - theory| > kOrderSlack
  // The likely reasons, looked for only when far:
  bool contacts = false;         // contacts acted during the run (ContactActivity)
  bool divergedSteps = false;    // some of its sweep's steps diverged
  bool edgeOfStability = false;  // without its largest step the fit is within kOrderSlack
  double withoutLargest = NAN;   // the fit without its largest step
  double largestStep = NAN;      // s
  bool nearReference = false;    // its finest fitted error < kReferenceMargin * the reference's
  double finestError = NAN;      // m: the smallest error in the fit
  double referenceError = NAN;   // m: the reference's own
};

// The fit of `integrator` over `rows` (errors above kFitFloor * referenceError) against its
// theory, with the reasons looked for when it is far.
OrderCheck checkOrder(const std::vector<ReportRow>& rows, Integrator integrator,
                      double referenceError, const ContactActivity& contacts);

// For a student: why `check`'s fit is far from its theory, one paragraph of Markdown (the
// reasons as a list); "" when it is not far. `contacts` names the surfaces and when.
std::string orderWarning(const OrderCheck& check, const ContactActivity& contacts);
// The same in one line for the summary on stdout: "RK4's fitted order is 0.99, not 4: ...".
std::string orderWarningLine(const OrderCheck& check, const ContactActivity& contacts);

// What an integrator's fitted slope is against: "dt", or "tolerance" for RK45, whose sweep is
// of its tolerance at one largest step (so that its slope is no order in dt).
const char* fittedAgainst(Integrator integrator);

// An integrator's fitted law in words: "error ∝ dt^4.07", "error ∝ tolerance^0.90" (RK45), or
// "n/a" when `order` is NaN.
std::string fittedLaw(Integrator integrator, double order);

// The plot's legend entry for an integrator's line: "RK4: error ∝ dt^{4.07}" or "RK45: error ∝
// tolerance^{0.90}" (gnuplot's enhanced text: ^{} is an exponent), or the name alone when
// `order` is NaN.
std::string legendLabel(Integrator integrator, double order);

// Run times closer than this, as a fraction, are "the same speed": the timings of runs of a
// few milliseconds vary by about that much from one report to the next.
constexpr double kSameSpeedWithin = 0.10;

// A run of `seconds` against the world's own run of `ownSeconds` (both > 0): "the same speed as
// the world's own", "2.3 times as fast as the world's own" or "takes 2.3 times as long as the
// world's own".
std::string speedAgainstOwn(double ownSeconds, double seconds);

// The shortest text that reads back as exactly `x` ("0.00078125", "1e-06"): a command given
// it runs the very setting measured.
std::string exactNumber(double x);

// A setting as the report names it: "RK4 dt=0.00078125", "RK45 dt=0.025 rtol=atol=1e-06".
// Numbers in shortest round-trip form, as the commands below give them.
std::string settingText(const ReportRow& row);

// Whether a world file can hold the setting: a world file stores the integrator and dt, not
// RK45's tolerances, which a world file's RK45 runs at their defaults (Tolerances{}).
bool worldFileHolds(const ReportRow& row);

// The command, as its words, that runs `worldPath` with the row's setting:
// {"./jello", "--integrator", "RK4", "--dt", "0.002", worldPath} (RK45 adds --rtol and --atol).
std::vector<std::string> runCommand(const std::string& worldPath, const ReportRow& row);

// The createWorld command, as its words, that writes a copy of `worldPath` holding the row's
// setting into the report's folder `reportDir` (world/rotate.w, RK4 at 0.001, into out:
// out/rotate-rk4-dt0.001.w); empty when a world file cannot hold it (worldFileHolds).
std::vector<std::string> worldFileCommand(const std::string& worldPath,
                                          const std::string& reportDir, const ReportRow& row);

// One word for a POSIX shell: as it is when it holds only characters no shell treats
// specially, otherwise in single quotes (a quote within as '\''); a word with a control
// character or bytes outside UTF-8 (printable() would change it) as $'...', those bytes as
// \xNN, so that the command stays one line and sends nothing raw to a terminal. A word that starts
// with '-' and is the world's path is given as ./WORD by the commands above, never as an option.
std::string shellWord(const std::string& word);
// The words as one command line, each through shellWord.
std::string shellLine(const std::vector<std::string>& words);

// Runs the study, writes DIR/report.csv, DIR/report.png and DIR/report.md, prints where they
// are and what they recommend on stdout, and says how it went (outcome.h).
Outcome runReport(const RunOptions& run, const ReportOptions& report);

}  // namespace jello
