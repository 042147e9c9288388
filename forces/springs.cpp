// forces/springs.cpp: the lattice's springs: the table, the kernel's groups, force, Jacobian,
// energy and description.

#include "forces/springs.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace jello {

const std::vector<SpringOffset> kSpringOffsets = {
    // structural
    {1, 0, 0, SpringKind::Structural},
    {0, 1, 0, SpringKind::Structural},
    {0, 0, 1, SpringKind::Structural},
    // face shear
    {1, 1, 0, SpringKind::Shear},
    {1, -1, 0, SpringKind::Shear},
    {1, 0, 1, SpringKind::Shear},
    {1, 0, -1, SpringKind::Shear},
    {0, 1, 1, SpringKind::Shear},
    {0, 1, -1, SpringKind::Shear},
    // body shear
    {1, 1, 1, SpringKind::Shear},
    {1, 1, -1, SpringKind::Shear},
    {1, -1, 1, SpringKind::Shear},
    {1, -1, -1, SpringKind::Shear},
    // bend
    {2, 0, 0, SpringKind::Bend},
    {0, 2, 0, SpringKind::Bend},
    {0, 0, 2, SpringKind::Bend},
};

std::vector<SpringGroup> buildSpringGroups() {
  std::vector<SpringGroup> groups;
  auto inside = [](int c) { return c >= 0 && c < kLatticeSize; };
  for (const SpringOffset& o : kSpringOffsets) {
    SpringGroup g;
    g.kind = o.kind;
    g.delta = pointIndex(o.di, o.dj, o.dk);
    g.rest = kRestSpacing * std::sqrt(double(o.di * o.di + o.dj * o.dj + o.dk * o.dk));
    g.mask.assign(kNumPoints, 0.0);
    for (int i = 0; i < kLatticeSize; ++i)
      for (int j = 0; j < kLatticeSize; ++j) {
        if (!inside(i + o.di) || !inside(j + o.dj)) continue;
        const int rowBegin = pointIndex(i, j, 0), rowEnd = rowBegin + kLatticeSize;
        if (!g.spans.empty() && g.spans.back().end == rowBegin)
          g.spans.back().end = rowEnd;
        else
          g.spans.push_back({rowBegin, rowEnd});
        for (int k = 0; k < kLatticeSize; ++k)
          if (inside(k + o.dk)) g.mask[pointIndex(i, j, k)] = 1.0;
      }
    // The last row's discarded slots would reach past the last point: they end the last span.
    g.spans.back().end = std::min(g.spans.back().end, kNumPoints - g.delta);
    groups.push_back(std::move(g));
  }
  return groups;
}

namespace {
// The same table walk as the kernel's: the springs are the groups' slots that are kept.
std::vector<Spring> springsOf(const std::vector<SpringGroup>& groups) {
  std::vector<Spring> springs;
  for (const SpringGroup& g : groups)
    for (const SpringGroup::Span& span : g.spans)
      for (int q = span.begin; q < span.end; ++q)
        if (g.mask[q] != 0) springs.push_back({q, q + g.delta, g.rest, g.kind});
  return springs;
}
}  // namespace

std::vector<Spring> buildSprings() { return springsOf(buildSpringGroups()); }

void springJacobian(Vec3 L, Vec3 relVel, double k, double d, double rest, Block3* dFdL,
                    Block3* dFdw) {
  double len;
  const Vec3 unit = direction(L, &len);
  *dFdL = Block3{};
  *dFdw = Block3{};
  if (len == 0) return;
  const double u[3] = {unit.x, unit.y, unit.z}, w[3] = {relVel.x, relVel.y, relVel.z};
  double uu[9], P[9], Pw[3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      uu[3 * i + j] = u[i] * u[j];
      P[3 * i + j] = (i == j ? 1.0 : 0.0) - uu[3 * i + j];
    }
  // P w summed as this Jacobian was summed when Eigen computed it (its SSE2 product adds rows 0
  // and 1 left to right, row 2 right to left), so that IMPLICIT's results stay bit for bit.
  for (int i = 0; i < 2; ++i) Pw[i] = (P[3 * i] * w[0] + P[3 * i + 1] * w[1]) + P[3 * i + 2] * w[2];
  Pw[2] = P[6] * w[0] + (P[7] * w[1] + P[8] * w[2]);
  const double uw = u[0] * w[0] + u[1] * w[1] + u[2] * w[2];
  const double bend = 1 - rest / len, damping = d / len;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int e = 3 * i + j;
      dFdL->m[e] = -k * (uu[e] + bend * P[e]) - damping * (u[i] * Pw[j] + uw * P[e]);
      dFdw->m[e] = -d * uu[e];
    }
}

