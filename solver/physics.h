// solver/physics.h: the acceleration of the jello (docs/physics.md), defined by the course's
// physics.cpp at the root: the force kernel that sums a model's terms, the derivative of a state,
// the divergence test, and the jello as the ODE system the integrators step (integrators.h).
//
// Units: metres, seconds, kilograms, newtons. Sign convention: every force term returns the
// force ON the point it is asked about (model/term.h).
#pragma once

#include "model/model.h"
#include "model/world.h"
#include "solver/integrators.h"

namespace jello {

class Team;  // core/team.h

// The force kernel: total force on every point (per-point arrays, see coordIndex) for
// positions p and velocities v, with the user's pull when there is one: the model's terms,
// each skipped when the positions are out of its reach. With a team, its two threads take a
// range of points each (balancedSplitPoint), with the same result bit for bit.
void computeForces(const Model& model, const double* p, const double* v, double* force,
                   const Pull* pull = nullptr, Team* team = nullptr);

// The same on the points of `points` alone (force elsewhere is left as it was), with `reach` the
// bounds of all the positions when the scene culls (null when it does not): what computeForces
// does, a range at a time, bit for bit.
// springForce: the spring list's forces a spring at a time (SpringTerm::listSpringForces), to
// gather rather than compute; null to compute them.
void computeForcesOn(const Model& model, PointRange points, const double* p, const double* v,
                     const Bounds* reach, double* force, const Pull* pull,
                     const double* springForce = nullptr);

// The derivative of a state y = [p; v] (2 * model.coords() doubles): dp/dt = v, dv/dt = F/mass.
// With a team, its two threads take half the points each (balancedSplitPoint for the course
// cube's row kernel, halves of a spring list's points), with the same result.
void derivative(const Model& model, const double* y, double* dydt, const Pull* pull = nullptr,
                Team* team = nullptr);

constexpr double kDivergenceRadius = 100.0;  // m: a point further from the origin has diverged

// Index of the first point with a non-finite coordinate or velocity, or further than
// kDivergenceRadius from the origin; -1 when the state is sane.
int findDivergedPoint(const State& state);

// What the jello's system is made of: the model, the user's pull if any, and the team whose two
// threads share each derivative (derivative, above) if any.
struct JelloInputs {
  const Model* model;
  const Pull* pull = nullptr;
  Team* team = nullptr;
};
// The jello's system: derivative() and newtonMatrix() of `inputs`, which it references:
// they must outlive it. (One reference fits std::function's own storage: a step allocates
// nothing.)
OdeSystem jelloSystem(const JelloInputs& inputs);

}  // namespace jello
