// solver/statics.h: a body at rest: the positions where the model's forces balance (every free
// point's force zero, velocities zero), found by Newton's method on the forces with the exact
// stiffness (jacobian.h). It is how a cantilever's sag is measured against beam theory
// (docs/physics.md, "Finite elements") and what `jello --static` prints.
//
// Units: metres, newtons.
#pragma once

#include "model/model.h"

namespace jello {

struct StaticSolution {
  State state;              // the balanced positions, velocities zero
  int steps = 0;            // Newton steps taken
  double largestForce = 0;  // N, on a free point at the end
  bool converged = false;   // the last step moved no point by more than 1e-9 of the spacing
};

// From `start` (its positions; velocities ignored), at most `maxSteps` Newton steps: each solves
// K dx = F with K = -dF/dp (pinned points held), halving the step while it raises the largest
// force (at most 20 times).
StaticSolution solveStatic(const Model& model, const State& start, int maxSteps = 50);

}  // namespace jello
