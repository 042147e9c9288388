// analysis/contacts.h: which points of the jelly touch a scene's frictional obstacles, and whether
// each sticks or slides (the window's friction colouring, README: The viewer). No GL, so that
// the classification is tested as numbers.
#pragma once

#include <vector>

#include "model/obstacle.h"
#include "solver/physics.h"

namespace jello {

// Every point's state against the scene's obstacles and its bounding box (when that is an
// obstacle), the strongest of them (strongerState: sliding anywhere is sliding). All None for a
// course world: its walls and plane have no friction.
std::vector<FrictionState> frictionStates(const Model& model, const State& state);

}  // namespace jello
