// stability.h: the largest stable step of every integrator for a world, predicted from the
// linearised forces (jello --check, the runtime guard's message, createWorld --describe).
//
// The accelerations are linearised at a state: dA/dp (N/m per kg, i.e. 1/s^2) and dA/dv (1/s).
// The symmetric part of dA/dp is diagonalised; each mode i has a frequency omega_i
// (dA/dp phi = -omega^2 phi) and a damping rate c_i = -phi^T dA/dv phi, so that it moves as
// x'' = -omega^2 x - c x'. An integrator is stable at dt when the one-step map of every such
// mode, computed by running the integrator itself on it, has spectral radius at most 1.
//
// Of a general state the modes at both ends of the spectrum are found (Lanczos iterations,
// spectrum.h): the fastest set every limit of the course and stress worlds but explicit Euler's,
// whose limit is about c / omega^2 for each mode, and the slowest set that one at a wall or in a
// collapsed cube. A mode in the middle of the spectrum damped less for its speed than all of
// those (a strained corner's, the cube's on deep contact springs) is looked for from the points
// whose own stiffness is damped least for its size (a short Lanczos run from there, then a
// shift-invert window where its Ritz pairs promise a lower Euler limit). A state the lattice's
// mirrors leave as it is (a compressed cube) has every mode found, from the mirror blocks. Every
// limit is then within 2% of the dense analysis's of every mode on the course and stress worlds
// (tests/test_stability_limits.cpp).
#pragma once

#include <string>
#include <vector>

#include "core/outcome.h"
#include "model/world.h"
#include "solver/physics.h"

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
  // Oscillating modes (omega > 0): the fastest (24, more when they end in a cluster), the 24
  // slowest and those of the windows inside the spectrum of a state (linearise), every one of
  // the rest lattice (lineariseAtRest) and of a state the mirrors leave as it is.
  std::vector<Mode> modes;
  bool allModes = false;  // whether `modes` holds every oscillating mode
  // Modes with negative stiffness (buckling): physical, not numerical. All of them, counted by
  // the inertia of a factorisation, not only those in `modes`.
  int growing = 0;
  double highestFrequency = 0;                   // rad/s
  double lowestDamping = 0, highestDamping = 0;  // 1/s, over `modes`
};

// The modes of the world linearised at `state` (its springs, and the collision springs active
// there): every one when the lattice's mirrors leave the state as it is (the 8 mirror blocks,
// about 0.1 s); otherwise those at both ends of the spectrum and those inside it that may set
// explicit Euler's limit (see above). Takes about 0.2-0.3 s then: Lanczos iterations on the
// sparse 1536 x 1536 stiffness, one of them on its factorisation, and one more factorisation
// where a window inside the spectrum opens; a dense eigensolver (seconds) only when an iteration
// does not converge.
Linearisation linearise(const Model& model, const State& state);

// The modes of the rest body (restState) for the world's springs. For the course cube, all of
// them: at rest every spring's stiffness and damping act along the same direction, so the damping
// is the stiffness times dElastic/kElastic and one eigenvalue solve of the lattice, done once and
// scaled, gives them: tens of milliseconds the first time (the lattice's mirror symmetries split
// it into 8 blocks, spectrum.h), microseconds after. With pins, another body or springs whose
// kinds differ: its springs and pins at rest through linearise().
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

// The body at rest (point (i,j,k) at spacing * (i,j,k)), and the same with its x = min face
// pressed 1 mm into the wall x = -2 (64 collision springs active for the course cube).
State restState(const Body& body);
State faceOnWallState(const Body& body);

// The verdict's margin. The limits are those of small motions about a fixed state; a cube's own
// large motion modulates its springs' stiffness, and a fast mode with little damping can be
// pumped by that modulation (parametric resonance) at steps the frozen analysis calls stable:
// undamped rotate.w with its corner pulled out by 0.17 or 0.35 m diverges under SYMPLECTIC at
// 0.91 or 0.82 of the predicted limit, stretched by 30% at 0.58 of it, while the highest
// frequency along those motions stays within 1% of the prediction's. So a step is called
// stable below kStableFraction of the limit, and, for a cube whose fast modes are lightly
// damped and which starts deformed, only below kLargeMotionStableFraction of it; above that it
// is marginal.
constexpr double kStableFraction = 0.8;
constexpr double kLargeMotionStableFraction = 0.5;
// Lightly damped: the fastest mode at rest loses less than this fraction of its amplitude per
// radian (damping rate / frequency). Deformed: some spring strained by more than kDeformed.
constexpr double kLightDamping = 0.02;
constexpr double kDeformed = 0.01;

