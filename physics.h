// physics.h: the forces of the jello model (SPEC.md section 2) and the derivative of a state.
//
// Units: metres, seconds, kilograms, newtons. Sign convention: every force term returns the
// force ON the point it is asked about (for a spring, on its end `a`; its end `b` gets minus
// that). L always points from the anchor (the other end, or the contact point) to the point.
// This file links no GL.
#pragma once

#include <cstdint>
#include <vector>

#include "vec3.h"
#include "world.h"

namespace jello {

enum class SpringKind : std::uint8_t { Structural, Shear, Bend };

// One row of the table the spring list is built from: every lattice point (i,j,k) whose
// neighbour (i+di, j+dj, k+dk) exists is joined to it by a spring of rest length |offset|/7.
struct SpringOffset {
  int di, dj, dk;
  SpringKind kind;
};
extern const std::vector<SpringOffset> kSpringOffsets;  // 16 rows, 6220 springs

struct Spring {
  int a, b;     // point indices, see pointIndex()
  double rest;  // m, from the ideal lattice
  SpringKind kind;
};

// Springs grouped by offset, in the order of kSpringOffsets.
std::vector<Spring> buildSprings();

// A world ready to simulate: its parameters and what is derived from them once.
struct Model {
  World world;
  std::vector<Spring> springs;
  // +1 or -1: the sign of a*x + b*y + c*z + d on the allowed side of the inclined plane, the
  // side holding the centroid of the initial positions (+1 when the centroid is on the plane).
  double planeSide = 1;
};
Model makeModel(const World& world, const State& initial);

// Returns L/|L| and writes |L|; a zero vector gives a zero direction. The one place where
// zero-length vectors are dealt with: every force term built on it exerts no force along a
// direction it cannot define.
Vec3 direction(Vec3 L, double* len);

// Damped spring of rest length `rest` between a and b: L = p_a - p_b, relVel = v_a - v_b.
// F_a = -k (|L| - rest) u - d (relVel . u) u; zero when |L| = 0.
Vec3 springForce(Vec3 L, Vec3 relVel, double k, double d, double rest);
// Collision spring of rest length 0 from a fixed contact point c to the point: L = p - c.
// F = -k L - d (v . u) u.
Vec3 collisionForce(Vec3 L, Vec3 v, double k, double d);
// Sum of the collision springs of the walls of [-2,2]^3 the point is strictly beyond.
Vec3 wallForce(Vec3 p, Vec3 v, double k, double d);
// Collision spring to the projection on the plane when the point is strictly on the side of
// sign -side (side = Model::planeSide).
Vec3 planeForce(const Plane& plane, double side, Vec3 p, Vec3 v, double k, double d);
// How many points of `state` are strictly on the far side of the model's plane (0 without one).
int pointsAcrossPlane(const Model& model, const State& state);
// The force field at p: trilinear inside the box (walls included), zero outside.
Vec3 fieldForce(const ForceField& field, Vec3 p);

// A user's pull on one point (the viewer's left-drag): a spring of rest length 0 from the point
// to a target the user moves. point < 0: no pull.
struct Pull {
  int point = -1;
  Vec3 target;           // m
  double stiffness = 0;  // N/m
};
// F = stiffness (target - p) on the pulled point.
Vec3 pullForce(const Pull& pull, Vec3 p);

// Total force on every point (kNumCoords doubles, xyz-interleaved) for positions p and
// velocities v, with the user's pull when there is one.
void computeForces(const Model& model, const double* p, const double* v, double* force,
                   const Pull* pull = nullptr);

// The derivative of a state y = [p; v] (2*kNumCoords doubles): dp/dt = v, dv/dt = F/mass.
void derivative(const Model& model, const double* y, double* dydt, const Pull* pull = nullptr);

constexpr double kDivergenceRadius = 100.0;  // m: a point further from the origin has diverged

// Index of the first point with a non-finite coordinate or velocity, or further than
// kDivergenceRadius from the origin; -1 when the state is sane.
int findDivergedPoint(const State& state);

}  // namespace jello
