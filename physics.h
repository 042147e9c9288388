// physics.h: the forces of the jello model (SPEC.md section 2) and the derivative of a state.
//
// Units: metres, seconds, kilograms, newtons. Sign convention: every force term returns the
// force ON the point it is asked about (for a spring, on its end `a`; its end `b` gets minus
// that). L always points from the anchor (the other end, or the contact point) to the point.
// This file links no GL.
#pragma once

#include <cstdint>
#include <string>
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


// The springs of one row of kSpringOffsets, for the force kernel: point q is joined to point
// q + delta for every q in the spans where mask[q] is 1. A span is a run of whole lattice rows
// (fixed i and j) whose neighbours' rows exist; inside a row, a neighbour beyond the last k
// has mask 0: the kernel computes that slot and discards it, which keeps its loops regular
// (6,826 slots for 6,220 springs).
struct SpringGroup {
  struct Span {
    int begin, end;  // point indices, end exclusive
  };
  int delta = 0;  // pointIndex(di, dj, dk), > 0 for every row of the table
  double rest = 0;
  SpringKind kind = SpringKind::Structural;
  std::vector<Span> spans;
  std::vector<double> mask;  // kNumPoints entries, 1.0 or 0.0
};
std::vector<SpringGroup> buildSpringGroups();
// The springs one by one (6,220), grouped by offset in the order of kSpringOffsets: the
// groups' kept slots.
std::vector<Spring> buildSprings();

// What a world needs of the force computation, decided once when it is loaded (SPEC.md
// section 2 defines every term; leaving one out changes no result).
enum class FieldUse { Absent, Zero, Uniform, Trilinear };
struct Scene {
  bool dampers = true;  // the springs' dampers (dElastic != 0)
  bool plane = true;    // an inclined plane exists
  FieldUse field = FieldUse::Trilinear;
  Vec3 uniformForce;  // N, for FieldUse::Uniform
};
// The scene of a world, its field as fieldUse says.
Scene analyseScene(const World& world);
// Absent at resolution 0, Zero when every node is exactly zero, Uniform when every node is
// exactly the same force (node 0's), Trilinear otherwise.
FieldUse fieldUse(const ForceField& field);
// "scene: kept: ...; left out: ...", naming every term of the force.
std::string sceneLine(const Scene& scene, const World& world);

// Total force on every point (per-point arrays, see coordIndex) for positions p and velocities
// v, with the user's pull when there is one.
struct Model;
struct Pull;
using ForceKernel = void (*)(const Model& model, const double* p, const double* v, double* force, const Pull* pull);

// Which instantiation of the force kernel a model uses: the one made for its scene, or the one
// that computes every term (the reference the specialisations are tested and timed against).
enum class KernelChoice { Specialised, General };

// A world ready to simulate: its parameters and what is derived from them once.
struct Model {
  World world;
  std::vector<Spring> springs;
  std::vector<SpringGroup> groups;
  Scene scene;
  ForceKernel kernel = nullptr;
  // A trilinear field's nodes, 4 doubles each (x, y, z, 0): the kernel's copy, for aligned
  // vector arithmetic.
  std::vector<double> paddedField;
  // The world's inclined plane as the forces use it: normalisedPlane(world.plane).
  Plane plane;
  // +1 or -1: the sign of a*x + b*y + c*z + d on the allowed side of the inclined plane, the
  // side holding the centroid of the initial positions (+1 when the centroid is on the plane).
  double planeSide = 1;
};
Model makeModel(const World& world, const State& initial, KernelChoice choice = KernelChoice::Specialised);

// The same plane scaled by a power of two, so that its largest normal component lies in
// [0.5, 1): the squared normal of a plane such as (1e-300, 0, 0, 0) or (1e200, 1e200, 1e200,
// -1.5e200) neither underflows nor overflows. Scaling by a power of two is exact, so every
// force of an ordinary plane stays bit for bit what the unscaled plane gives. A normal
// component far smaller than the largest (by more than 2^1022) may round to zero: its effect
// on the plane was below double's resolution anyway. d is not finite when the plane is beyond
// the range of doubles (see planeProblem).
Plane normalisedPlane(const Plane& plane);
// Why the plane cannot be simulated, "" when it can: its normal is zero, or its normalised d
// is not finite (the plane lies further from the origin than about 1e308 m).
std::string planeProblem(const Plane& plane);
// a*x + b*y + c*z + d at p: the one place it is computed (positive on the normal's side).
inline double planeValue(const Plane& plane, Vec3 p) {
  return dot(Vec3{plane.a, plane.b, plane.c}, p) + plane.d;
}

