// model/world.h: the parameters of a jello world and its state (docs/world-format.md says how a
// .w file writes them; io/input.h reads and writes them).
//
// Units: metres, seconds, kilograms, newtons. Stiffness in N/m, damping in N s/m.
// Lattice index (i,j,k) maps to axes (x,y,z); point (i,j,k) is point number
// pointIndex(i,j,k) = i*64 + j*8 + k, in the file's order.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/limits.h"
#include "model/integrator.h"
#include "model/vec3.h"

namespace jello {

constexpr int kLatticeSize = 8;                                         // points per cube edge
constexpr int kNumPoints = kLatticeSize * kLatticeSize * kLatticeSize;  // 512
constexpr int kNumCoords = 3 * kNumPoints;                              // 1536 doubles per array
constexpr double kRestSpacing = 1.0 / (kLatticeSize - 1);               // 1/7 m between neighbours
constexpr double kBoxHalfSize = 2.0;                                    // bounding box [-2,2]^3

constexpr int pointIndex(int i, int j, int k) { return (i * kLatticeSize + j) * kLatticeSize + k; }

// A per-point array (positions, velocities, forces) of a body of `points` points (body.h; the
// course cube's are kNumPoints) holds 3 * points doubles, structure of arrays: all x, then all y,
// then all z,
// each in point order. Coordinate `axis` (0 x, 1 y, 2 z) of point q is element
// coordIndex(q, axis, points). The force kernel's loops then run over contiguous, equally spaced
// doubles and vectorise.
constexpr int coordIndex(int q, int axis, int points) { return axis * points + q; }
inline Vec3 load(const double* a, int q, int points) {
  return {a[q], a[points + q], a[2 * points + q]};
}
inline void store(double* a, int q, int points, Vec3 value) {
  a[q] = value.x;
  a[points + q] = value.y;
  a[2 * points + q] = value.z;
}
// The same on the course cube's arrays (kNumPoints points): the course's files, the grader.
constexpr int coordIndex(int q, int axis) { return coordIndex(q, axis, kNumPoints); }
inline Vec3 load(const double* a, int q) { return load(a, q, kNumPoints); }
inline void store(double* a, int q, Vec3 value) { store(a, q, kNumPoints, value); }

// "[i][j][k]" for point q, as in the course's p[i][j][k].
std::string latticeLabel(int q);

// The plane a*x + b*y + c*z + d = 0, (a,b,c) != 0.
struct Plane {
  double a = 0, b = 0, c = 0, d = 0;
};
// Whether (a,b,c) != 0: the one rule every plane keeps (the world reader, createWorld --plane, the
// checks of a world in memory, the plane term).
inline bool hasNormal(const Plane& plane) { return plane.a != 0 || plane.b != 0 || plane.c != 0; }

// Forces (newtons) on an R^3 grid spanning the box. Node (i,j,k) sits at
// (-2 + 4i/(R-1), -2 + 4j/(R-1), -2 + 4k/(R-1)); its force is forces[3*(i*R*R + j*R + k) + axis].
// R = 0: no field. R = 1: one uniform force inside the box.
// The nodes' forces stay interleaved (xyz per node): interpolation reads whole nodes.
struct ForceField {
  int resolution = 0;
  std::vector<double> forces;
  Vec3 node(std::size_t i) const { return {forces[3 * i], forces[3 * i + 1], forces[3 * i + 2]}; }
  void setNode(std::size_t i, Vec3 f) {
    forces[3 * i] = f.x;
    forces[3 * i + 1] = f.y;
    forces[3 * i + 2] = f.z;
  }
};

struct SceneSpec;  // model/scenespec.h

// How a world is run: its integrator, its step and the steps per drawn frame. A world file or a
// scene file says them, and the command line may override them (solver/run.h); a run passes them
// to its Simulation, which holds them (solver/simulation.h). They are not physics: a World, and
// the Model made of it, hold none of them.
struct RunSettings {
  Integrator integrator = Integrator::RK4;
  double dt = 0.001;  // s, > 0
  int n = 1;          // steps per drawn frame, >= 1
};

// The physics a world file fixes: everything but its run settings and its state. Read once, never
// changed by a run.
struct World {
  double kElastic = 0, dElastic = 0, kCollision = 0, dCollision = 0;  // >= 0
  double mass = 1.0 / kNumPoints;                                     // kg per point, > 0
  bool hasPlane = false;
  Plane plane;
  ForceField field;
  // What a scene file adds (gravity, obstacles, pins, the bounding box); null for a course world.
  // Shared, never changed once read.
  std::shared_ptr<const SceneSpec> scene;
};

// Positions (m) and velocities (m/s) of a body's points (512 for the course cube), each a
// per-point array of 3n doubles (see coordIndex): y[0 .. 3n) positions, y[3n .. 6n) velocities.
// One contiguous array so that integrators copy and combine whole states cheaply.
struct State {
  State() : State(kNumPoints) {}
  explicit State(int points) : y(6 * std::size_t(points), 0.0) {}
  std::vector<double> y;
  int points() const { return static_cast<int>(y.size() / 6); }
  int coords() const { return static_cast<int>(y.size() / 2); }
  double* p() { return y.data(); }
  double* v() { return y.data() + coords(); }
  const double* p() const { return y.data(); }
  const double* v() const { return y.data() + coords(); }
};

}  // namespace jello
