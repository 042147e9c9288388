// describe.cpp: a world in words.

#include "app/describe.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "analysis/stability.h"
#include "solver/physics.h"

namespace jello {

namespace {

std::string vec(Vec3 v) { return textf("(%.6g, %.6g, %.6g)", v.x, v.y, v.z); }

}  // namespace

Extent extentOf(const State& state) {
  Extent e;
  const int n = state.points();
  e.lower = e.upper = load(state.p(), 0, n);
  for (int q = 0; q < n; ++q) {
    Vec3 p = load(state.p(), q, n);
    e.lower = {std::min(e.lower.x, p.x), std::min(e.lower.y, p.y), std::min(e.lower.z, p.z)};
    e.upper = {std::max(e.upper.x, p.x), std::max(e.upper.y, p.y), std::max(e.upper.z, p.z)};
    e.centroid += p;
  }
  e.centroid = (1.0 / n) * e.centroid;
  return e;
}

namespace {
// Every term the world has (the general scene, which computes each in full), then what it
// does not have.
std::string termLines(const World& w, const State& state) {
  std::string out;
  const Model general = makeModel(w, state, KernelChoice::General);
  for (const auto& term : general.forces.terms)
    for (const TermLine& line : term->describe(state.p()))
      out += textf("%-11s %s\n", line.label.c_str(), line.text.c_str());
  const std::vector<std::string> left = summarise(general.forces).leftOut;
  if (!left.empty()) out += "left out    " + listText(left) + "\n";
  return out;
}
}  // namespace

std::string describeWorld(const WorldFile& file) {
  const World& w = file.world;
  const RunSettings& run = file.run;
  const State& state = file.state;
  std::string out;
  out += textf("integrator  %s, dt %.9g s, n %d (a drawn frame every %.9g s)\n",
               integratorName(run.integrator), run.dt, run.n, run.dt * run.n);
  out += textf("mass        %.9g kg a point, %.9g kg in all\n", w.mass, w.mass * state.points());
  out += termLines(w, state);
  Extent e = extentOf(state);
  out += "cube        from " + vec(e.lower) + " to " + vec(e.upper) + " m, centroid " +
         vec(e.centroid) + " m\n";
  Vec3 meanVelocity;
  double fastest = 0;
  const int n = state.points();
  for (int q = 0; q < n; ++q) {
    Vec3 v = load(state.v(), q, n);
    meanVelocity += v;
    fastest = std::max(fastest, length(v));
  }
  meanVelocity = (1.0 / n) * meanVelocity;
  out += "velocity    mean " + vec(meanVelocity) + textf(" m/s, fastest point %.6g m/s\n", fastest);
  if (std::string beyond = beyondDoubles(w, state); !beyond.empty()) {
    out += "stability   beyond what double arithmetic can simulate: " + beyond + "\n";
    return out;
  }
  // The verdict of jello --check: the limit at rest or at the initial state, the smaller.
  const StabilityReport report = analyseStability(w, state);
  const double limit = report.verdictLimit(run.integrator);
  if (std::isfinite(limit)) {
    out += textf("stability   %s dt %.9g: %s (%.0f%% of its limit %.3g s%s; see jello --check)\n",
                 integratorName(run.integrator), run.dt,
                 verdictName(verdictFor(run.dt, limit, report.stableFraction)),
                 100 * run.dt / limit, limit,
                 limit < report.critical(run.integrator) ? " at the initial state" : " at rest");
  } else {
    out += textf("stability   %s: no step limit\n", integratorName(run.integrator));
  }
  return out;
}

}  // namespace jello
