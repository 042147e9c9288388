// report.cpp: the work-precision study of jello --report.
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
#include <mutex>
#include <sstream>
#include <thread>

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

using Clock = std::chrono::steady_clock;

constexpr int kSweepLength = 6;                    // steps per integrator, halving
constexpr int kReferenceRefinement = 32;           // reference step: the smallest swept step / 32
constexpr long long kMaxReferenceSteps = 1 << 16;  // ... but no more steps than this
constexpr int kLargestStepDivisor = 8;             // the stability search starts at T / 8
constexpr int kSearchHalvings = 24;
constexpr double kSameEnd = 0.01;             // m RMS: two runs that end this close agree
constexpr double kRepeatBelowSeconds = 0.25;  // runs shorter than this are timed three times
constexpr double kRk45Tolerances[kSweepLength] = {1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7};

// The calling thread's CPU time, s. Runs are timed by it, not by the wall clock: it leaves out
// the time the thread waits for a core, so a run's figure is its own whatever else the machine
// (or the report's other runs, on the other cores) does at the time.
double threadCpuSeconds() {
  timespec now{};
  ::clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

struct Run {
  State end;
  StepStats stats;
  double cpu = 0;  // s: the stepping thread's CPU time
  bool diverged = false;
};

// From the start to time T: stepsForTime(T, dt) steps, the last one shortened when dt does not
// divide T (Simulation::advanceTo). runReport has checked that T/dt is a step count for every dt
// it passes. A run that fails the checks of every run (simulation.h) has diverged.
Run simulate(const Model& model, const State& start, Integrator integrator, double dt, double time,
             Tolerances tolerances = {}) {
  Run run;
  Simulation simulation(model, start, integrator, dt, tolerances);
  const double begin = threadCpuSeconds();
  run.diverged = !simulation.advanceTo(time).ran();
  run.cpu = threadCpuSeconds() - begin;
  run.end = simulation.state();
  run.stats = simulation.stats();
  return run;
}

// Fills `row` from a run of its setting, which is the warm-up: runs shorter than
// kRepeatBelowSeconds are timed twice more and the least time kept. Returns the end state.
State measureFrom(const Model& model, const State& start, double time, Run run, ReportRow* row) {
  double best = run.cpu;
  if (!run.diverged && run.cpu < kRepeatBelowSeconds) {
    for (int repeat = 0; repeat < 2; ++repeat)
      best = std::min(best,
                      simulate(model, start, row->integrator, row->dt, time, row->tolerances).cpu);
  }
  row->steps = run.stats.steps;
  row->evaluations = run.stats.evaluations + run.stats.jacobians;
  row->cpuSeconds = best;
  row->diverged = run.diverged;
  return std::move(run.end);
}

// Runs one setting into `row` (measureFrom). Returns the end state.
State measure(const Model& model, const State& start, double time, ReportRow* row) {
  return measureFrom(model, start, time,
                     simulate(model, start, row->integrator, row->dt, time, row->tolerances), row);
}

double rms(const State& a, const State& b, double* largest) {
  double sum = 0;
  *largest = 0;
  const int n = a.points();
  for (int q = 0; q < n; ++q) {
    Vec3 d = load(a.p(), q, n) - load(b.p(), q, n);
    sum += dot(d, d);
    *largest = std::max(*largest, length(d));
  }
  return std::sqrt(sum / n);
}

// RK45 sweeps its tolerance, not its step, and so needs no search for a largest stable step.
bool sweepsTolerance(Integrator integrator) { return integrator == Integrator::RK45; }

// The items the progress line counts: each integrator's search for its largest stable step
// (one item, however many halvings it takes), its sweep's runs, the world's own setting (an
// item even when a sweep has measured it) and the reference.
int reportItemCount(const std::vector<Integrator>& integrators) {
  int items = 2;
  for (Integrator integrator : integrators)
    items += kSweepLength + (sweepsTolerance(integrator) ? 0 : 1);
  return items;
}

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

std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", x);
  return text;
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

}  // namespace

