// The one step-then-check loop (simulation.h): its outcomes, its rule of checks, its steps in T.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "app/headless.h"
#include "core/exitstatus.h"
#include "solver/guard.h"
#include "solver/integrators.h"
#include "solver/physics.h"
#include "solver/simulation.h"
#include "test_support.h"

namespace jello {
namespace {

std::string sourcePath(const std::string& name) {
  return std::string(JELLO_SOURCE_DIR) + "/" + name;
}

bool sameBits(const State& a, const State& b) {
  return std::memcmp(a.y.data(), b.y.data(), a.y.size() * sizeof(double)) == 0;
}

struct DivergingCase {
  const char* world;  // under the source folder
  Integrator integrator;
  double dt;
  // What `jello --headless` reported before the loop was one Simulation.
  long long step;
  double time;
  const char* reason;
  bool runJello;  // compare with jello's own line too (its diagnosis takes seconds)
};

// The step, the time and the guard's reason are what runHeadless reported, and what it reports now.
TEST(Simulation, ADivergingRunReportsTheStepTimeAndReasonTheHeadlessRunReported) {
  const DivergingCase cases[] = {
      // the energy bound, on a step that is a multiple of n = 10
      {"world/stress/stiff-1e5.w", Integrator::RK4, 1e-4, 100, 0.01,
       "its energy, 9.6e+03 J, is beyond what the world's forces can supply (2.21e+03 J)", true},
      // the cheap test, on a step that is no multiple of max(n, 8)
      {"world/rotate.w", Integrator::Euler, 0.01, 7, 0.07,
       "point p[0][3][3] is more than 100 m from the origin", false},
  };
  for (const DivergingCase& c : cases) {
    WorldFile f = readWorldFile(sourcePath(c.world));
    Model model = makeModel(f.world, f.state);
    // As the headless run: the world file's n (the energy bound's cadence), the case's step.
    Simulation simulation(model, f.state, RunSettings{c.integrator, c.dt, f.run.n});
    const RunOutcome outcome = simulation.advance(2000);
    EXPECT_EQ(outcome.kind, RunOutcome::Kind::Diverged) << c.world;
    EXPECT_EQ(outcome.step, c.step) << c.world;
    EXPECT_EQ(outcome.time, c.step * c.dt) << c.world;
    EXPECT_DOUBLE_EQ(outcome.time, c.time) << c.world;
    EXPECT_EQ(outcome.reason, c.reason) << c.world;
    EXPECT_EQ(simulation.step(), c.step) << "no step after the one that failed";
    if (!c.runJello) continue;

    char expected[300];
    std::snprintf(expected, sizeof expected, "diverged at step %lld (t=%g s): %s;", c.step, c.time,
                  c.reason);
    test::CommandResult run = test::runJelloArgs({"--headless", "--steps", "2000", "--integrator",
                                                  integratorName(c.integrator), "--dt",
                                                  std::to_string(c.dt), sourcePath(c.world)});
    EXPECT_EQ(run.status, kExitDiverged) << run.err;
    EXPECT_NE(run.err.find(expected), std::string::npos) << run.err;
  }
}

// The checks depend on the step number alone: any grouping of the steps stops at the same step,
// for the same reason, in the same state.
// The window's panel changes dt and the integrator as a run goes: after change(), the run is bit
// for bit a new Simulation's from the state it had reached, and its time goes on from there.
TEST(Simulation, AChangeOfStepAndIntegratorGoesOnAsANewRunFromTheStateReached) {
  const WorldFile file = readWorldFile(test::dataPath("rotate.w"));
  const Model model = makeModel(file.world, file.state);
  Simulation run(model, file.state, {Integrator::RK4, 0.001, 10});
  ASSERT_TRUE(run.advance(50).ran());
  const State reached = run.state();
  const double timeThen = run.time();
  run.change({Integrator::Midpoint, 0.0004, 3});
  EXPECT_EQ(run.integrator(), Integrator::Midpoint);
  EXPECT_EQ(run.dt(), 0.0004);
  ASSERT_TRUE(run.advance(40).ran());
  Simulation fresh(model, reached, {Integrator::Midpoint, 0.0004, 3});
  ASSERT_TRUE(fresh.advance(40).ran());
  EXPECT_EQ(run.state().y, fresh.state().y);
  EXPECT_EQ(run.step(), 90);
  EXPECT_DOUBLE_EQ(run.time(), timeThen + 40 * 0.0004);
  run.restore(reached, 60);  // the time of a step after the change: dt a step since it
  EXPECT_DOUBLE_EQ(run.time(), timeThen + 10 * 0.0004);
}

TEST(Simulation, StopsAtTheSameStepHoweverItsStepsAreGrouped) {
  WorldFile f = readWorldFile(sourcePath("world/stress/stiff-1e5.w"));
  f.run.n = 1;  // the energy every 8 steps, which advancing by 7 does not line up with
  Model model = makeModel(f.world, f.state);
  Simulation whole(model, f.state, Integrator::RK4, 1e-4),
      single(model, f.state, Integrator::RK4, 1e-4), sevens(model, f.state, Integrator::RK4, 1e-4);
  const RunOutcome once = whole.advance(300);
  RunOutcome bySingle, bySevens;
  for (int i = 0; i < 300 && bySingle.ran(); ++i) bySingle = single.advance(1);
  for (int i = 0; i < 300 && bySevens.ran(); i += 7) bySevens = sevens.advance(7);
  for (const RunOutcome* other : {&bySingle, &bySevens}) {
    EXPECT_EQ(other->kind, once.kind);
    EXPECT_EQ(other->step, once.step);
    EXPECT_EQ(other->reason, once.reason);
  }
  EXPECT_TRUE(sameBits(single.state(), whole.state()));
  EXPECT_TRUE(sameBits(sevens.state(), whole.state()));
  // A failed run takes no more steps and says the same again.
  const RunOutcome again = whole.advance(10);
  EXPECT_EQ(again.step, once.step);
  EXPECT_EQ(whole.step(), once.step);
}

// The energy bound runs on the multiples of max(n, 8): a divergence it catches is found there.
TEST(Simulation, ChecksTheEnergyOnMultiplesOfTheLargerOfNAndEight) {
  for (int n : {1, 3, 12, 25}) {
    WorldFile f = readWorldFile(sourcePath("world/stress/stiff-1e5.w"));
    f.run.n = n;
    Model model = makeModel(f.world, f.state);
    Simulation simulation(model, f.state, RunSettings{Integrator::RK4, 1e-4, f.run.n});
    const RunOutcome outcome = simulation.advance(2000);
    ASSERT_EQ(outcome.kind, RunOutcome::Kind::Diverged) << n;
    ASSERT_EQ(outcome.reason.rfind("its energy", 0), 0u) << outcome.reason;
    const long long every = std::max(n, 8);
    EXPECT_EQ(outcome.step % every, 0) << "n = " << n << ": step " << outcome.step;
    // and not much later than where every step's check finds it (step 100 at n = 10)
    EXPECT_LE(std::abs(outcome.step - 100), every) << n;
  }
}

// While the user pulls, the energy bound is not checked (the pull adds energy); the first step
// without a pull restarts the bound from the state then, so that the pull's work is allowed.
TEST(Simulation, APullSkipsTheEnergyBoundAndLettingGoRestartsIt) {
  WorldFile f = readWorldFile(test::dataPath("still.w"));
  Model model = makeModel(f.world, f.state);
  Simulation simulation(model, f.state, Integrator::RK4, 1e-3);
  Pull pull;
  pull.point = pointIndex(7, 7, 7);
  pull.stiffness = 2000;
  pull.target = load(f.state.p(), pull.point) + Vec3{1.5, 0, 0};
  ASSERT_TRUE(simulation.advance(400, &pull).ran());
  // The pulled state holds far more energy than the start's bound allows...
  DivergenceGuard fromTheStart(model, f.state);
  ASSERT_NE(fromTheStart.check(simulation.state(), simulation.time()), "")
      << "the pull added too little energy";
  // ...and the run goes on without a pull, checked against a bound that starts there.
  EXPECT_TRUE(simulation.advance(400).ran());
  EXPECT_EQ(simulation.step(), 800);
}

// The viewer's push: every free point gains the velocity, a pinned one keeps its zero to the
// bit; the energy the push adds is not taken for a divergence.
TEST(Simulation, AddVelocityMovesEveryFreePointAndNoPinnedOneAndRestartsTheBound) {
  WorldFile f = readWorldFile(test::dataPath("still.w"));
  f.run.n = 1;  // the energy bound checked every kEnergyEvery steps
  Model model = makeModel(f.world, f.state);
  model.pinned = {pointIndex(0, 0, 0), pointIndex(7, 7, 7)};
  Simulation simulation(model, f.state, Integrator::RK4, 1e-3);
  const Vec3 dv{3, -4, 2};
  simulation.addVelocity(dv);
  for (int q = 0; q < kNumPoints; ++q) {
    const bool pinned = q == model.pinned[0] || q == model.pinned[1];
    const Vec3 v = load(simulation.state().v(), q), expected = load(f.state.v(), q) + dv;
    EXPECT_EQ(length(v - (pinned ? load(f.state.v(), q) : expected)), 0) << q;
  }
  DivergenceGuard fromTheStart(model, f.state);
  ASSERT_NE(fromTheStart.check(simulation.state(), 0), "") << "the push added too little energy";
  EXPECT_TRUE(simulation.advance(4 * kEnergyEvery).ran());
}

// --report's steps T/2^k land on T: stepsForTime counts 2^k of them, as the report's own
// formula did (floor(T/dt (1 + 1e-12)) whole steps and no remainder), and advanceTo takes them.
TEST(StepsForTime, AgreesWithTheReportsStepsOfTOverTwoToTheK) {
  for (double T : {1.0, 0.002, 0.1, 0.3, 3.7, 1e-3, 250.0}) {
    for (int k = 0; k <= 24; ++k) {
      const double dt = T / static_cast<double>(1LL << k);
      const long long reportWhole = static_cast<long long>(std::floor(T / dt * (1 + 1e-12)));
      const double reportRest = T - reportWhole * dt;
      EXPECT_EQ(stepsForTime(T, dt), 1LL << k) << "T=" << T << " k=" << k;
      EXPECT_EQ(reportWhole, 1LL << k) << "T=" << T << " k=" << k;
      EXPECT_LE(reportRest, 1e-12 * T) << "the report took no short last step";
    }
  }
  WorldFile f = readWorldFile(test::dataPath("rotate.w"));
  Model model = makeModel(f.world, f.state);
  for (int k = 0; k <= 5; ++k) {
    const double T = 0.001, dt = T / (1 << k);  // within RK4's stable step for rotate.w
    Simulation to(model, f.state, Integrator::RK4, dt), by(model, f.state, Integrator::RK4, dt);
    ASSERT_TRUE(to.advanceTo(T).ran());
    ASSERT_TRUE(by.advance(1LL << k).ran());
    EXPECT_EQ(to.step(), 1LL << k);
    EXPECT_TRUE(sameBits(to.state(), by.state())) << k;
  }
}

// A dt that does not divide T (the world's own in --report): stepsForTime's count of steps, the
// last one shortened so that the run ends on T.
TEST(Simulation, AdvanceToShortensTheLastStepToEndOnTheTime) {
  WorldFile f = readWorldFile(test::dataPath("rotate.w"));
  Model model = makeModel(f.world, f.state);
  const double T = 0.05, dt = 0.0007;  // 72 steps, the last of 0.3 ms
  Simulation simulation(model, f.state, Integrator::RK4, dt);
  ASSERT_TRUE(simulation.advanceTo(T).ran());
  EXPECT_EQ(simulation.step(), *stepsForTime(T, dt));
  EXPECT_EQ(simulation.time(), T);
  State expected = f.state;
  Stepper stepper(Integrator::RK4);
  for (long long s = 1; s < *stepsForTime(T, dt); ++s) stepper.step(model, expected, dt);
  stepper.step(model, expected, T - (*stepsForTime(T, dt) - 1) * dt);
  EXPECT_TRUE(sameBits(simulation.state(), expected));
}

// RK45 giving a step up is its own outcome, not a divergence.
TEST(Simulation, AToleranceBeyondDoublesIsItsOwnOutcome) {
  WorldFile f = readWorldFile(test::dataPath("rotate.w"));
  Model model = makeModel(f.world, f.state);
  Simulation simulation(model, f.state, Integrator::RK45, 0.01, Tolerances{1e-300, 1e-300});
  const RunOutcome outcome = simulation.advance(5);
  EXPECT_EQ(outcome.kind, RunOutcome::Kind::ToleranceUnmet);
  EXPECT_EQ(outcome.step, 1);
}

// restart() gives a run that repeats the first bit for bit, with the same counts (the stepper's
// memory afresh, its buffers kept: RK45's last step, IMPLICIT's solver); restore() goes back to a
// saved state.
TEST(Simulation, RestartRepeatsTheRunAndRestoreGoesBack) {
  WorldFile f = readWorldFile(test::dataPath("rotate.w"));
  Model model = makeModel(f.world, f.state);
  for (Integrator integrator : {Integrator::RK45, Integrator::Implicit}) {
    Simulation run(model, f.state, integrator, 0.001);
    ASSERT_TRUE(run.advance(20).ran());
    const State once = run.state();
    const StepStats stats = run.stats();
    run.restart(f.state);
    EXPECT_EQ(run.stats().evaluations, 0);
    ASSERT_TRUE(run.advance(20).ran());
    EXPECT_TRUE(sameBits(run.state(), once)) << integratorName(integrator);
    EXPECT_EQ(run.stats().evaluations, stats.evaluations) << integratorName(integrator);
    EXPECT_EQ(run.stats().rejected, stats.rejected) << integratorName(integrator);
  }
  Simulation simulation(model, f.state, Integrator::RK45, 0.001);
  ASSERT_TRUE(simulation.advance(40).ran());
  const State first = simulation.state();
  simulation.restart(f.state);
  EXPECT_EQ(simulation.step(), 0);
  ASSERT_TRUE(simulation.advance(40).ran());
  EXPECT_TRUE(sameBits(simulation.state(), first));
  simulation.restore(f.state, 3);
  EXPECT_EQ(simulation.step(), 3);
  EXPECT_EQ(simulation.time(), 3 * 0.001);
  EXPECT_TRUE(sameBits(simulation.state(), f.state));
}

// The loop's cheap test is findDivergedPoint's, on states sane and not.
TEST(Simulation, TheCheapTestIsFindDivergedPointsTest) {
  const double inf = std::numeric_limits<double>::infinity(), nan = std::nan("");
  const double odd[] = {nan,   inf,   -inf,  100.0,   -100.0, 100.0000001,
                        57.73, 57.74, 1e200, -1e-310, -0.0,   1e155};
  std::mt19937_64 random(7);
  std::uniform_int_distribution<int> anyCoordinate(0, 2 * kNumCoords - 1);
  std::uniform_int_distribution<int> anyOdd(0, static_cast<int>(std::size(odd)) - 1);
  int bad = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    State state = test::restLattice();
    for (int changes = trial % 4; changes > 0; --changes)
      state.y[anyCoordinate(random)] = odd[anyOdd(random)];
    if (trial % 7 == 0) {  // three coordinates of one point, near the radius together
      const int q = trial % kNumPoints;
      for (int axis = 0; axis < 3; ++axis) state.p()[coordIndex(q, axis)] = odd[6 + trial % 2];
    }
    const bool expected = findDivergedPoint(state) < 0;
    bad += !expected;
    ASSERT_EQ(passesCheapTest(state), expected) << "trial " << trial;
  }
  EXPECT_GT(bad, 1000) << "the trials should hold many diverged states";
}

}  // namespace
}  // namespace jello
