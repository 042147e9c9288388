// checkkit.h: what the checks share: the worlds and states they probe with, and the
// comparisons. Internal to the grader's checks.
#pragma once

#include <string>
#include <vector>

#include "grader/checks.h"
#include "grader/probe.h"
#include "io/input.h"
#include "model/term.h"
#include "model/world.h"

namespace jello::grader {

// The world the term checks probe with: constants unlike each other and unlike the course's, so
// that one used in another's place shows; no plane; a field of R = 30 zero nodes (the course's
// resolution: a submission that assumes it still reads the field right).
World probeWorld();
// The run settings of the probe's worlds: RK4 at dt 0.5 ms, n 1.
RunSettings probeRun();
constexpr double kProbeMass = 1.0 / kNumPoints;  // kg: exact in binary

// The cube at rest, p[i][j][k] = (i,j,k)/7, turned by `angle` radians about (1,2,3) around its
// centre, then moved by `offset`; velocities zero.
State restLattice(Vec3 offset, double angle = 0);
// The lattice's usual place for the term checks: centred on the origin.
constexpr Vec3 kCentred = {-0.5, -0.5, -0.5};

// "p[i][j][k]".
std::string pointName(int q);
// "(1,-1,0)".
std::string offsetName(int di, int dj, int dk);

// The forces (N) between two answers of accelerations: mass * (after - before) for point q.
Vec3 forceChange(const std::vector<double>& after, const std::vector<double>& before, int q);

// When `measured` is `expected` times the probe's mass (1/512 kg) or its square, to rounding:
// words that name the mass (" (exactly 1/512 of it, the mass: is the force not divided by the
// mass?)"); otherwise "". Every constant a force-free mistake puts off by the same factor.
std::string massHint(double measured, double expected);

// The largest |value| of per-point arrays (whether they are usable at all: allUsable, probe.h).
double largest(const std::vector<double>& values);

CheckResult passed(const std::string& check, std::string line = {});
CheckResult near(const std::string& check, std::string line);
CheckResult failed(const std::string& check, std::string line);
CheckResult info(const std::string& check, std::string line);
// The accelerations at each of `states` in `world`, in one probe run; empty, with *failure saying
// what went wrong, when it did not answer them all, or answered a NaN or an infinity.
std::vector<std::vector<double>> accelerationsAt(const std::string& probe, const World& world,
                                                 const std::vector<State>& states,
                                                 std::string* failure);
// One step of `integrator` from `start`: its answers are the accelerations at the start, the
// step's "ok", and the state after.
ProbeRun oneStep(const std::string& probe, const WorldFile& start, Integrator integrator);

// A probe run that did not answer everything: Fail, saying what it was doing.
CheckResult crashed(const std::string& check, const ProbeRun& run, const std::string& when);

// The agreement's reference for a world (checkagreement.cpp): this project's positions every
// kCheckpointSteps steps, and at each the tolerance: 100 times the spread of the runs whose
// initial positions are nudged one ulp up and down, at least 1e-9 m RMS. `judged`: the last
// checkpoint whose tolerance is at most 1e-6 m (0 when none is), where the world is judged.
struct AgreementReference {
  std::vector<State> checkpoints;
  std::vector<double> tolerance;  // m RMS
  std::size_t judged = 0;
  std::string diverged;  // when this project's own run diverged
};
constexpr long kCheckpointSteps = 100;
AgreementReference agreementReference(const WorldFile& world);

// The checks, one function each (checks.cpp dispatches by name).
CheckResult checkRest(const std::string& probe);
CheckResult checkSprings(const std::string& probe, const std::string& kind);
CheckResult checkDampers(const std::string& probe);
CheckResult checkWalls(const std::string& probe);
CheckResult checkPlane(const std::string& probe);
CheckResult checkField(const std::string& probe, const GradingSetup& setup);
CheckResult checkEuler(const std::string& probe);
CheckResult checkRk4(const std::string& probe);
CheckResult checkAgreement(const std::string& probe, const GradingSetup& setup);
CheckResult checkRobust(const std::string& probe, const GradingSetup& setup);
CheckResult checkSpeed(const std::string& probe, const GradingSetup& setup);

}  // namespace jello::grader
