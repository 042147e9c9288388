// physics.cpp (the course's file): the acceleration of the jello, declared in solver/physics.h:
// the force kernel that sums a model's terms (model/model.h) a range of points at a time, the
// derivative of a state, the divergence test, and the jello as the integrators' ODE system. The
// terms themselves are in model/, the integrators in solver/integrators.cpp.

#include "solver/physics.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/assert.h"
#include "core/limits.h"
#include "core/threadpool.h"
#include "solver/integrators.h"
#include "solver/jacobian.h"

namespace jello {

namespace {

// This thread's 3 n doubles for the point terms' sum, grown once.
double* pointSumsOf(int n) {
  thread_local std::vector<double> grown;
  if (grown.size() < std::size_t(3 * n)) grown.resize(3 * n);
  return grown.data();
}

}  // namespace

// The pair terms add into the total; the point terms in reach add into their own sum first,
// which then joins the total (one term alone adds directly: x + (0 + y) is x + y). This is the
// order docs/physics.md gives the terms in, so every kernel rounds alike, and every range of
// points gets the forces the whole pass gives it.
void computeForcesOn(const Model& model, PointRange points, const double* p, const double* v,
                     const Bounds* reach, double* force, const Pull* pull,
                     const double* springForce, double* pointSums) {
  const int n = model.points();
  // A range begins on a multiple of kRangeAlignment (model/term.h) and lies within the body.
  JELLO_ASSERT(points.begin % kRangeAlignment == 0);
  JELLO_ASSERT(0 <= points.begin && points.begin <= points.end && points.end <= n);
  JELLO_ASSERT(!pull || pull->point < n);
  for (int a = 0; a < 3; ++a)
    std::fill(force + a * n + points.begin, force + a * n + points.end, 0.0);
  const ForceTerm* inReach[kMaxTerms];
  int count = 0;
  for (const auto& term : model.forces.terms) {
    if (springForce && term.get() == model.forces.springs)
      model.forces.springs->addListedForces(points, springForce, force);
    else if (term->isPairTerm())
      term->addForcesOn(points, p, v, reach, force);
    else if (!reach || term->mayReach(*reach))
      inReach[count++] = term.get();
  }
  if (count == 1) {
    inReach[0]->addForcesOn(points, p, v, reach, force);
  } else if (count > 1) {
    // The course cube's sum fits on the stack; a larger body's is the threads' shared one, or this
    // thread's own.
    alignas(64) double onStack[kNumCoords];
    double* sum = pointSums ? pointSums : 3 * n > kNumCoords ? pointSumsOf(n) : onStack;
    for (int a = 0; a < 3; ++a)
      std::fill(sum + a * n + points.begin, sum + a * n + points.end, 0.0);
    for (int t = 0; t < count; ++t) inReach[t]->addForcesOn(points, p, v, reach, sum);
    for (int a = 0; a < 3; ++a)
      for (int q = a * n + points.begin; q < a * n + points.end; ++q) force[q] += sum[q];
  }
  if (pull && pull->point >= points.begin && pull->point < points.end)
    store(force, pull->point, n,
          load(force, pull->point, n) + pullForce(*pull, load(p, pull->point, n)));
}

namespace {

// With several threads, a spring list's forces are computed a spring at a time, an equal share of
// the springs each, before the points' ranges gather them (each spring once, where a range alone
// computes the springs of its points, each at both ends). Into this thread's buffer, grown once.
// Null for the row and grid kernels, whose ranges compute their own.
const double* listedSpringForces(const Model& model, const double* p, const double* v,
                                 const Workers& workers) {
  const SpringTerm& springs = *model.forces.springs;
  if (!springs.listKernel() || springs.springs().empty()) return nullptr;
  thread_local std::vector<double> buffer;
  const long long count = static_cast<long long>(springs.springs().size());
  if (buffer.size() < std::size_t(3 * count)) buffer.resize(3 * count);
  double* out = buffer.data();
  const int parts = workers.threads();
  workers.pool->run(parts, [&](int part) {
    springs.listSpringForces(static_cast<int>(count * part / parts),
                             static_cast<int>(count * (part + 1) / parts), p, v, out);
  });
  return out;
}

// dp/dt and dv/dt = F/mass on the points of `points`.
void derivativeOn(const Model& model, PointRange points, const double* y, const Bounds* reach,
                  double* dydt, const Pull* pull, const double* springForce, double* pointSums) {
  const int n = model.points();
  const double* p = y;
  const double* v = y + 3 * n;
  double* a = dydt + 3 * n;
  computeForcesOn(model, points, p, v, reach, a, pull, springForce, pointSums);
  JELLO_ASSERT(model.pointMass.size() == std::size_t(n));
  for (int axis = 0; axis < 3; ++axis) {
    const int first = axis * n + points.begin, end = axis * n + points.end;
    std::copy(v + first, v + end, dydt + first);
    if (model.commonMass > 0) {  // one mass for every point: a division by one number
      const double mass = model.commonMass;
      for (int c = first; c < end; ++c) a[c] /= mass;
    } else {
      const double* mass = model.pointMass.data();
      double* along = a + axis * n;
      for (int q = points.begin; q < points.end; ++q) along[q] /= mass[q];
    }
  }
  // A pinned point neither moves nor accelerates: every integrator keeps it exactly where it is.
  for (int q : model.pinned)
    if (q >= points.begin && q < points.end)
      for (int axis = 0; axis < 3; ++axis)
        dydt[coordIndex(q, axis, n)] = a[coordIndex(q, axis, n)] = 0;
}

}  // namespace

int threadsFor(const Model& model, int most) {
  const int n = model.points();
  if (n < kFewestPointsShared || most <= 1) return 1;
  return std::min(most, std::max(2, n / kPointsPerThread));
}

Workers workersFor(const Model& model, ThreadPool* pool, bool bySize) {
  Workers workers{pool, {}};
  const int n = model.points();
  int threads = pool ? std::min(pool->threads(), kMostThreads) : 1;
  if (bySize) threads = threadsFor(model, threads);
  if (threads <= 1) return workers;
  // Each point costs its springs' slots and one more for the other terms, and each range after the
  // first the slots it computes again (w): the first range costs E = (total + (T - 1) w) / T, the
  // others E - w; ranges on multiples of kRangeAlignment.
  const SpringTerm& springs = *model.forces.springs;
  const int groups = (n + kRangeAlignment - 1) / kRangeAlignment;
  std::vector<long long> before(groups + 1, 0);  // the cost of the groups of points before
  for (int group = 0; group < groups; ++group) {
    const PointRange r{group * kRangeAlignment, std::min(n, (group + 1) * kRangeAlignment)};
    // A range computes a unit of the grid once, though two groups share it (a voxel body's units
    // straddle groups where its vector is narrower than a group): the group's cost after the
    // point before it, as a range running through both counts it.
    const long long cost = r.begin == 0 ? springs.costOf(r)
                                        : springs.costOf({r.begin - 1, r.end}) -
                                              springs.costOf({r.begin - 1, r.begin});
    before[group + 1] = before[group] + cost + (r.end - r.begin);
  }
  const long long again = springs.warmUpCost();
  const long long first = (before.back() + (threads - 1) * again) / threads;
  int begin = 0;
  for (int t = 1; t <= threads; ++t) {
    const long long share = t * first - (t - 1) * again;
    int group =
        static_cast<int>(std::lower_bound(before.begin(), before.end(), share) - before.begin());
    const int end = t == threads ? n : std::min(n, group * kRangeAlignment);
    if (end > begin) workers.parts.push_back({begin, end});
    begin = std::max(begin, end);
  }
  return workers;
}

namespace {

// The bounds of the positions p, a range a thread, put together.
Bounds boundsOnThreads(const double* p, int n, const Workers& workers) {
  Bounds part[kMostThreads];
  JELLO_ASSERT(workers.threads() <= kMostThreads);
  workers.pool->run(workers.threads(), [&](int t) { part[t] = boundsOf(p, n, workers.parts[t]); });
  Bounds all = part[0];
  for (int t = 1; t < workers.threads(); ++t) {
    const Bounds& b = part[t];
    all.lower = {std::min(all.lower.x, b.lower.x), std::min(all.lower.y, b.lower.y),
                 std::min(all.lower.z, b.lower.z)};
    all.upper = {std::max(all.upper.x, b.upper.x), std::max(all.upper.y, b.upper.y),
                 std::max(all.upper.z, b.upper.z)};
  }
  return all;
}

}  // namespace

void computeForces(const Model& model, const double* p, const double* v, double* force,
                   const Pull* pull, const Workers* workers) {
  if (!workers || workers->threads() == 1) {
    const Bounds box = model.forces.culling ? boundsOf(p, model.points()) : Bounds{};
    computeForcesOn(model, {0, model.points()}, p, v, model.forces.culling ? &box : nullptr, force,
                    pull);
    return;
  }
  const Bounds box = model.forces.culling ? boundsOnThreads(p, model.points(), *workers) : Bounds{};
  const Bounds* reach = model.forces.culling ? &box : nullptr;
  const double* springForce = listedSpringForces(model, p, v, *workers);
  double* sums = pointSumsOf(model.points());
  workers->pool->run(workers->threads(), [&](int part) {
    computeForcesOn(model, workers->parts[part], p, v, reach, force, pull, springForce, sums);
  });
}

void derivative(const Model& model, const double* y, double* dydt, const Pull* pull,
                const Workers* workers) {
  if (!workers || workers->threads() == 1) {
    const Bounds box = model.forces.culling ? boundsOf(y, model.points()) : Bounds{};
    derivativeOn(model, {0, model.points()}, y, model.forces.culling ? &box : nullptr, dydt, pull,
                 nullptr, nullptr);
    return;
  }
  const Bounds box = model.forces.culling ? boundsOnThreads(y, model.points(), *workers) : Bounds{};
  const Bounds* reach = model.forces.culling ? &box : nullptr;
  const double* springForce = listedSpringForces(model, y, y + model.coords(), *workers);
  double* sums = pointSumsOf(model.points());
  workers->pool->run(workers->threads(), [&](int part) {
    derivativeOn(model, workers->parts[part], y, reach, dydt, pull, springForce, sums);
  });
}

int findDivergedPoint(const State& state) {
  const double* p = state.p();
  const double* v = state.v();
  const int n = state.points();
  for (int q = 0; q < n; ++q) {
    Vec3 pq = load(p, q, n), vq = load(v, q, n);
    bool finite = std::isfinite(pq.x) && std::isfinite(pq.y) && std::isfinite(pq.z) &&
                  std::isfinite(vq.x) && std::isfinite(vq.y) && std::isfinite(vq.z);
    if (!finite || dot(pq, pq) > kDivergenceRadius * kDivergenceRadius) return q;
  }
  return -1;
}

OdeSystem jelloSystem(const JelloInputs& inputs) {
  OdeSystem system;
  system.derivative = [&inputs](const double* y, double* dydt) {
    derivative(*inputs.model, y, dydt, inputs.pull, inputs.workers);
  };
  system.newtonMatrix = [&inputs](const double* y, double cv, double cp, NewtonBlocks& matrix) {
    newtonBlocks(*inputs.model, y, y + inputs.model->coords(), inputs.pull, cv, cp, &matrix);
  };
  // The integrators' element-wise loops on the same threads, in ranges of whole cache lines.
  if (inputs.workers && inputs.workers->threads() > 1)
    system.inRanges = [&inputs](std::size_t n, const RangeBody& body) {
      const Workers& workers = *inputs.workers;
      const std::size_t parts = workers.threads();
      auto edge = [&](std::size_t part) { return part == parts ? n : n * part / parts / 8 * 8; };
      workers.pool->run(static_cast<int>(parts),
                        [&](int part) { body.call(body.context, edge(part), edge(part + 1)); });
    };
  return system;
}

void Stepper::step(const Model& model, State& state, double dt, const Pull* pull,
                   const Workers* workers) {
  JELLO_ASSERT(state.points() == model.points());
  const JelloInputs inputs{&model, pull, workers};
  step(jelloSystem(inputs), state.y, dt);
}

}  // namespace jello
