// analysis/contacts.cpp: the points' friction states (contacts.h).

#include "analysis/contacts.h"

#include "model/scenespec.h"

namespace jello {

std::vector<FrictionState> frictionStates(const Model& model, const State& state) {
  const int n = model.points();
  std::vector<FrictionState> out(n, FrictionState::None);
  const SceneSpec* spec = model.world.scene.get();
  if (!spec) return out;
  std::vector<const Obstacle*> obstacles;
  for (const Obstacle& o : spec->obstacles) obstacles.push_back(&o);
  if (spec->boundsPresent && spec->bounds) obstacles.push_back(&*spec->bounds);
  for (int q = 0; q < n; ++q) {
    const Vec3 p = load(state.p(), q, n), v = load(state.v(), q, n);
    for (const Obstacle* o : obstacles) out[q] = strongerState(out[q], frictionState(*o, p, v));
  }
  return out;
}

}  // namespace jello