std::string reportCsv(const std::vector<ReportRow>& rows) {
  std::ostringstream csv;
  csv << "integrator,dt,tolerance,steps,evaluations,cpu_s,rms_error,max_error,status\n";
  for (const ReportRow& r : rows) {
    char line[256];
    std::snprintf(
        line, sizeof line, "%s,%.9g,%s,%lld,%lld,%.6g,%s,%s,%s\n", integratorName(r.integrator),
        r.dt, r.integrator == Integrator::RK45 ? number(r.tolerances.rtol).c_str() : "", r.steps,
        r.evaluations, r.cpuSeconds, r.diverged ? "" : number(r.rmsError).c_str(),
        r.diverged ? "" : number(r.maxError).c_str(), r.diverged ? "diverged" : "ok");
    csv << line;
  }
  return csv.str();
}

double fittedOrder(const std::vector<ReportRow>& rows, Integrator integrator, double floor) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const ReportRow& r : rows) {
    if (r.integrator != integrator || r.diverged || r.worldsOwn || !(r.rmsError > floor)) continue;
    double x = std::log(integrator == Integrator::RK45 ? r.tolerances.rtol : r.dt),
           y = std::log(r.rmsError);
    n += 1;
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  if (n < 2 || n * sxx - sx * sx == 0) return NAN;
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

OrderCheck checkOrder(const std::vector<ReportRow>& rows, Integrator integrator,
                      double referenceError, const ContactActivity& contacts) {
  OrderCheck check;
  check.integrator = integrator;
  check.theory = orderOf(integrator);
  check.referenceError = referenceError;
  const double floor = kFitFloor * referenceError;
  check.fitted = fittedOrder(rows, integrator, floor);
  if (sweepsTolerance(integrator) || std::isnan(check.fitted)) return check;
  check.far = std::fabs(check.fitted - check.theory) > kOrderSlack;
  if (!check.far) return check;
  check.contacts = contacts.inContact > 0;
  // The sweep's runs in the fit, and the largest of their steps.
  std::vector<ReportRow> fitted;
  for (const ReportRow& r : rows) {
    if (r.integrator != integrator || r.worldsOwn) continue;
    if (r.diverged)
      check.divergedSteps = true;
    else if (r.rmsError > floor)
      fitted.push_back(r);
  }
  // fittedOrder found two runs or more above the floor: `fitted` is not empty.
  check.finestError = fitted[0].rmsError;
  for (const ReportRow& r : fitted) check.finestError = std::min(check.finestError, r.rmsError);
  auto largest =
      std::max_element(fitted.begin(), fitted.end(),
                       [](const ReportRow& a, const ReportRow& b) { return a.dt < b.dt; });
  check.largestStep = largest->dt;
  fitted.erase(largest);
  check.withoutLargest = fittedOrder(fitted, integrator, floor);
  check.edgeOfStability = std::fabs(check.withoutLargest - check.theory) <= kOrderSlack;
  check.nearReference = check.finestError < kReferenceMargin * referenceError;
  return check;
}

namespace {

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

// A search's result: the largest stable step and, when one was found, the search's own runs at
// that step and at half of it, which are its sweep's first two.
struct StableStep {
  double dt = 0;
  std::vector<Run> runs;
};

// The largest step T/(8 2^k) at which `integrator` is stable: its run does not diverge and ends
// where the run at half the step ends, to within kSameEnd (an unstable run need not reach
// the 100 m of docs/physics.md's divergence rule within T).
StableStep largestStableStep(const Study& s, Integrator integrator) {
  Run previous = simulate(s.model, s.start, integrator, s.T / kLargestStepDivisor, s.T);
  for (int k = 0; k < kSearchHalvings; ++k) {
    double dt = s.T / (kLargestStepDivisor << k);
    s.progress.update(std::string("finding ") + integratorName(integrator) +
                      "'s largest stable step, dt=" + number(dt));
    Run half = simulate(s.model, s.start, integrator, dt / 2, s.T);
    double ignored;
    if (!previous.diverged && !half.diverged && rms(previous.end, half.end, &ignored) < kSameEnd) {
      StableStep found{dt, {}};
      found.runs.push_back(std::move(previous));
      found.runs.push_back(std::move(half));
      return found;
    }
    previous = std::move(half);
  }
  return {s.T / (static_cast<double>(kLargestStepDivisor) * (1 << kSearchHalvings)), {}};
}

// A run's cost, to order the queue: its force evaluations, an IMPLICIT step (a Newton solve or
// two, about 1.5 ms against an evaluation's 20 us here) counted as kImplicitStepCost of them.
// Searches come before every run: the runs they add wait on them, and so does the reference.
constexpr double kImplicitStepCost = 70;
constexpr double kSearchCost = 1e300;
double stepCost(Integrator integrator) {
  switch (integrator) {
    case Integrator::Midpoint:
    case Integrator::Verlet:
      return 2;
    case Integrator::RK4:
      return 4;
    case Integrator::RK45:
      return 6;  // a substep; its largest step is T/8, so its runs are short whatever they take
    case Integrator::Implicit:
      return kImplicitStepCost;
    default:
      return 1;
  }
}
double runCost(Integrator integrator, double dt, double T) { return T / dt * stepCost(integrator); }

// The row of sweep run i of an integrator whose largest stable step is `largest` (RK45 sweeps
// its tolerance at a largest step of T/8 instead).
ReportRow sweepRow(double T, Integrator integrator, double largest, int i) {
  ReportRow row;
  row.integrator = integrator;
  if (sweepsTolerance(integrator)) {
    // Its largest step as large as anyone's first try, so that the tolerance alone decides
    // the steps it takes.
    row.dt = T / kLargestStepDivisor;
    row.tolerances = {kRk45Tolerances[i], kRk45Tolerances[i]};
  } else {
    row.dt = largest / (1 << i);
  }
  return row;
}

// The queue's jobs and what they decide on the way: the world's own row (the last), and the
// searches still running, after which the reference's step is known.
struct Plan {
  Plan(const Study& s, Measured* measured, RunQueue* q, std::size_t ownRow)
      : study(s), m(measured), queue(q), own(ownRow) {}
  const Study& study;
  Measured* m;
  RunQueue* queue;
  std::size_t own;   // the index of the world's own row
  std::mutex mutex;  // guards what follows and m->smallestStep
  int searchesLeft = 0;
  bool ownInSweep = false;  // a sweep ran the world's own setting: that row is marked instead
};

// Queues the job that measures row `at`, from `first` when a search has run its setting.
void queueRow(Plan& plan, std::size_t at, const std::string& what, std::vector<Run> first = {}) {
  const ReportRow& row = plan.m->rows[at];
  plan.queue->add(runCost(row.integrator, row.dt, plan.study.T),
                  [&plan, at, what, first = std::move(first)]() mutable {
                    const Study& s = plan.study;
                    ReportRow& r = plan.m->rows[at];
                    s.progress.next(what);
                    plan.m->ends[at] =
                        first.empty() ? measure(s.model, s.start, s.T, &r)
                                      : measureFrom(s.model, s.start, s.T, std::move(first[0]), &r);
                  });
}

void queueOwn(Plan& plan) {
  queueRow(plan, plan.own,
           std::string("the world's own ") + integratorName(plan.m->rows[plan.own].integrator));
}

// The reference run: RK4 at T / steps, stepped one step at a time so that every state is looked
// at for contacts; the same steps as simulate's advanceTo(T), since the step divides T.
Run referenceRun(const Study& s, double dt, long long steps, ContactActivity* contacts) {
  const auto& terms = s.model.forces.terms;
  std::vector<char> pushed(terms.size(), 0);
  auto look = [&](const State& state, double time) {
    bool any = false;
    for (std::size_t t = 0; t < terms.size(); ++t)
      if (terms[t]->pointsInContact(state.p()) > 0) pushed[t] = any = true;
    ++contacts->steps;
    if (!any) return;
    ++contacts->inContact;
    if (std::isnan(contacts->firstContact)) contacts->firstContact = time;
  };
  Simulation simulation(s.model, s.start, Integrator::RK4, dt);
  look(s.start, 0);
  bool ran = true;
  for (long long k = 1; ran && k < steps; ++k) {
    ran = simulation.advance(1).ran();
    if (ran) look(simulation.state(), simulation.time());
  }
  if (ran) ran = simulation.advanceTo(s.T).ran();
  if (ran) look(simulation.state(), simulation.time());
  for (std::size_t t = 0; t < terms.size(); ++t)
    if (pushed[t]) contacts->touched.push_back(terms[t]->describe(s.start.p()).at(0).label);
  Run run;
  run.diverged = !ran;
  run.end = simulation.state();
  return run;
}

// The reference's two runs, RK4 at the largest T / 2^k at least kReferenceRefinement times below
// the smallest step measured (at most kMaxReferenceSteps steps, at least 2) and at twice that
// step, as two jobs: once every search is done, when that step is known.
void queueReference(Plan& plan) {
  const Study& s = plan.study;
  Reference& reference = plan.m->reference;
  reference.steps = 2;
  while (reference.steps < kMaxReferenceSteps &&
         s.T / reference.steps > plan.m->smallestStep / kReferenceRefinement)
    reference.steps *= 2;
  reference.step = s.T / reference.steps;
  const double cost = runCost(Integrator::RK4, reference.step, s.T);
  plan.queue->add(cost, [&plan] {
    const Study& study = plan.study;
    Reference& r = plan.m->reference;
    study.progress.next("the reference, RK4 dt=" + number(r.step) +
                        " and dt=" + number(2 * r.step));
    Run run = referenceRun(study, r.step, r.steps, &r.contacts);
    r.diverged = run.diverged;
    r.end = std::move(run.end);
  });
  plan.queue->add(cost / 2, [&plan] {
    plan.m->coarse = simulate(plan.study.model, plan.study.start, Integrator::RK4,
                              2 * plan.m->reference.step, plan.study.T);
  });
}

// A search is done and its sweep's rows are set: the world's own is one of them or is queued
// (when it is this integrator's), and after the last search the reference is queued.
void searched(Plan& plan, std::size_t first, bool ownsWorld) {
  bool last = false;
  {
    std::lock_guard<std::mutex> lock(plan.mutex);
    for (int i = 0; i < kSweepLength; ++i) {
      ReportRow& row = plan.m->rows[first + i];
      plan.m->smallestStep = std::min(plan.m->smallestStep, row.dt);
      if (ownsWorld && row.dt == plan.m->rows[plan.own].dt) {
        row.worldsOwn = plan.ownInSweep = true;
        plan.m->rows[plan.own].worldsOwn = false;  // the row of its own is not used
      }
    }
    last = --plan.searchesLeft == 0;
  }
  if (ownsWorld && !plan.ownInSweep) queueOwn(plan);
  if (ownsWorld && plan.ownInSweep) plan.study.progress.next("the world's own, in its sweep");
  if (last) queueReference(plan);
}

// Queues one integrator's sweep, into rows and ends [first, first + kSweepLength): after its
// search for its largest stable step, whose two runs at the largest step and at half of it are
// the sweep's first two (RK45 needs no search).
void queueSweep(Plan& plan, Integrator integrator, std::size_t first, bool ownsWorld) {
  const Study& s = plan.study;
  if (sweepsTolerance(integrator)) {
    for (int i = 0; i < kSweepLength; ++i) {
      plan.m->rows[first + i] = sweepRow(s.T, integrator, 0, i);
      queueRow(plan, first + i, settingText(plan.m->rows[first + i]));
    }
    return;
  }
  const double cost = kSearchCost / (integrator == Integrator::Implicit ? 1 : 2);
  plan.queue->add(cost, [&plan, integrator, first, ownsWorld] {
    const Study& study = plan.study;
    study.progress.next(std::string("finding ") + integratorName(integrator) +
                        "'s largest stable step");
    StableStep stable = largestStableStep(study, integrator);
    for (int i = 0; i < kSweepLength; ++i)
      plan.m->rows[first + i] = sweepRow(study.T, integrator, stable.dt, i);
    for (int i = 0; i < kSweepLength; ++i) {
      std::vector<Run> run;
      if (static_cast<std::size_t>(i) < stable.runs.size())
        run.push_back(std::move(stable.runs[i]));
      queueRow(plan, first + i, settingText(plan.m->rows[first + i]), std::move(run));
    }
    searched(plan, first, ownsWorld);
  });
}

// Every sweep, the world's own setting and the reference, on every core. The world's own is a
// row of its own unless a sweep runs the same setting, which is then marked as the world's and
// run once.
void measureAll(const Study& s, const std::vector<Integrator>& integrators, const World& world,
                const Tolerances& tolerances, Measured* m) {
  const std::size_t sweeps = integrators.size() * kSweepLength;
  m->rows.resize(sweeps + 1);
  m->ends.resize(sweeps + 1);
  m->smallestStep = world.dt;
  RunQueue queue;
  Plan plan(s, m, &queue, sweeps);
  ReportRow& own = m->rows[sweeps];
  own.integrator = world.integrator;
  own.dt = world.dt;
  if (world.integrator == Integrator::RK45) own.tolerances = tolerances;
  own.worldsOwn = true;
  bool ownSwept = false;  // the world's integrator has a sweep of steps, which may hold its dt
  for (Integrator integrator : integrators) {
    if (!sweepsTolerance(integrator)) ++plan.searchesLeft;
    if (integrator == world.integrator && !sweepsTolerance(integrator)) ownSwept = true;
  }
  for (std::size_t i = 0; i < integrators.size(); ++i)
    queueSweep(plan, integrators[i], i * kSweepLength,
               ownSwept && integrators[i] == world.integrator);
  if (!ownSwept) queueOwn(plan);
  if (plan.searchesLeft == 0) queueReference(plan);
  queue.run(std::max(1u, std::thread::hardware_concurrency()));
  if (plan.ownInSweep) {
    m->rows.pop_back();  // the world's own row, which a sweep's row stands for
    m->ends.pop_back();
  }
  Reference& reference = m->reference;
  reference.diverged = reference.diverged || m->coarse.diverged;
  if (reference.diverged) return;
  double largest;
  reference.error = rms(reference.end, m->coarse.end, &largest);
  if (reference.contacts.inContact > 0) return;
  std::vector<double>& y = reference.end.y;
  for (std::size_t i = 0; i < y.size(); ++i) y[i] += kRichardson * (y[i] - m->coarse.end.y[i]);
}

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
  return std::string(integratorName(row.integrator)) + " dt=" + number(row.dt) +
         " is cheaper but left out: --check calls it " +
         verdictName(verdictFor(row.dt, limit, stability.stableFraction)) +
         textf(" (%.0f%% of its limit %s s; stable is below %.0f%%)", 100 * row.dt / limit,
               number(limit).c_str(), 100 * stability.stableFraction);
}

Choice cheapestWithin(const std::vector<ReportRow>& rows, double limit,
                      const StabilityReport& stability) {
  auto cheapest = [&](bool inWorldFile, bool stable) {
    const ReportRow* best = nullptr;
    for (const ReportRow& row : rows)
      if (!row.diverged && row.rmsError <= limit && (!inWorldFile || worldFileHolds(row)) &&
          (!stable || checkCallsStable(row, stability)) &&
          (!best || row.cpuSeconds < best->cpuSeconds))
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

Recommendations recommend(const std::vector<ReportRow>& rows, double visualTolerance,
                          const StabilityReport& stability) {
  Recommendations r;
  for (const ReportRow& row : rows)
    if (row.worldsOwn) r.own = &row;
  if (r.own && !r.own->diverged) r.asAccurate = cheapestWithin(rows, r.own->rmsError, stability);
  r.looksSame = cheapestWithin(rows, visualTolerance, stability);
  return r;
}

// What to tell about one recommended run: its setting and figures, the command that runs it,
// and the one that keeps it in a world file ("" when no world file can). A scene keeps it in its
// own keys instead (createWorld writes course worlds, which hold no obstacles or pins).
struct Advice {
  std::string setting;  // "MIDPOINT dt=0.00078125: 0.0141 s, error 8.11e-08 m, 2.3 times ..."
  std::string run, keep;
  std::string sceneKeys;  // `integrator = "MIDPOINT"` and `dt = 0.00078125`, for a scene
};

Advice advise(const std::string& worldPath, const ReportRow& row, const ReportRow* own) {
  Advice advice;
  advice.setting =
      settingText(row) + ": " + number(row.cpuSeconds) + " s, error " + number(row.rmsError) + " m";
  if (own && !own->diverged && own->cpuSeconds > 0 && row.cpuSeconds > 0)
    advice.setting += ", " + speedAgainstOwn(own->cpuSeconds, row.cpuSeconds);
  advice.run = shellLine(runCommand(worldPath, row));
  if (isSceneFile(worldPath)) {
    if (worldFileHolds(row))
      advice.sceneKeys = "integrator = \"" + std::string(integratorName(row.integrator)) +
                         "\" and dt = " + exactNumber(row.dt);
    return advice;
  }
  const std::vector<std::string> keep = worldFileCommand(worldPath, row);
  if (!keep.empty()) advice.keep = shellLine(keep);
  return advice;
}

// Why a recommended RK45 run has no createWorld command.
std::string noWorldFileNote() {
  const Tolerances defaults;
  return "a world file holds RK45 and its dt but not its tolerances (RK45 from a world file runs "
         "at rtol=" +
         exactNumber(defaults.rtol) + " atol=" + exactNumber(defaults.atol) +
         "): give --rtol and --atol each time";
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
  return t.rtol == t.atol ? number(t.rtol) : "rtol " + number(t.rtol) + ", atol " + number(t.atol);
}

// report.md's head and its table of runs.
std::string markdownRuns(const std::string& worldPath, double T, const Reference& reference,
                         const std::vector<ReportRow>& rows) {
  std::ostringstream md;
  md << "# Error against run time: " << worldPath << "\n\n"
     << "Every run goes from the world's initial state to T = " << number(T)
     << " s. Error: RMS over the 512 points of the distance to the reference positions at T (max: "
        "the largest "
        "distance). Time: the least CPU time of the stepping's thread over repeated runs, after a "
        "warm-up (runs over "
     << kRepeatBelowSeconds << " s are timed once).\n\n"
     << "Reference: RK4 at dt = " << number(reference.step) << " s (" << reference.steps
     << " steps); its own error is at most its difference from RK4 at dt = "
     << number(2 * reference.step) << " s, " << number(reference.error) << " m RMS ("
     << (reference.contacts.inContact > 0
             ? "about all of it: across the run's contacts RK4 is of order about 1"
             : "a fifteenth of it where rounding does not make most of it, RK4 being of order 4 "
               "on smooth forces; the two runs are extrapolated to dt = 0 that way, Richardson's, "
               "for the reference")
     << "). Errors below " << number(kFitFloor * reference.error)
     << " m are at the reference's limit and are left out of the fitted orders.\n\n"
     << "![error against run time](report.png)\n\n"
     << "| integrator | dt (s) | tolerance | steps | evaluations | CPU (s) | RMS error (m) | max "
        "error (m) | status |\n"
     << "|---|---|---|---|---|---|---|---|---|\n";
  for (const ReportRow& r : rows) {
    md << "| " << integratorName(r.integrator) << (r.worldsOwn ? " (the world's own)" : "") << " | "
       << exactNumber(r.dt) << " | " << toleranceCell(r) << " | " << r.steps << " | "
       << r.evaluations << " | " << number(r.cpuSeconds) << " | "
       << (r.diverged ? "" : number(r.rmsError)) << " | " << (r.diverged ? "" : number(r.maxError))
       << " | " << (r.diverged ? "diverged" : "ok") << " |\n";
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
void markdownAdvice(const std::string& worldPath, const ReportRow& row, const ReportRow* own,
                    std::ostringstream& md) {
  const Advice advice = advise(worldPath, row, own);
  md << advice.setting << ".\n  - Run it: " << codeSpan(advice.run) << "\n";
  if (!advice.keep.empty()) md << "  - Keep it in a world file: " << codeSpan(advice.keep) << "\n";
  if (!advice.sceneKeys.empty())
    md << "  - Keep it in the scene file: " << codeSpan(advice.sceneKeys) << "\n";
}

// report.md's recommendations.
std::string markdownRecommendations(const std::string& worldPath,
                                    const Recommendations& recommended, double visualTolerance) {
  const ReportRow* own = recommended.own;
  std::ostringstream md;
  md << "\n## Recommendations\n\n";
  if (own) {
    md << "The world's own setting, " << settingText(*own) << ", "
       << (own->diverged ? std::string("diverges before T.")
                         : "takes " + number(own->cpuSeconds) + " s for an error of " +
                               number(own->rmsError) + " m.")
       << "\n\n";
  }
  auto recommendation = [&](const std::string& what, const Choice& choice) {
    md << "- **" << what << "**: ";
    if (!choice.best) {
      md << "none of the runs.\n";
    } else if (choice.best == own) {
      md << "the world's own setting; nothing cheaper is as accurate.\n";
    } else {
      markdownAdvice(worldPath, *choice.best, own, md);
    }
    if (!choice.leftOut.empty()) md << "  - " << choice.leftOut << ".\n";
    if (!choice.best || worldFileHolds(*choice.best)) return;
    md << "  - " << noWorldFileNote() << ". The cheapest setting a world file can hold: ";
    if (!choice.inWorldFile)
      md << "none of the runs.\n";
    else if (choice.inWorldFile == own)
      md << "the world's own.\n";
    else
      markdownAdvice(worldPath, *choice.inWorldFile, own, md);
  };
  if (own && own->diverged)
    md << "- **The cheapest setting at least as accurate as the world's own**: the world's own "
          "diverges, so any run that does not is more accurate; see the next.\n";
  else
    recommendation("The cheapest setting at least as accurate as the world's own",
                   recommended.asAccurate);
  recommendation(
      "The cheapest setting within the visual tolerance (" + number(visualTolerance) + " m RMS)",
      recommended.looksSame);
  return md.str();
}

// report.csv, report.md and report.gp into the claimed folder. Throws OutputError.
void writeReportFiles(const std::string& worldPath, const ReportOptions& options,
                      const std::vector<Integrator>& integrators,
                      const std::vector<ReportRow>& rows, const Reference& reference,
                      const std::vector<OrderCheck>& orders, const Recommendations& recommended) {
  const Existing existing = options.overwrite ? Existing::Replace : Existing::Refuse;
  const double T = options.time, floor = kFitFloor * reference.error;
  const std::string title = worldPath + ": error at T = " + number(T) + " s against run time";
  const std::string md = markdownRuns(worldPath, T, reference, rows) +
                         markdownOrders(orders, reference.contacts) +
                         markdownRecommendations(worldPath, recommended, options.visualTolerance);
  writeFileWhole(options.dir + "/report.csv", reportCsv(rows), existing);
  writeFileWhole(options.dir + "/report.md", md, existing);
  writeFileWhole(options.dir + "/report.gp",
                 gnuplotScript(rows, integrators, floor, options.visualTolerance, title), existing);
}

// The lines on stdout for one recommendation ("as accurate as the world's own"): the setting,
// the command that runs it, and the one that keeps it in a world file.
void printChoice(const std::string& what, const std::string& worldPath, const Choice& choice,
                 const ReportRow* own) {
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
    const Advice advice = advise(worldPath, row, own);
    std::printf("  run it:  %s\n", advice.run.c_str());
    if (!advice.keep.empty()) std::printf("  keep it: %s\n", advice.keep.c_str());
    if (!advice.sceneKeys.empty())
      std::printf("  keep it: %s in %s\n", advice.sceneKeys.c_str(), printable(worldPath).c_str());
  };
  std::printf("%s: %s\n", what.c_str(), advise(worldPath, *choice.best, own).setting.c_str());
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
              advise(worldPath, *choice.inWorldFile, own).setting.c_str());
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
    printChoice("as accurate as the world's own", worldPath, recommended.asAccurate,
                recommended.own);
  const std::string within = "within " + number(options.visualTolerance) + " m";
  // The same setting twice: its commands once (a second createWorld would refuse its file).
  if (first && recommended.looksSame.best && recommended.looksSame.best != recommended.own &&
      recommended.looksSame.best == recommended.asAccurate.best)
    std::printf("%s: the same setting\n", within.c_str());
  else
    printChoice(within, worldPath, recommended.looksSame, recommended.own);
}

}  // namespace

Outcome runReport(const RunOptions& runOptions, const ReportOptions& options) {
  WorldFile file;
  if (Outcome loaded = loadRun(runOptions, &file); !loaded.ok()) return loaded;
  const World& world = file.world;
  const Model model = makeModel(world, file.state);
  const double T = options.time;
  // The world's own setting runs to T at the world's dt (the sweeps' steps are T / 2^k).
  if (!stepsForTime(T, world.dt)) return failed("--report: " + tooManyStepsMessage(T, world.dt));
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
  measureAll(study, integrators, world, runOptions.tolerances, &measured);
  const Reference& reference = measured.reference;
  if (reference.diverged) {
    if (made) ::rmdir(options.dir.c_str());  // only when empty: the folder this run made
    return diverged("--report: the reference run (RK4 at dt=" + number(reference.step) +
                    ") diverged; no report");
  }
  std::vector<ReportRow>& rows = measured.rows;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (!rows[i].diverged)
      rows[i].rmsError = rms(measured.ends[i], reference.end, &rows[i].maxError);
  }
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
