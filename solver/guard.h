// guard.h: the runtime guard against a diverging simulation: a cheap check, every drawn
// frame, that the state is still one the world's forces could have produced.
#pragma once

#include <string>

#include "solver/physics.h"

namespace jello {

// Kinetic energy plus the energy every term of the scene stores (the springs, the collision
// springs of walls and plane), joules. Without a force field it never grows: springs are
// conservative, dampers dissipate.
double mechanicalEnergy(const Model& model, const State& state);

// A term that stores no energy for its force (the field) can add energy at a rate of at most
// Fmax * sum |v| <= Fmax * sqrt(2 N E / m), Fmax its largest force, so
// sqrt(E(t)) <= sqrt(E(0)) + Fmax sqrt(N / (2 m)) t. A state beyond a generous multiple of that
// bound, with a non-finite coordinate, or a point more than 100 m from the origin, has
// diverged: no physics of this world produces it.
class DivergenceGuard {
 public:
  DivergenceGuard(const Model& model, const State& initial);
  // Starts the bound afresh from `state` at `time` (after the user pulled the cube, say).
  void restart(const State& state, double time);
  // "" while the state is plausible; otherwise what is wrong, in a few words.
  std::string check(const State& state, double time) const;

 private:
  const Model* model_;  // a pointer, so that a simulation's change() can make a new guard
  double rootEnergy_ = 0, energyRate_ = 0, start_ = 0;
};

}  // namespace jello
