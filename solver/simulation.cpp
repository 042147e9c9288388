// simulation.cpp: the one step-then-check loop (simulation.h states its rule).

#include "solver/simulation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>

#include "core/assert.h"

namespace jello {

std::optional<long long> stepsForTime(double time, double dt) {
  const double steps = std::ceil(time / dt * (1 - kStepSlack));
  if (!(steps <= kMaxSteps)) return std::nullopt;  // also NaN and infinity
  return static_cast<long long>(std::max(steps, 0.0));
}

bool passesCheapTest(const State& state) {
  const double* p = state.p();
  const double* v = state.v();
  constexpr double kRadiusSquared = kDivergenceRadius * kDivergenceRadius;
  // One pass without an exit or a branch per point (it runs after every step: 0.9 us here, where
  // findDivergedPoint's loop takes 1.3). A NaN fails every comparison and an infinite coordinate
  // makes the squared distance infinite, so `r2 <= R^2` holds exactly for a finite position
  // within the radius; and v * 0 is 0 for a finite velocity component, NaN otherwise. Together:
  // findDivergedPoint's test, point by point.
  bool sane = true;
  const int n = state.points();
  for (int q = 0; q < n; ++q) {
    const double x = p[q], y = p[n + q], z = p[2 * n + q];
    const double r2 = x * x + y * y + z * z;
    const double zero = v[q] * 0 + v[n + q] * 0 + v[2 * n + q] * 0;
    sane &= (r2 <= kRadiusSquared) & (zero == 0);
  }
  return sane;
}

Simulation::Simulation(const Model& model, const State& start, const RunSettings& run,
                       Tolerances tolerances)
    : model_(model),
      state_(start),
      dt_(run.dt),
      energyEvery_(std::max<long long>(run.n, kEnergyEvery)),
      tolerances_(tolerances),
      stepper_(run.integrator, tolerances),
      guard_(model, start) {
  // The start holds the model's body's points; a step is a positive, finite time.
  JELLO_ASSERT(start.points() == model.points());
  JELLO_ASSERT(run.dt > 0 && std::isfinite(run.dt));
}

bool Simulation::stepAndCheck(double h, double timeAfter, const Pull* pull) {
  // The pull's work is the world's energy once the user lets go: the bound starts afresh.
  if (pulled_ && !pull) guard_.restart(state_, time_);
  pulled_ = pull != nullptr;
  const long long failedBefore = stepper_.stats().failed;
  stepper_.step(model_, state_, h, pull, &workers_);
  ++step_;
  time_ = timeAfter;
  if (stepper_.stats().failed != failedBefore) {
    outcome_ = {RunOutcome::Kind::ToleranceUnmet, step_, time_, ""};
    return false;
  }
  const bool energyStep = !pull && step_ % energyEvery_ == 0;
  if (!energyStep && passesCheapTest(state_)) return true;
  std::string wrong = guard_.check(state_, time_);  // the cheap test again, naming the point
  if (wrong.empty()) return true;
  outcome_ = {RunOutcome::Kind::Diverged, step_, time_, std::move(wrong)};
  return false;
}

RunOutcome Simulation::advance(long long steps, const Pull* pull) {
  if (!outcome_.ran()) return outcome_;
  for (long long i = 0; i < steps; ++i)
    if (!stepAndCheck(dt_, timeAt(step_ + 1), pull)) break;
  return outcome_;
}

RunOutcome Simulation::advanceTo(double time) {
  JELLO_ASSERT(stepBase_ == 0);  // counted from the start at one dt: never after change()
  const std::optional<long long> total = stepsForTime(time, dt_);
  if (!total) throw std::logic_error("advanceTo: more steps than a run may take");
  if (*total <= step_ || !outcome_.ran()) return outcome_;
  // What the last step has left to go: a whole step, to stepsForTime's slack, when dt divides
  // the time (T/2^k always does); otherwise less, and the last step is that long.
  const double rest = time - static_cast<double>(*total - 1) * dt_;
  if (rest >= dt_ * (1 - kStepSlack)) return advance(*total - step_);
  const RunOutcome wholeSteps = advance(*total - 1 - step_);
  if (!wholeSteps.ran()) return wholeSteps;
  stepAndCheck(rest, time, nullptr);
  return outcome_;
}

void Simulation::restart(const State& start) {
  state_ = start;
  step_ = 0;
  time_ = 0;
  timeBase_ = 0;
  stepBase_ = 0;
  pulled_ = false;
  stepper_.restart();
  guard_.restart(start, 0);
  outcome_ = {};
}

void Simulation::addVelocity(Vec3 dv) {
  const int n = model_.points();
  std::vector<bool> pinned(n, false);
  for (int q : model_.pinned) pinned[q] = true;
  for (int q = 0; q < n; ++q)
    if (!pinned[q]) store(state_.v(), q, n, load(state_.v(), q, n) + dv);
  guard_.restart(state_, time_);
}

void Simulation::restore(const State& state, long long step) {
  state_ = state;
  step_ = step;
  time_ = timeAt(step);
  outcome_ = {};
}

void Simulation::change(const RunSettings& run) {
  JELLO_ASSERT(state_.points() == model_.points());
  JELLO_ASSERT(run.dt > 0 && std::isfinite(run.dt));
  timeBase_ = time_;
  stepBase_ = step_;
  dt_ = run.dt;
  energyEvery_ = std::max<long long>(run.n, kEnergyEvery);
  stepper_ = Stepper(run.integrator, tolerances_);
  guard_ = DivergenceGuard(model_, state_);
  guard_.restart(state_, time_);
  pulled_ = false;
  outcome_ = {};
  if (workers_.pool) setPool(workers_.pool, workersBySize_);  // the model's ranges again
}

void Simulation::setPool(ThreadPool* pool, bool bySize) {
  workers_ = workersFor(model_, pool, bySize);
  workersBySize_ = bySize;
}

std::string tooManyStepsMessage(double time, double dt) {
  char steps[64] = "more steps than a double can count";
  if (std::isfinite(time / dt)) std::snprintf(steps, sizeof steps, "%g steps", time / dt);
  char text[256];
  std::snprintf(text, sizeof text,
                "--time %g s at --dt %g s would take %s, more than the %g a run may take; choose a "
                "shorter --time or a larger --dt",
                time, dt, steps, kMaxSteps);
  return text;
}

}  // namespace jello
