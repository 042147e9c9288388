// analysis/stabilitytext.cpp: jello --check's report, as text and as JSON (stability.h).

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "analysis/stability.h"
#include "core/output.h"
#include "core/plot.h"
#include "core/progress.h"
#include "model/scenespec.h"
#include "solver/guard.h"
#include "solver/integrators.h"
#include "solver/simulation.h"

namespace jello {

namespace {

// --check's table: a line per integrator of the integrator table, its limits or "unbounded".
std::string limitTable(const StabilityReport& r) {
  std::string out =
      "\n  integrator   largest stable dt (s)   at the initial state   with a face on a wall\n";
  char line[256];
  for (std::size_t i = 0; i < kExplicitIntegrators.size(); ++i) {
    std::snprintf(line, sizeof line, "  %-12s %-23s %-22s %s\n",
                  integratorName(kExplicitIntegrators[i]), limitText(r.criticalRest[i]).c_str(),
                  limitText(r.criticalInitial[i]).c_str(),
                  r.courseWalls ? limitText(r.criticalFaceOnWall[i]).c_str() : "(no course walls)");
    out += line;
  }
  for (const IntegratorInfo& row : integratorTable()) {
    if (row.boundedStableStep) continue;
    std::snprintf(line, sizeof line, "  %-12s unbounded (A-stable)\n", row.name());
    out += line;
  }
  return out + "\n";
}

// Why a step below the limit is only marginal (see kStableFraction).
std::string marginalNote(const StabilityReport& r) {
  char text[400];
  if (r.stableFraction < kStableFraction) {
    std::snprintf(
        text, sizeof text,
        "  marginal: the cube starts deformed (a spring strained by %.0f%%) and its fast modes are "
        "nearly undamped, so its large motion can pump them at steps the limits call stable (runs "
        "diverged at 0.58 of the limit for a cube stretched by 30%%); below %.0f%% of the limit a "
        "step is called stable\n",
        100 * r.largestStrain, 100 * r.stableFraction);
  } else {
    std::snprintf(
        text, sizeof text,
        "  marginal: within %.0f%% of the limit, which holds for small motions about the state "
        "analysed; a large motion can lower the real one (an undamped cube with a corner pulled "
        "out by 0.35 m diverged at 0.82 of it)\n",
        100 * (1 - r.stableFraction));
  }
  return text;
}
}  // namespace

namespace {

// --check's lines on the modes: at rest, at the initial state, and those that grow.
std::string modesText(const StabilityReport& r) {
  std::string out;
  char line[256];
  // The count only where every mode was found (not only the spectrum's ends)
  const std::string count =
      r.rest.allModes ? " " + std::to_string(r.rest.modes.size()) + " oscillating modes," : "";
  std::snprintf(line, sizeof line,
                "  at rest:%s highest frequency %.4g rad/s (%.4g Hz), damping rates %.3g to %.3g "
                "1/s\n",
                count.c_str(), r.rest.highestFrequency, r.rest.highestFrequency / (2 * kPi),
                r.rest.lowestDamping, r.rest.highestDamping);
  out += line;
  std::snprintf(
      line, sizeof line,
      "  at the initial state: highest frequency %.4g rad/s, damping rates %.3g to %.3g 1/s\n",
      r.initial.highestFrequency, r.initial.lowestDamping, r.initial.highestDamping);
  out +=
      r.initial.finite
          ? line
          : "  at the initial state: the forces' derivatives are not finite numbers (beyond double "
            "arithmetic): no analysis\n";
  if (r.initial.growing) {
    out += "  " + std::to_string(r.initial.growing) +
           " modes of the initial state grow whatever the step (negative stiffness: buckling "
           "springs, a repelling "
           "field): physics, not numerics\n";
  }
  return out;
}

// --check's verdict on the world's own dt, with the note and the advice it calls for.
std::string verdictText(const RunSettings& world, const StabilityReport& r) {
  const double critical = r.verdictLimit(world.integrator);
  // Named when it differs in print from the headline one (the two eigensolves differ in the last
  // bits).
  const char* which = figureText(critical) != figureText(r.critical(world.integrator))
                          ? " at the initial state"
                          : "";
  Verdict verdict = verdictFor(world.dt, critical, r.stableFraction);
  std::string out = "  the world's dt " + figureText(world.dt) + " with " +
                    integratorName(world.integrator) + ": " + verdictName(verdict);
  if (critical == 0) {
    out += " (the limit is " + limitText(critical) + " s)";
  } else if (std::isfinite(critical)) {
    char line[256];
    std::snprintf(line, sizeof line, " (%.0f%% of the limit %s%s)", 100 * world.dt / critical,
                  figureText(critical).c_str(), which);
    out += line;
  }
  out += "\n";
  if (verdict == Verdict::NearLimit) out += marginalNote(r);
  if (verdict != Verdict::Stable && std::isfinite(critical))
    out += "  " + stepAdvice(critical, r.stableFraction) + "\n";
  return out;
}

// --check's warnings when the world's dt is above the limit at the start or against a wall.
std::string otherLimitsText(const RunSettings& world, const StabilityReport& r) {
  std::string out;
  auto at = std::find(kExplicitIntegrators.begin(), kExplicitIntegrators.end(), world.integrator);
  if (at != kExplicitIntegrators.end()) {
    std::size_t i = static_cast<std::size_t>(at - kExplicitIntegrators.begin());
    // Only a limit below the headline one (at rest) says something the verdict has not.
    if (world.dt > r.criticalInitial[i] && r.criticalInitial[i] < r.criticalRest[i]) {
      out += "  at the initial state the limit is " + limitText(r.criticalInitial[i]) +
             " s: the start's deformation may destabilise this step for a while\n";
    }
    if (world.dt > r.criticalFaceOnWall[i] && r.criticalFaceOnWall[i] < r.criticalRest[i]) {
      out += "  while a face presses on a wall the limit is " + limitText(r.criticalFaceOnWall[i]) +
             " s: contact may destabilise this step\n";
    }
  }
  return out;
}

}  // namespace

std::string stabilityText(const std::string& worldPath, const RunSettings& world,
                          const StabilityReport& r) {
  if (!r.beyond.empty()) {
    return worldPath +
           ": the world's numbers are beyond what double arithmetic can simulate: " + r.beyond +
           "\n  its first step overflows, or leaves the guard's 100 m: no practical step of any "
           "integrator will do, and no stability analysis was made\n";
  }
  std::string out =
      worldPath + ": the largest stable step of each integrator, from the linearised forces\n";
  out += modesText(r);
  out += limitTable(r);
  out += verdictText(world, r);
  out += otherLimitsText(world, r);
  return out;
}

std::string stabilityJson(const std::string& worldPath, const RunSettings& world,
                          const StabilityReport& r) {
  nlohmann::json j;
  j["world"] = worldPath;
  j["dt"] = world.dt;
  j["integrator"] = integratorName(world.integrator);
  if (!r.beyond.empty()) {
    j["beyond_double_arithmetic"] = r.beyond;
    j["verdict"] = "beyond double arithmetic";
    j["critical_dt"] = nullptr;
    return j.dump(2) + "\n";
  }
  j["modes"] = r.rest.modes.size();
  j["highest_frequency"] = r.rest.highestFrequency;
  j["damping_rates"] = {r.rest.lowestDamping, r.rest.highestDamping};
  j["initial_state"] = {{"highest_frequency", r.initial.highestFrequency},
                        {"damping_rates", {r.initial.lowestDamping, r.initial.highestDamping}},
                        {"growing_modes", r.initial.growing}};
  auto finite = [](double x) {
    return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
  };
  for (std::size_t i = 0; i < kExplicitIntegrators.size(); ++i) {
    Integrator integrator = kExplicitIntegrators[i];
    j["integrators"][integratorName(integrator)] = {
        {"critical_dt", finite(r.critical(integrator))},
        {"initial_state", finite(r.criticalInitial[i])},
        {"face_on_wall", finite(r.criticalFaceOnWall[i])}};
  }
  for (const IntegratorInfo& row : integratorTable())
    if (!row.boundedStableStep)
      j["integrators"][row.name()] = {{"critical_dt", nullptr}, {"unbounded", true}};
  double critical = r.critical(world.integrator), verdictLimit = r.verdictLimit(world.integrator);
  j["verdict"] = verdictName(verdictFor(world.dt, verdictLimit, r.stableFraction));
  j["critical_dt"] = finite(critical);
  j["verdict_limit_dt"] =
      finite(verdictLimit);  // the smaller of the limits at rest and at the start
  j["stable_below_dt"] = finite(r.stableFraction * verdictLimit);
  return j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

}  // namespace jello
