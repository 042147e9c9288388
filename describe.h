// describe.h: what a world is, in words a user reads (createWorld --describe), and the
// recognition of the course's force fields.
#pragma once

#include <string>

#include "vec3.h"
#include "world.h"

namespace jello {

// The position (m) of field node (i,j,k) along one axis for resolution r >= 2.
double fieldNodeCoordinate(int index, int resolution);

enum class FieldKind { Zero, Uniform, Swirl, Radial, General };
const char* fieldKindName(FieldKind kind);

// What a force field is: zero, uniform F, swirl F = s (-y, x, 0), radial F = s (x, y, z), or
// general, recognised to within the six-decimal rounding of the course's files.
struct FieldShape {
  FieldKind kind = FieldKind::Zero;
  Vec3 uniform;          // N, for Uniform
  double strength = 0;   // N/m, for Swirl and Radial
  double smallest = 0, largest = 0;  // |F| over the nodes, N
};
FieldShape classifyField(const ForceField& field);

// Axis-aligned bounds and centroid of the positions of a state (m).
struct Extent {
  Vec3 lower, upper, centroid;
};
Extent extentOf(const State& state);

// Several lines: the parameters, the field's kind and magnitude range, the cube's bounding box
// and velocities, the plane and which side of it the cube is on.
std::string describeWorld(const World& world, const State& state);

}  // namespace jello
