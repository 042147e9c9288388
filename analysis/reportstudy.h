// analysis/reportstudy.h: the parts of jello --report's study that its files share (report.cpp
// runs it; reportruns.cpp measures, recommend.cpp recommends, reportfiles.cpp writes). Not for
// use outside analysis/report*.cpp and recommend.cpp.
#pragma once

#include <chrono>
#include <mutex>
#include <string>
#include <vector>

#include "analysis/report.h"
#include "analysis/stability.h"
#include "core/progress.h"
#include "solver/integrators.h"
#include "solver/physics.h"

namespace jello {

using Clock = std::chrono::steady_clock;

constexpr int kSweepLength = 6;                    // steps per integrator, halving
constexpr int kReferenceRefinement = 32;           // reference step: the smallest swept step / 32
constexpr long long kMaxReferenceSteps = 1 << 16;  // ... but no more steps than this
constexpr int kLargestStepDivisor = 8;             // the stability search starts at T / 8
constexpr int kSearchHalvings = 24;
constexpr double kSameEnd = 0.01;             // m RMS: two runs that end this close agree
constexpr double kRepeatBelowSeconds = 0.25;  // runs shorter than this are timed three times
constexpr double kRk45Tolerances[kSweepLength] = {1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7};

struct Run {
  State end;
  StepStats stats;
  double cpu = 0;  // s: the stepping thread's CPU time
  bool diverged = false;
};

// The report's progress line: what runs now, and how many of the reportItemCount() items
// have begun. The count ends on its total, and the last line stays (finish).
class ReportProgress {
 public:
  explicit ReportProgress(int total) : total_(total), begin_(Clock::now()) {}
  // The next item begins. (Both may be called from any of the report's threads.)
  void next(const std::string& what) {
    std::lock_guard<std::mutex> lock(mutex_);
    ++begun_;
    show(what);
  }
  // What an item does now (a search's next halving), with the same count.
  void update(const std::string& what) {
    std::lock_guard<std::mutex> lock(mutex_);
    show(what);
  }
  // "report: done, 45/45 in 12 s" and a newline, before the summary on stdout.
  void finish() {
    const double seconds = std::chrono::duration<double>(Clock::now() - begin_).count();
    char took[32];
    std::snprintf(took, sizeof took, "%.0f s", seconds);
    line_.finish("report: done, " + count() + " in " + took);
  }

 private:
  void show(const std::string& what) { line_.show("report: " + what + " (" + count() + ")"); }
  std::string count() const { return std::to_string(begun_) + "/" + std::to_string(total_); }
  std::mutex mutex_;
  int total_, begun_ = 0;
  Clock::time_point begin_;
  Progress line_;
};

// What every run of the study shares.
struct Study {
  const Model& model;
  const State& start;
  double T;  // s: every run ends there
  ReportProgress& progress;
};

// The positions every run is compared with: RK4 well below the smallest step measured, checked
// against RK4 at twice its step. Its own error is at most their difference: about all of it
// across contacts, where RK4 is of order about 1, a fifteenth of it on smooth forces, where RK4
// is of order 4, unless rounding makes most of the difference (two runs cannot tell which). On
// smooth forces that fifteenth is added to it (Richardson's extrapolation, whose own error is
// smaller still); across contacts it is not.
struct Reference {
  double step = 0;  // s
  long long steps = 0;
  bool diverged = false;  // the reference or the run at twice its step diverged: no report
  State end;
  double error = 0;  // m RMS: the reference's own, at most its difference as above
  ContactActivity contacts;
};
constexpr double kRichardson = 1.0 / 15;  // 1 / (2^4 - 1): RK4's order 4

// The study's rows and their runs' end states, index for index, and the reference's runs.
struct Measured {
  std::vector<ReportRow> rows;
  std::vector<State> ends;
  double smallestStep = 0;  // s: the smallest dt measured, which the reference's must be well below
  Reference reference;
  Run coarse;  // RK4 at twice the reference's step
};

// One recommendation: the cheapest run within an error and, when no world file can hold its
// setting (RK45's tolerances), the cheapest run within that error one can. Into the rows; null
// when there is none.
struct Choice {
  const ReportRow* best = nullptr;
  const ReportRow* inWorldFile = nullptr;  // only when best is not worldFileHolds
  // A cheaper run within the error left out, and why: --check does not call its step stable.
  std::string leftOut;
};

// What to recommend: the cheapest setting as accurate as the world's own, and the cheapest
// within the visual tolerance.
struct Recommendations {
  const ReportRow* own = nullptr;
  Choice asAccurate, looksSame;
};

// What to tell about one recommended run: its setting and figures, the command that runs it,
// and the one that keeps it in a world file ("" when no world file can). A scene keeps it in its
// own keys instead (createWorld writes course worlds, which hold no obstacles or pins).
struct Advice {
  std::string setting;  // "MIDPOINT dt=0.00078125: 0.0141 s, error 8.11e-08 m, 2.3 times ..."
  std::string run, keep;
  std::string sceneKeys;  // `integrator = "MIDPOINT"` and `dt = 0.00078125`, for a scene
};

// The calling thread's CPU time, s (runs are timed by it, not by the wall clock).
double threadCpuSeconds();
// RK45 sweeps its tolerance, not its step, and so needs no search for a largest stable step.
bool sweepsTolerance(Integrator integrator);
// The items the progress line counts: each integrator's search for its largest stable step
// (one item, however many halvings it takes), its sweep's runs, the world's own setting (an
// item even when a sweep has measured it) and the reference.
int reportItemCount(const std::vector<Integrator>& integrators);
// The root-mean-square distance of the points of `a` from those of `b`, m; the largest in
// *largest.
double rms(const State& a, const State& b, double* largest);
// "%.6g" of x: the report's figures.
std::string reportNumber(double x);
// Every sweep, the world's own setting and the reference, on every core. The world's own is a
// row of its own unless a sweep runs the same setting, which is then marked as the world's and
// run once.
void measureAll(const Study& s, const std::vector<Integrator>& integrators,
                const RunSettings& world, const Tolerances& tolerances, Measured* m);

// Each row's cost (recommend.cpp): an explicit integrator's force evaluations (each the same
// work) times the median seconds an evaluation over every explicit run of the study, so that a
// run is never called cheaper than one of less work because a single timing was disturbed;
// IMPLICIT's (a Jacobian and a linear solve a step) is its own least timing.
void assignCosts(std::vector<ReportRow>& rows);

// The recommendations of a study's rows (recommend.cpp): the cheapest setting as accurate as the
// world's own and the cheapest within the visual tolerance, each one --check calls stable.
Recommendations recommend(const std::vector<ReportRow>& rows, double visualTolerance,
                          const StabilityReport& stability);
Advice advise(const std::string& worldPath, const std::string& reportDir, const ReportRow& row,
              const ReportRow* own);
// Why a recommended RK45 run has no createWorld command.
std::string noWorldFileNote();
// report.csv, report.md and report.gp into the claimed folder. Throws OutputError.
void writeReportFiles(const std::string& worldPath, const ReportOptions& options,
                      const std::vector<Integrator>& integrators,
                      const std::vector<ReportRow>& rows, const Reference& reference,
                      const std::vector<OrderCheck>& orders, const Recommendations& recommended);

}  // namespace jello
