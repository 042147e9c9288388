// model/contact.h: the collision spring every obstacle (walls, plane) pushes back with.
//
// Units: metres, seconds, newtons; k in N/m, d in N s/m. L points from the contact point (the
// point's projection on the obstacle) to the point; the force is ON the point.
#pragma once

#include "model/term.h"
#include "model/vec3.h"

namespace jello {

// The collision spring's constants, one pair for every obstacle of a world (the world file's
// kCollision and dCollision). An obstacle's term keeps a copy and asks the functions below for
// the force and its derivatives, so that a change to how contacts push (friction, say) is made
// here once.
struct ContactSpring {
  double k = 0;  // N/m
  double d = 0;  // N s/m
};

// Collision spring of rest length 0 from a fixed contact point c to the point: L = p - c.
// F = -k L - d (v . u) u; zero when L is.
inline Vec3 collisionForce(Vec3 L, Vec3 v, double k, double d) {
  double len;
  Vec3 u = direction(L, &len);
  return -k * L + (-d * dot(v, u)) * u;
}
inline Vec3 contactForce(const ContactSpring& spring, Vec3 L, Vec3 v) {
  return collisionForce(L, v, spring.k, spring.d);
}

// Adds the derivatives of contactForce for a contact along a fixed normal n (L = (s/|n|^2) n, s
// the point's signed distance times |n|): -k n n^T / |n|^2 with respect to the position, and
// -d n n^T / |n|^2 with respect to the velocity.
inline void addContactJacobian(const ContactSpring& spring, Vec3 normal, Block3* dFdp,
                               Block3* dFdv) {
  const double n[3] = {normal.x, normal.y, normal.z};
  const double norm2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double nn = n[i] * n[j] / norm2;
      dFdp->m[3 * i + j] += -spring.k * nn;
      dFdv->m[3 * i + j] += -spring.d * nn;
    }
}

}  // namespace jello
