// forces/contact.h: the collision spring every obstacle (walls, plane) pushes back with.
//
// Units: metres, seconds, newtons; k in N/m, d in N s/m. L points from the contact point (the
// point's projection on the obstacle) to the point; the force is ON the point.
#pragma once

#include "vec3.h"

namespace jello {

// Collision spring of rest length 0 from a fixed contact point c to the point: L = p - c.
// F = -k L - d (v . u) u; zero when L is.
inline Vec3 collisionForce(Vec3 L, Vec3 v, double k, double d) {
  double len;
  Vec3 u = direction(L, &len);
  return -k * L + (-d * dot(v, u)) * u;
}

}  // namespace jello