// Returns L/|L| and writes |L|; a zero vector gives a zero direction. The one place where
// zero-length vectors are dealt with: every force term built on it exerts no force along a
// direction it cannot define. (A select, not a branch, so that the spring loop vectorises.)
inline Vec3 direction(Vec3 L, double* len) {
  *len = length(L);
  const double inverse = *len != 0 ? 1.0 / *len : 0.0;
  return inverse * L;
}

// Spring and damper, as magnitudes along u = L/|L| (positive pushes a away from b).
inline double springTension(double len, double k, double rest) { return -k * (len - rest); }
inline double damperTension(Vec3 relVel, Vec3 u, double d) { return -d * dot(relVel, u); }

// Damped spring of rest length `rest` between a and b: L = p_a - p_b, relVel = v_a - v_b.
// F_a = -k (|L| - rest) u - d (relVel . u) u; zero when |L| = 0.
inline Vec3 springForce(Vec3 L, Vec3 relVel, double k, double d, double rest) {
  double len;
  Vec3 u = direction(L, &len);
  return (springTension(len, k, rest) + damperTension(relVel, u, d)) * u;
}
// Collision spring of rest length 0 from a fixed contact point c to the point: L = p - c.
// F = -k L - d (v . u) u; zero when L is.
inline Vec3 collisionForce(Vec3 L, Vec3 v, double k, double d) {
  double len;
  Vec3 u = direction(L, &len);
  return -k * L + (-d * dot(v, u)) * u;
}
// The collision spring of the wall perpendicular to `axis` (0 x, 1 y, 2 z) that the point is
// strictly beyond, from the point's projection on it; zero when it is beyond neither. Selects,
// not branches, so that the kernel's loop over the points vectorises.
inline Vec3 wallForceAlong(int axis, Vec3 p, Vec3 v, double k, double d) {
  const double c = axis == 0 ? p.x : axis == 1 ? p.y : p.z;
  const double beyond = c > kBoxHalfSize ? c - kBoxHalfSize : c < -kBoxHalfSize ? c + kBoxHalfSize : 0.0;
  const Vec3 L{axis == 0 ? beyond : 0.0, axis == 1 ? beyond : 0.0, axis == 2 ? beyond : 0.0};
  return collisionForce(L, v, k, d);
}
// Sum of the collision springs of the walls of [-2,2]^3 the point is strictly beyond.
Vec3 wallForce(Vec3 p, Vec3 v, double k, double d);
// Collision spring to the projection on the plane when the point is strictly on the side of
// sign -side (side = Model::planeSide). Computed for every point and selected, so that the
// kernel's contact loop has no branch. The model passes its normalised plane (Model::plane),
// whose |n|^2 neither overflows nor underflows.
inline Vec3 planeForce(const Plane& plane, double side, Vec3 p, Vec3 v, double k, double d) {
  Vec3 normal{plane.a, plane.b, plane.c};
  double s = planeValue(plane, p);
  Vec3 L = (s / dot(normal, normal)) * normal;  // p minus its projection p - (s/|n|^2) n
  Vec3 f = collisionForce(L, v, k, d);
  const bool across = s * side < 0;
  return {across ? f.x : 0.0, across ? f.y : 0.0, across ? f.z : 0.0};
}
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

// The model's kernel: total force on every point for positions p and velocities v.
inline void computeForces(const Model& model, const double* p, const double* v, double* force,
                          const Pull* pull = nullptr) {
  model.kernel(model, p, v, force, pull);
}

// The derivative of a state y = [p; v] (2*kNumCoords doubles): dp/dt = v, dv/dt = F/mass.
void derivative(const Model& model, const double* y, double* dydt, const Pull* pull = nullptr);

constexpr double kDivergenceRadius = 100.0;  // m: a point further from the origin has diverged

// Index of the first point with a non-finite coordinate or velocity, or further than
// kDivergenceRadius from the origin; -1 when the state is sane.
int findDivergedPoint(const State& state);

}  // namespace jello
