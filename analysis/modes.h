// analysis/modes.h: the modes of a world linearised at a state, for the stable steps of
// steplimits.h and the verdicts of stability.h (jello --check, the guard's message, createWorld
// --describe).
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

#include <vector>

#include "model/world.h"
#include "solver/physics.h"

namespace jello {

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

// The body at rest (point (i,j,k) at spacing * (i,j,k)), and the same with its x = min face
// pressed 1 mm into the wall x = -2 (64 collision springs active for the course cube).
State restState(const Body& body);
State faceOnWallState(const Body& body);

// The modes of the free course lattice at rest for the world's springs, scaled from the unit
// lattice's, solved once (lineariseAtRest's way for the course cube).
Linearisation freeLatticeAtRest(const World& world);

// A step at which every mode of `state` is stable, bounded from the row sums (Gershgorin) of the
// stiffness and the damping: in a second for a 48^3 lattice instead of the analysis's minutes.
struct RowSumBound {
  double limit;    // s; NaN where the derivatives are not finite, infinite if no point is free
  double fastest;  // rad/s: the square root of the stiffness's top
  // An integrator unstable on an undamped oscillation (EULER, MIDPOINT) is held by the damping
  // alone, of which row sums promise nothing for the slower modes: its bound is then far below its
  // limit (under kUsefulRowSumBound / fastest), and a step suggested from it would be useless.
  static constexpr double kUsefulRowSumBound = 0.01;  // RK4's undamped limit is 2.8 / fastest
  bool useful() const { return !(limit * fastest < kUsefulRowSumBound); }
};
RowSumBound rowSumBound(const Model& model, const State& state, Integrator integrator);

}  // namespace jello
