// solver/physics.h: the acceleration of the jello (docs/physics.md), defined by the course's
// physics.cpp at the root: the force kernel that sums a model's terms, the derivative of a state,
// the divergence test, and the jello as the ODE system the integrators step (integrators.h).
//
// Units: metres, seconds, kilograms, newtons. Sign convention: every force term returns the
// force ON the point it is asked about (model/term.h).
#pragma once

#include <vector>

#include "core/limits.h"
#include "model/model.h"
#include "model/world.h"
#include "solver/integrators.h"

namespace jello {

class ThreadPool;  // core/threadpool.h

// How a model's evaluations are shared between threads: the pool, and the ranges of points that
// are its parts (each one a thread's at a time), in order, covering the points. No pool, or one
// part: this thread alone.
struct Workers {
  ThreadPool* pool = nullptr;
  std::vector<PointRange> parts;
  int threads() const { return pool && parts.size() > 1 ? static_cast<int>(parts.size()) : 1; }
};
// A body of fewer points is computed by one thread: two measured slower than one up to 1,000
// points (the course cube 0.93x to 1.00x, 10^3 0.88x) and faster from 1,728 (12^3 1.13x, 16^3
// 1.26x, 24^3 1.56x; docs/performance.md, "Threads").
constexpr int kFewestPointsShared = 1500;
// Beyond two threads, one for each kPointsPerThread points: a range after the first computes again
// the slots of up to two planes before it, which a range of a few planes pays for.
constexpr int kPointsPerThread = 2048;
// The threads a run of `model` shares its evaluations between, given at most `most`: one below
// kFewestPointsShared points, else one for each kPointsPerThread points, at least two.
int threadsFor(const Model& model, int most);
// The workers of `model` with `pool`: as many threads as the pool has, at most threadsFor's
// (bySize; else the pool's threads, for timing each count), each given a range of about equal cost
// (the springs' slots, those a range after the first computes again included, and the points;
// ranges begin on multiples of kRangeAlignment).
Workers workersFor(const Model& model, ThreadPool* pool, bool bySize = true);

// The force kernel: total force on every point (per-point arrays, see coordIndex) for
// positions p and velocities v, with the user's pull when there is one: the model's terms,
// each skipped when the positions are out of its reach. With workers, their threads take a
// range of points each, with the same result bit for bit.
void computeForces(const Model& model, const double* p, const double* v, double* force,
                   const Pull* pull = nullptr, const Workers* workers = nullptr);

// The same on the points of `points` alone (force elsewhere is left as it was), with `reach` the
// bounds of all the positions when the scene culls (null when it does not): what computeForces
// does, a range at a time, bit for bit.
// springForce: the spring list's forces a spring at a time (SpringTerm::listSpringForces), to
// gather rather than compute; null to compute them. pointSums: 3 n doubles where the point terms
// sum (threads share one: their ranges do not overlap); null: this thread's own.
void computeForcesOn(const Model& model, PointRange points, const double* p, const double* v,
                     const Bounds* reach, double* force, const Pull* pull,
                     const double* springForce = nullptr, double* pointSums = nullptr);

// The derivative of a state y = [p; v] (2 * model.coords() doubles): dp/dt = v, dv/dt = F/mass.
// With workers, their threads take a range of points each, with the same result.
void derivative(const Model& model, const double* y, double* dydt, const Pull* pull = nullptr,
                const Workers* workers = nullptr);

// Index of the first point with a non-finite coordinate or velocity, or further than
// kDivergenceRadius from the origin; -1 when the state is sane.
int findDivergedPoint(const State& state);

// What the jello's system is made of: the model, the user's pull if any, and the workers that
// share each derivative (derivative, above) if any.
struct JelloInputs {
  const Model* model;
  const Pull* pull = nullptr;
  const Workers* workers = nullptr;
};
// The jello's system: derivative() and newtonMatrix() of `inputs`, which it references:
// they must outlive it. (One reference fits std::function's own storage: a step allocates
// nothing.)
OdeSystem jelloSystem(const JelloInputs& inputs);

}  // namespace jello
