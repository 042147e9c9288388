// simulation.h: a run of a world, step by step, with the divergence checks: the one
// step-then-check loop. Headless runs, the viewer, --report, --check --map's observed limits
// and --bench all advance through it.
//
// The checks, one rule for every caller. After step s (s counted from the start, 1-based):
//  - always the cheap test of docs/physics.md (Divergence): a position or velocity that is not
//  finite, or a point more
//    than 100 m from the origin (findDivergedPoint's test);
//  - when s is a multiple of max(n, kEnergyEvery), n the run's steps per drawn frame, the
//    energy bound of the guard (guard.h) as well: at most once a drawn frame, and no more often
//    than every kEnergyEvery steps, since the energy costs about a fifth of an RK4 step;
//  - never the energy bound after a step taken with a pull (the viewer's mouse adds energy the
//    bound does not know of); the first step without one restarts the bound from the state then.
// The checks depend on the step number alone, never on how steps are grouped into advance()
// calls: advancing 1000 times by 1 or once by 1000 stops at the same step for the same reason.
//
// How many steps fit in T seconds is stepsForTime(T, dt), below, for every caller.
#pragma once

#include <optional>
#include <string>

#include "core/limits.h"
#include "model/world.h"
#include "solver/guard.h"
#include "solver/integrators.h"
#include "solver/physics.h"

namespace jello {

// The energy bound is checked at most this often (steps); see the rule above.
constexpr long long kEnergyEvery = 8;

// Number of steps of dt that fit in T seconds, for every caller (--time, --report, the observed
// stability limits): the fewest that reach T, with a relative slack of kStepSlack that keeps
// T = 1, dt = 0.001 at 1000 steps despite rounding. Empty when T/dt is not a finite number or
// exceeds kMaxSteps (--time 1e16, or --dt 1e-300): no conversion to an integer is attempted then.
std::optional<long long> stepsForTime(double time, double dt);
constexpr double kStepSlack = 1e-9;
// The one line (without "jello: ") that refuses a --time T that stepsForTime cannot count at such a
// dt.
std::string tooManyStepsMessage(double time, double dt);

// How an advance ended.
struct RunOutcome {
  enum class Kind {
    Ran,             // every step asked for was taken and passed the checks
    Diverged,        // a step reached a state no physics of the world produces
    ToleranceUnmet,  // RK45 gave a step up: its tolerances are finer than doubles resolve
  };
  Kind kind = Kind::Ran;
  long long step = 0;  // the step that failed, counted from the start (not for Ran)
  double time = 0;     // s, at the end of that step
  std::string reason;  // Diverged: the guard's words, e.g. "point p[0][0][0] is no longer finite"
  bool ran() const { return kind == Kind::Ran; }
};

class Simulation {
 public:
  // A run of `model` from `start` (copied) with the run's integrator at steps of its dt seconds
  // (which the simulation holds: nothing else does during a run). The model
  // is referenced, not copied: it must outlive the simulation. Costs what a DivergenceGuard
  // costs to make (a pass over the field's nodes).
  Simulation(const Model& model, const State& start, const RunSettings& run,
             Tolerances tolerances = {});
  // The same with n = 1 (the energy bound every kEnergyEvery steps): a run that draws no frames.
  Simulation(const Model& model, const State& start, Integrator integrator, double dt,
             Tolerances tolerances = {})
      : Simulation(model, start, RunSettings{integrator, dt, 1}, tolerances) {}
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  // Takes `steps` steps, each with the pull when one is given (nullptr: none), checking each
  // as the rule above says; stops at the first that fails. Once a run has failed it takes no
  // more steps and returns the same outcome, until restart() or restore(). Allocates nothing
  // once the stepper's buffers are sized (IMPLICIT's solver excepted; contact between bodies
  // grows its buffers when more pairs touch than ever before), unless it fails.
  RunOutcome advance(long long steps, const Pull* pull = nullptr);
  // Runs on to `time` s: stepsForTime(time, dt) steps from the start in all, the last one
  // shortened to end on `time` exactly when dt does not divide it (--report compares runs of
  // different steps at one instant). The caller has checked that stepsForTime gives a count.
  RunOutcome advanceTo(double time);

  // Back to step 0 at `start`, with a fresh stepper and the guard's bound from `start`: a run
  // that costs what the first did (--bench repeats runs). No pass over the field.
  void restart(const State& start);
  // Puts the run back at `state`, `step` steps from the start (the viewer's last good frame
  // after a divergence), ready to advance again; the guard's bound is kept.
  void restore(const State& state, long long step);

  // Goes on from the current state and time with `run`'s integrator, dt and steps per frame, after
  // the model this simulation references was replaced in place (the window's panel assigns it a
  // new one): a fresh stepper (VERLET and RK45 start their memory afresh, as from a state file) and
  // a guard whose bound starts from the current state under the new model. The next steps are bit
  // for bit a new Simulation's from this state; the time goes on from here at the new dt.
  void change(const RunSettings& run);

  // Adds `dv` (m/s) to the velocity of every point the model does not pin: the viewer's push and
  // jump keys. The work done is the user's, as a pull's is: the guard's energy bound starts
  // afresh from the new state, so that the push is not taken for a divergence.
  void addVelocity(Vec3 dv);

  const State& state() const { return state_; }
  long long step() const { return step_; }
  double time() const {
    return time_;
  }  // s: step * dt (advanceTo's last step: its time; after
     // change(), dt a step since it)
  double dt() const { return dt_; }
  Integrator integrator() const { return stepper_.integrator(); }
  const StepStats& stats() const { return stepper_.stats(); }  // the stepper's, since the start
  const Model& model() const { return model_; }
  // Shares each force evaluation between the threads of `pool` (physics.h's workersFor: as many
  // as the body's size makes worth it; bySize false: all of them), with the same results bit for
  // bit; null: this thread alone (the default). The pool must outlive its use here.
  void setPool(ThreadPool* pool, bool bySize = true);
  // The threads each evaluation is shared between.
  int threads() const { return workers_.threads(); }

 private:
  bool stepAndCheck(double h, double timeAfter, const Pull* pull);
  // The time at the end of step `step`: dt a step since the last change of dt.
  double timeAt(long long step) const {
    return timeBase_ + static_cast<double>(step - stepBase_) * dt_;
  }

  const Model& model_;
  State state_;
  double dt_;
  long long step_ = 0;
  double time_ = 0;
  double timeBase_ = 0;     // s, the time at step stepBase_: where change() found the run
  long long stepBase_ = 0;  // (0 and 0 until then)
  long long energyEvery_;
  bool pulled_ = false;  // the last step had a pull: the next one without restarts the bound
  Tolerances tolerances_;
  Stepper stepper_;
  Workers workers_;
  bool workersBySize_ = true;
  DivergenceGuard guard_;
  RunOutcome outcome_;
};

// Whether `state` passes the cheap test: findDivergedPoint(state) < 0, in one pass without a
// branch per point (the test runs after every step).
bool passesCheapTest(const State& state);

}  // namespace jello
