// analysis/stabilitymap.h: jello --check --map, the predicted and the observed stable steps
// against kElastic.
#pragma once

#include <string>

#include "core/outcome.h"
#include "io/input.h"
#include "model/world.h"

namespace jello {

// jello --check --map DIR: kElastic swept against dt, the predicted and the observed (real
// runs of `time` seconds, by bisection) largest stable step per integrator; writes
// DIR/stability-map.csv, .gp and .png, and says how it went (outcome.h).
Outcome writeStabilityMap(const std::string& dir, const std::string& worldPath,
                          const WorldFile& file, double time, bool overwrite);

}  // namespace jello
