// describe.h: what a world is, in words a user reads (createWorld --describe). The recognition
// of the course's force fields is the field term's (model/field.h).
#pragma once

#include <string>

#include "io/input.h"
#include "model/field.h"
#include "model/vec3.h"
#include "model/world.h"

namespace jello {

// Axis-aligned bounds and centroid of the positions of a state (m).
struct Extent {
  Vec3 lower, upper, centroid;
};
Extent extentOf(const State& state);

// Several lines: the integrator and mass, a line or more from each force term of the world (its
// parameters; the field's kind and magnitude range; the plane and which side of it the cube is
// on), what the kernel leaves out, the cube's bounding box and velocities, and its stability.
std::string describeWorld(const WorldFile& file);

}  // namespace jello
