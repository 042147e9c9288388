// analysis/reportruns.cpp: jello --report's runs (reportstudy.h): each integrator's largest stable
// step, its sweep of halving steps, the world's own setting and the reference, on every core,
// timed by their threads' CPU time.

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

// A search's result: the largest stable step and, when one was found, the search's own runs at
// that step and at half of it, which are its sweep's first two.
struct StableStep {
  double dt = 0;
  std::vector<Run> runs;
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

// The largest step T/(8 2^k) at which `integrator` is stable: its run does not diverge and ends
// where the run at half the step ends, to within kSameEnd (an unstable run need not reach
// the 100 m of docs/physics.md's divergence rule within T).
StableStep largestStableStep(const Study& s, Integrator integrator) {
  Run previous = simulate(s.model, s.start, integrator, s.T / kLargestStepDivisor, s.T);
  for (int k = 0; k < kSearchHalvings; ++k) {
    double dt = s.T / (kLargestStepDivisor << k);
    s.progress.update(std::string("finding ") + integratorName(integrator) +
                      "'s largest stable step, dt=" + reportNumber(dt));
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
    study.progress.next("the reference, RK4 dt=" + reportNumber(r.step) +
                        " and dt=" + reportNumber(2 * r.step));
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

}  // namespace

// The calling thread's CPU time, s. Runs are timed by it, not by the wall clock: it leaves out
// the time the thread waits for a core, so a run's figure is its own whatever else the machine
// (or the report's other runs, on the other cores) does at the time.
double threadCpuSeconds() {
  timespec now{};
  ::clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

bool sweepsTolerance(Integrator integrator) { return integrator == Integrator::RK45; }

int reportItemCount(const std::vector<Integrator>& integrators) {
  int items = 2;
  for (Integrator integrator : integrators)
    items += kSweepLength + (sweepsTolerance(integrator) ? 0 : 1);
  return items;
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

std::string reportNumber(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", x);
  return text;
}

// Every sweep, the world's own setting and the reference, on every core. The world's own is a
// row of its own unless a sweep runs the same setting, which is then marked as the world's and
// run once.
void measureAll(const Study& s, const std::vector<Integrator>& integrators,
                const RunSettings& world, const Tolerances& tolerances, Measured* m) {
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

}  // namespace jello
