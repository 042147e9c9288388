// checkfield.cpp: the force field, isolated as the difference between the same positions in
// the field and in a zero field of the same resolution; compared with this project's
// interpolation (model/field.h).
#include <cmath>
#include <random>

#include "grader/checkkit.h"
#include "solver/physics.h"

namespace jello::grader {
namespace {

constexpr int kFieldResolution = 7;
constexpr double kNearField = 1e-5;  // of the field's largest force: a rounded constant, near

// A field whose nodes all differ, so that a wrong node order or cell shows.
ForceField unevenField(int resolution) {
  ForceField field;
  field.resolution = resolution;
  std::mt19937_64 random(20261123);
  std::uniform_real_distribution<double> value(-0.5, 0.5);
  field.forces.resize(3 * static_cast<std::size_t>(resolution * resolution * resolution));
  for (double& f : field.forces) f = value(random);
  return field;
}

// The field with its node order turned around (k outer, i inner): what reading it that way gives.
ForceField transposed(const ForceField& field) {
  ForceField turned = field;
  int R = field.resolution;
  for (int i = 0; i < R; ++i)
    for (int j = 0; j < R; ++j)
      for (int k = 0; k < R; ++k)
        turned.setNode((i * R + j) * R + k, field.node((k * R + j) * R + i));
  return turned;
}

// Where the field check puts the 512 points: spread through the box; in the cells at the walls
// (each point within 2 cm of a wall, one in five within 2 cm of two, none on a wall: the course's
// worlds have points there); exactly on the walls (the box's faces: no course world puts a
// point exactly there, so outside the course's domain).
enum class Spread { Inside, NearWalls, OnWalls };
State scattered(Spread spread) {
  std::mt19937_64 random(spread == Spread::Inside ? 11 : 7);
  std::uniform_real_distribution<double> inside(-1.97, 1.97), depth(1e-6, 0.02);
  State state;
  for (int q = 0; q < kNumPoints; ++q) {
    double c[3] = {inside(random), inside(random), inside(random)};
    if (spread != Spread::Inside) {
      double off = spread == Spread::OnWalls ? 0.0 : depth(random);
      c[q % 3] = q % 2 ? 2.0 - off : -2.0 + off;
      if (q % 5 == 0) c[(q + 1) % 3] = 2.0 - (spread == Spread::OnWalls ? 0.0 : depth(random));
    }
    store(state.p(), q, {c[0], c[1], c[2]});
  }
  return state;
}

// This project's field forces (N) at the positions.
std::vector<double> fieldForces(const ForceField& field, const State& state) {
  World world;
  world.field = field;
  Model model = makeModel(world, state);
  std::vector<double> force(kNumCoords);
  computeForces(model, state.p(), state.v(), force.data());
  return force;
}

// The largest difference (N) between the submission's field forces and `expected`, and where.
double worstDifference(const std::vector<double>& with, const std::vector<double>& without,
                       const std::vector<double>& expected, int* where) {
  double worst = 0;
  for (int q = 0; q < kNumPoints; ++q) {
    double miss = length(forceChange(with, without, q) - load(expected.data(), q));
    if (std::isnan(miss)) miss = INFINITY;  // a NaN at any point is the worst, never skipped
    if (!(miss <= worst)) {
      worst = miss;
      *where = q;
    }
  }
  return worst;
}

// The field of `field` against a zero field at `state`: "" when right, else why.
std::string probeField(const std::string& probe, const ForceField& field, const State& state,
                       const std::string& where, bool tryTransposed, bool* nearly = nullptr) {
  World world = probeWorld(), zero = probeWorld();
  world.field = field;
  zero.field.resolution = field.resolution;
  zero.field.forces.assign(field.forces.size(), 0.0);
  Script script;
  script.world(world, probeRun(), state);
  script.accelerations();
  script.world(zero, probeRun(), state);
  script.accelerations();
  ProbeRun run = runProbe(probe, script);
  if (!run.complete()) return run.failure + " " + where;
  if (!allUsable(run.answers[0]) || !allUsable(run.answers[1]))
    return "NaN or infinity in the accelerations " + where;
  std::vector<double> expected = fieldForces(field, state);
  int q = 0;
  double worst = worstDifference(run.answers[0], run.answers[1], expected, &q);
  double scale = largest(field.forces);
  if (worst <= 1e-9 * scale) return "";
  // Off by a rounding of a constant (a node's place computed in float): right in kind.
  if (nearly && worst <= kNearField * scale) {
    *nearly = true;
    return textf(
        "%s: the field force at %s is off by %.3g N, %.2g of the field's largest: right "
        "but for a constant rounded (a node's place in float?)",
        where.c_str(), pointName(q).c_str(), worst, worst / scale);
  }
  if (tryTransposed) {
    int ignored = 0;
    if (worstDifference(run.answers[0], run.answers[1], fieldForces(transposed(field), state),
                        &ignored) <= 1e-9 * scale) {
      return "the field's nodes are read in the wrong order: node (i,j,k) is forceField[i*R*R + "
             "j*R + k], i outer and k inner";
    }
  }
  Vec3 e = load(expected.data(), q);
  return textf(
             "%s: the field force at %s is off by %.3g N (expected (%.6g, %.6g, %.6g) N, "
             "trilinear in its cell)",
             where.c_str(), pointName(q).c_str(), worst, e.x, e.y, e.z) +
         massHint(length(forceChange(run.answers[0], run.answers[1], q)), length(e));
}

}  // namespace

CheckResult checkField(const std::string& probe, const GradingSetup& setup) {
  ForceField field = unevenField(kFieldResolution);
  bool nearly = false;
  std::string why =
      probeField(probe, field, scattered(Spread::Inside), "inside the box", true, &nearly);
  if (why.empty() || nearly) {
    bool walls = false;
    std::string atWalls =
        probeField(probe, field, scattered(Spread::NearWalls),
                   "near the walls (in the last cells, within 2 cm of a wall)", false, &walls);
    if (!atWalls.empty() && (why.empty() || !walls)) {
      why = atWalls;
      nearly = walls;
    }
  }
  CheckResult result = why.empty()
                           ? passed("field", "trilinear, node order, the cells at the walls")
                       : nearly ? near("field", why)
                                : failed("field", why);
  // Beyond the course's worlds (R = 30, points never exactly on a wall): notes, or --strict.
  std::string onWalls =
      probeField(probe, field, scattered(Spread::OnWalls), "exactly on the walls", false);
  if (!onWalls.empty()) addOutsideDomain(result, onWalls, setup);
  ForceField uniform;
  uniform.resolution = 1;
  uniform.forces = {0.3, -0.2, 0.1};
  std::string one = probeField(probe, uniform, scattered(Spread::Inside),
                               "with R = 1 (one uniform force)", false);
  if (!one.empty())
    addOutsideDomain(result,
                     one +
                         " (the course's spacing 4/(R-1) divides by zero there; physics.md: "
                         "the single node's force everywhere in the box)",
                     setup);
  // R = 0, a world without a field (createWorld's default): not a course world either.
  ForceField none;
  Script script;
  World world = probeWorld();
  world.field = none;
  script.world(world, probeRun(), scattered(Spread::Inside));
  script.accelerations();
  ProbeRun run = runProbe(probe, script);
  if (!run.complete() || !allUsable(run.answers[0])) {
    addOutsideDomain(result,
                     "a world without a field (R = 0) " +
                         (run.complete() ? std::string("gives NaN") : run.failure) +
                         ": worlds made without a field cannot run",
                     setup);
  }
  return result;
}

}  // namespace jello::grader
