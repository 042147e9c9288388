// stability.h: the largest stable step of every integrator for a world, predicted from the
// linearised forces (jello --check, the runtime guard's message, createWorld --describe).
//
// The accelerations are linearised at a state: dA/dp (N/m per kg, i.e. 1/s^2) and dA/dv (1/s).
// The symmetric part of dA/dp is diagonalised; each mode i has a frequency omega_i
// (dA/dp phi = -omega^2 phi) and a damping rate c_i = -phi^T dA/dv phi, so that it moves as
// x'' = -omega^2 x - c x'. An integrator is stable at dt when the one-step map of every such
// mode, computed by running the integrator itself on it, has spectral radius at most 1.
#pragma once

#include <string>
#include <vector>

#include "physics.h"
#include "world.h"

namespace jello {

// Integrators with a bounded stable step, in table order (integratorsWithStepLimit()).
extern const std::vector<Integrator> kExplicitIntegrators;

struct Mode {
  double omegaSquared;  // 1/s^2
  double damping;       // 1/s
};

struct Linearisation {
  // False when the forces' derivatives at the state hold a number that is not finite: no
  // eigen-analysis is run on such a matrix, and there are no modes.
  bool finite = true;
  std::vector<Mode> modes;    // the oscillating ones, omega > 0
  int growing = 0;            // modes with negative stiffness (buckling): physical, not numerical
  double highestFrequency = 0;  // rad/s
  double lowestDamping = 0, highestDamping = 0;  // 1/s, over the modes
};

// The modes of the world linearised at `state` (its springs, and the collision springs active
// there). Takes about a second: a dense symmetric eigensolver on 1536 unknowns.
Linearisation linearise(const Model& model, const State& state);

// The modes of the rest lattice (restState()) for the world's springs. At rest every spring's
// stiffness and damping act along the same direction, so the damping is the stiffness times
// dElastic/kElastic and one eigenvalue solve of the lattice, done once and scaled, gives them:
// milliseconds after the first call.
Linearisation lineariseAtRest(const World& world);

// The largest dt at which `integrator` keeps every mode bounded; +infinity for IMPLICIT; 0 when
// it is below kShortestResolvedStep (a mode faster than about 1e18 rad/s).
double criticalStep(Integrator integrator, const std::vector<Mode>& modes);
// The shortest limit criticalStep resolves: 2^-60 s, 60 halvings of its largest step, 1 s.
constexpr double kShortestResolvedStep = 8.673617379884035e-19;

// Why the world's numbers are beyond what double arithmetic can simulate, "" when they are not:
// a rate per kilogram (kElastic, dElastic, kCollision or dCollision over the mass, or the
// largest field force over it) that is not finite with a factor kHeadroom to spare, or an
// initial velocity whose square is not. Such a world's forces overflow at its first step
// whatever the step; no eigen-analysis is run on it (its matrix would hold inf or NaN, on which
// the eigensolver spends minutes for nothing). Takes microseconds.
std::string beyondDoubles(const World& world, const State& initial);
// The margin beyondDoubles keeps: stretches up to the guard's 200 m times the ~50 springs on a
// point, and the sums of the integrators' stages, stay finite.
constexpr double kHeadroom = 1e6;

// The rest lattice, and the rest lattice with its x = min face pressed 1 mm into the wall
// x = -2 (64 collision springs active), both at rest.
State restState();
State faceOnWallState();

struct StabilityReport {
  // beyondDoubles of the world: when it is not empty, nothing else was analysed and the vectors
  // below are empty.
  std::string beyond;
  Linearisation rest, initial;
  std::vector<double> criticalRest, criticalInitial, criticalFaceOnWall;  // by kExplicitIntegrators
  // The headline limit: at rest, the state every damped world settles towards (a deformed start
  // or a contact may lower it for a while: see criticalInitial, criticalFaceOnWall). Infinite
  // for IMPLICIT.
  double critical(Integrator integrator) const;
};

// The whole analysis of a world (about three seconds).
StabilityReport analyseStability(const World& world, const State& initial);

enum class Verdict { Stable, NearLimit, Unstable };
// Stable below 80% of the limit, NearLimit within 20% of it, Unstable beyond it.
Verdict verdictFor(double dt, double critical);
const char* verdictName(Verdict verdict);

// The human report of jello --check, and its JSON.
std::string stabilityText(const std::string& worldPath, const World& world, const StabilityReport& report);
std::string stabilityJson(const std::string& worldPath, const World& world, const StabilityReport& report);

// The limit that matters when a run has diverged: the smaller of the limits at the initial
// state and with a face on a wall (two eigensolves, a few seconds). NaN when the forces'
// derivatives there are not finite (no analysis is run then).
double predictedLimit(const World& world, const State& initial, Integrator integrator);

// The one-line diagnosis of a diverged run, without the "jello: " prefix: where, why, and
// what to change, e.g. "diverged at step 812 (t=0.0812 s): <reason>; dt=1e-4 exceeds RK4's
// stable limit 6.6e-5 for this world; try --dt 5e-5 or --integrator IMPLICIT".
std::string divergenceMessage(const World& world, const State& initial, long long step, double time,
                              const std::string& reason);

// The largest dt at which real runs of `time` seconds from `start` stay plausible (the checks of
// every Simulation, simulation.h), by bisection to 0.5% between a third and three times `guess`; NaN when
// the limit is not in that range, or when runs at guess / 3 would take more than kMaxSteps.
double observedLimit(const Model& model, const State& start, Integrator integrator, double time, double guess);

// jello --check --map DIR: kElastic swept against dt, the predicted and the observed (real
// runs of `time` seconds, by bisection) largest stable step per integrator; writes
// DIR/stability-map.csv, .gp and .png. Returns the exit status.
int writeStabilityMap(const std::string& dir, const std::string& worldPath, const World& world, const State& initial,
                      double time, bool overwrite);

// A predicted limit in words, "%.3g" of it: criticalStep's 0 is "below 8.67e-19" (not zero),
// NaN "none (not finite)".
std::string limitText(double limit);

// A step to suggest: 80% of the predicted limit, rounded down to 1, 2 or 5 times a power of 10.
double suggestedStep(double critical);
// "try --dt 5e-05 or --integrator IMPLICIT" for a limit, or, when suggestedStep would give a step
// --dt refuses or a double cannot hold normally (0, subnormal), why no step will do.
std::string stepAdvice(double critical);

}  // namespace jello