namespace {

// The springs of one group: the forces of all slots first (loops the compiler vectorises),
// then one pass over the points adding each point's two springs of the group, the one that
// ends at it (q - delta to q) before the one that starts at it: the order in which a loop over
// single springs adds them, so the sums round the same way. f holds zeros before slot 0 and
// outside the spans, so that both reads are plain loads.
constexpr int kMaxDelta = 2 * kLatticeSize * kLatticeSize;  // the bend spring along i
template <bool kDampers>
void addSpringGroup(const SpringGroup& g, double k, double d, const double* __restrict p,
                    const double* __restrict v, double* __restrict force) {
  const double* __restrict mask = g.mask.data();
  alignas(64) double buffer[3][kMaxDelta + kNumPoints];
  const double *px = p, *py = p + kNumPoints, *pz = p + 2 * kNumPoints;
  const double *vx = v, *vy = v + kNumPoints, *vz = v + 2 * kNumPoints;
  const int b = g.delta;
  int written = -b;  // buffer slots before this one are set
  for (const SpringGroup::Span& span : g.spans) {
    for (double* f : buffer) std::fill(f + kMaxDelta + written, f + kMaxDelta + span.begin, 0.0);
    written = span.end;
    for (int q = span.begin; q < span.end; ++q) {
      double len;
      Vec3 u = direction({px[q] - px[q + b], py[q] - py[q + b], pz[q] - pz[q + b]}, &len);
      double tension = springTension(len, k, g.rest);
      if constexpr (kDampers)
        tension += damperTension({vx[q] - vx[q + b], vy[q] - vy[q + b], vz[q] - vz[q + b]}, u, d);
      Vec3 fq = (mask[q] * tension) * u;
      buffer[0][kMaxDelta + q] = fq.x;
      buffer[1][kMaxDelta + q] = fq.y;
      buffer[2][kMaxDelta + q] = fq.z;
    }
  }
  for (int axis = 0; axis < 3; ++axis) {
    double* __restrict out = force + axis * kNumPoints;
    double* f = buffer[axis] + kMaxDelta;
    std::fill(f + written, f + kNumPoints, 0.0);
    for (int q = 0; q < kNumPoints; ++q) out[q] = (out[q] - f[q - b]) + f[q];
  }
}

}  // namespace

SpringTerm::SpringTerm(double k, double d, bool dampers)
    : k_(k), d_(d), dampers_(dampers), groups_(buildSpringGroups()), springs_(springsOf(groups_)) {}

std::vector<std::pair<int, int>> SpringTerm::pairs() const {
  std::vector<std::pair<int, int>> out;
  out.reserve(springs_.size());
  for (const Spring& s : springs_) out.emplace_back(s.a, s.b);
  return out;
}

void SpringTerm::addForces(const double* p, const double* v, const Bounds*, double* force) const {
  for (const SpringGroup& g : groups_) {
    if (dampers_)
      addSpringGroup<true>(g, k_, d_, p, v, force);
    else
      addSpringGroup<false>(g, k_, d_, p, v, force);
  }
}

void SpringTerm::addJacobian(const double* p, const double* v, JacobianSink* sink) const {
  Block3 dFdL, dFdw;
  for (const Spring& s : springs_) {
    springJacobian(load(p, s.a) - load(p, s.b), load(v, s.a) - load(v, s.b), k_, d_, s.rest, &dFdL,
                   &dFdw);
    sink->addPair(dFdL, dFdw);
  }
}

void SpringTerm::addEnergy(const double* p, double* energy) const {
  for (const Spring& s : springs_) {
    double stretch = length(load(p, s.a) - load(p, s.b)) - s.rest;
    *energy += 0.5 * k_ * stretch * stretch;
  }
}

void SpringTerm::summarise(std::vector<std::string>* kept,
                           std::vector<std::string>* leftOut) const {
  kept->push_back("springs");
  if (dampers_)
    kept->push_back("dampers");
  else
    leftOut->push_back("dampers (zero damping)");
}

std::vector<TermLine> SpringTerm::describe(const double*) const {
  return {{"springs",
           textf("kElastic %.9g N/m, dElastic %.9g N s/m (%zu springs: structural, shear, bend)",
                 k_, d_, springs_.size())}};
}

}  // namespace jello
