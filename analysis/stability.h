// analysis/stability.h: the largest stable step of every integrator for a world, predicted from the
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

#include "analysis/modes.h"
#include "analysis/steplimits.h"
#include "core/outcome.h"
#include "model/world.h"
#include "solver/physics.h"

namespace jello {

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
// `run`: the run's integrator and dt, which the verdict judges (the world file's, or the command
// line's overrides).
std::string stabilityText(const std::string& worldPath, const RunSettings& run,
                          const StabilityReport& report);
std::string stabilityJson(const std::string& worldPath, const RunSettings& run,
                          const StabilityReport& report);

// What is said of a start already beyond the divergence guard (findDivergedPoint), by a run's
// diagnosis and by --static alike.
extern const char* const kStartBeyondGuard;

// The one-line diagnosis of a diverged run, without the "jello: " prefix: where, why, and
// what to change, e.g. "diverged at step 812 (t=0.0812 s): <reason>; dt=1e-4 exceeds RK4's
// stable limit 6.6e-5 for this world; try --dt 5e-5 or --integrator IMPLICIT". A body of more
// points than the course cube is not analysed (that takes seconds to minutes): its advice comes
// from a step bounded by the row sums of its stiffness and damping, in a second at 48^3.
// The run's integrator and dt are its own (the world file's, or the command line's overrides).
std::string divergenceMessage(const World& world, const State& initial, Integrator integrator,
                              double dt, long long step, double time, const std::string& reason);

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
