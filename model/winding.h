// model/winding.h: whether a point is inside a body's closed surface, by its winding number: the
// solid angles of the surface's triangles seen from the point, summed, over 4 pi (Van Oosterom and
// Strackee's formula for a triangle's). About +1 inside a closed surface wound counter-clockwise
// from outside, 0 outside, whatever the surface's shape; meaningless for an open sheet.
//
// Units: metres.
#pragma once

#include "model/body.h"
#include "model/vec3.h"

namespace jello {

// The winding number about x of part `part`'s surface (the whole surface of a body that is not
// joined, part 0), its points at positions p (a per-point array of the body's).
double windingNumber(const Body& body, int part, const double* p, Vec3 x);

}  // namespace jello