// The largest |length - rest| / rest over the springs at `state`.
double largestStrain(const Body& body, const State& state);
// kLargeMotionStableFraction for a lightly damped world starting deformed, kStableFraction
// otherwise (for the course cube a lattice eigensolve the first time, then microseconds; for
// another body its modes at rest: `rest` when the caller has them, else computed).
double stableFraction(const World& world, const State& initial,
                      const Linearisation* rest = nullptr);

struct StabilityReport {
  // beyondDoubles of the world: when it is not empty, nothing else was analysed and the vectors
  // below are empty.
  std::string beyond;
  Linearisation rest, initial;
  std::vector<double> criticalRest, criticalInitial, criticalFaceOnWall;  // by kExplicitIntegrators
  double largestStrain = 0;                                               // at the initial state
  // Whether the course's walls hold the jelly (a scene may have none, or a box of its own):
  // criticalFaceOnWall is NaN where not.
  bool courseWalls = true;
  double stableFraction = kStableFraction;  // of verdictLimit, see above
  // The headline limit: at rest, the state every damped world settles towards (a deformed start
  // or a contact may lower it for a while: see criticalInitial, criticalFaceOnWall). Infinite
  // for IMPLICIT.
  double critical(Integrator integrator) const;
  // The limit the verdict compares the world's dt with: the smaller of those at rest and at the
  // initial state.
  double verdictLimit(Integrator integrator) const;
};

// The whole analysis of a world (about 0.3 s; the two states' on two threads).
StabilityReport analyseStability(const World& world, const State& initial);

enum class Verdict { Stable, NearLimit, Unstable };
// Stable below `stableFraction` of the limit, NearLimit (marginal) from there to the limit,
// Unstable beyond it.
Verdict verdictFor(double dt, double critical, double stableFraction = kStableFraction);
// "stable", "marginal" or "unstable".
const char* verdictName(Verdict verdict);

// The human report of jello --check, and its JSON.
std::string stabilityText(const std::string& worldPath, const World& world,
                          const StabilityReport& report);
std::string stabilityJson(const std::string& worldPath, const World& world,
                          const StabilityReport& report);

// The limit that matters when a run has diverged: the smaller of the limits at the initial
// state and with a face on a wall (two linearisations, about 0.3 s). NaN when the forces'
// derivatives there are not finite (no analysis is run then).
double predictedLimit(const World& world, const State& initial, Integrator integrator);

// The one-line diagnosis of a diverged run, without the "jello: " prefix: where, why, and
// what to change, e.g. "diverged at step 812 (t=0.0812 s): <reason>; dt=1e-4 exceeds RK4's
// stable limit 6.6e-5 for this world; try --dt 5e-5 or --integrator IMPLICIT". A body of more
// points than the course cube is not analysed (that takes seconds to minutes): its advice comes
// from a step bounded by the row sums of its stiffness and damping, in a second at 48^3.
std::string divergenceMessage(const World& world, const State& initial, long long step, double time,
                              const std::string& reason);

// The largest dt at which real runs of `time` seconds from `start` stay plausible (the checks of
// every Simulation, simulation.h), by bisection to 0.5% between a third and three times `guess`;
// NaN when the limit is not in that range, or when runs at guess / 3 would take more than
// kMaxSteps.
double observedLimit(const Model& model, const State& start, Integrator integrator, double time,
                     double guess);

// jello --check --map DIR: kElastic swept against dt, the predicted and the observed (real
// runs of `time` seconds, by bisection) largest stable step per integrator; writes
// DIR/stability-map.csv, .gp and .png, and says how it went (outcome.h).
Outcome writeStabilityMap(const std::string& dir, const std::string& worldPath, const World& world,
                          const State& initial, double time, bool overwrite);

// A predicted limit in words, "%.3g" of it: criticalStep's 0 is "below 8.67e-19" (not zero),
// NaN "none (not finite)".
std::string limitText(double limit);

// A step to suggest: `stableFraction` of the predicted limit, rounded down to 1, 2 or 5 times a
// power of 10.
double suggestedStep(double critical, double stableFraction = kStableFraction);
// "try --dt 5e-05 or --integrator IMPLICIT" for a limit, or, when suggestedStep would give a step
// --dt refuses or a double cannot hold normally (0, subnormal), why no step will do.
std::string stepAdvice(double critical, double stableFraction = kStableFraction);

}  // namespace jello
