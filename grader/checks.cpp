// checks.cpp: the check table, dispatch and what the checks share (checkkit.h).
#include "grader/checks.h"

#include <cmath>

#include "grader/checkkit.h"

namespace jello::grader {

const char* gradeName(Grade grade) {
  switch (grade) {
    case Grade::Pass:
      return "pass";
    case Grade::Near:
      return "near";
    case Grade::Fail:
      return "FAIL";
    case Grade::Info:
      return "info";
  }
  return "?";
}

namespace {

// The checks whose function needs more than the probe, or a name.
template <CheckResult (*check)(const std::string&)>
CheckResult probeOnly(const std::string& probe, const GradingSetup&) {
  return check(probe);
}
CheckResult field(const std::string& probe, const GradingSetup& setup) {
  return checkField(probe, setup);
}
CheckResult robust(const std::string& probe, const GradingSetup& setup) {
  return checkRobust(probe, setup);
}
CheckResult structural(const std::string& probe, const GradingSetup&) {
  return checkSprings(probe, "structural");
}
CheckResult shear(const std::string& probe, const GradingSetup&) {
  return checkSprings(probe, "shear");
}
CheckResult bend(const std::string& probe, const GradingSetup&) {
  return checkSprings(probe, "bend");
}

}  // namespace

const std::vector<CheckInfo>& checkTable() {
  static const std::vector<CheckInfo> table = {
      {"builds", "physics.cpp compiles and links with the course API", nullptr},
      {"rest", "zero acceleration at the rest lattice, also moved and turned rigidly",
       probeOnly<checkRest>},
      {"structural", "structural springs: present, rest length 1/7, stiffness kElastic",
       structural},
      {"shear", "shear springs (face and body diagonals): present, rest length, stiffness", shear},
      {"bend", "bend springs: present, rest length 2/7, stiffness", bend},
      {"dampers", "dampers along each spring, dElastic, the right sign", probeOnly<checkDampers>},
      {"walls", "each of the six walls: rest length 0, kCollision, only beyond it, damping",
       probeOnly<checkWalls>},
      {"plane", "the inclined plane: the positive side allowed, rest length 0, damping",
       probeOnly<checkPlane>},
      {"field", "the force field: trilinear, node order, the cells at the walls", field},
      {"euler", "one Euler step is the course's Euler on its own accelerations",
       probeOnly<checkEuler>},
      {"rk4", "one RK4 step is classic RK4 on its own accelerations; order 4", probeOnly<checkRk4>},
      {"agreement", "2000 steps of the course worlds and of unseen worlds against this project",
       checkAgreement},
      {"robust", "no NaN and no crash beyond the course: thrown into a corner, collapsed", robust},
      {"speed", "microseconds per RK4 step (reported, not graded)", checkSpeed},
  };
  return table;
}

bool isCheck(const std::string& name) {
  for (const auto& check : checkTable()) {
    if (name == check.name) return true;
  }
  return false;
}

CheckResult runCheck(const std::string& name, const std::string& probe, const GradingSetup& setup) {
  for (const CheckInfo& check : checkTable())
    if (name == check.name && check.run) return check.run(probe, setup);
  return failed(name, "no such check");
}

CheckResult outsideDomain(const std::string& check, const std::string& line,
                          const GradingSetup& setup) {
  if (setup.strict) return failed(check, line + " (graded: --strict)");
  return info(check, line + " (not asked by the course's worlds: not graded; --strict grades it)");
}

void addOutsideDomain(CheckResult& result, const std::string& line, const GradingSetup& setup) {
  CheckResult finding = outsideDomain(result.check, line, setup);
  if (finding.grade == Grade::Fail && result.grade != Grade::Fail) {
    finding.notes = result.notes;
    result = finding;
  } else {
    result.notes.push_back(finding.diagnosis);
  }
}

RunSettings probeRun() { return {Integrator::RK4, 0.0005, 1}; }

World probeWorld() {
  World world;
  world.kElastic = 300;
  world.dElastic = 0.7;
  world.kCollision = 1100;
  world.dCollision = 1.3;
  world.mass = kProbeMass;
  world.field.resolution = kCourseResolution;
  world.field.forces.assign(3 * 30 * 30 * 30, 0.0);
  return world;
}

State restLattice(Vec3 offset, double angle) {
  // Rotation about the unit axis n by angle (Rodrigues).
  Vec3 n = (1 / std::sqrt(14.0)) * Vec3{1, 2, 3};
  double c = std::cos(angle), s = std::sin(angle);
  Vec3 centre = {0.5, 0.5, 0.5};
  State state;
  for (int q = 0; q < kNumPoints; ++q) {
    Vec3 r = kRestSpacing * Vec3{double(q / 64), double(q / 8 % 8), double(q % 8)} - centre;
    Vec3 turned = c * r + s * cross(n, r) + (1 - c) * dot(n, r) * n;
    store(state.p(), q, turned + centre + offset);
  }
  return state;
}

std::string pointName(int q) { return latticeLabel(q); }

std::string offsetName(int di, int dj, int dk) { return textf("(%d,%d,%d)", di, dj, dk); }

Vec3 forceChange(const std::vector<double>& after, const std::vector<double>& before, int q) {
  return kProbeMass * (load(after.data(), q) - load(before.data(), q));
}

std::string massHint(double measured, double expected) {
  double ratio = measured / expected;
  if (std::fabs(ratio - kProbeMass) <= 1e-6 * kProbeMass)
    return " (exactly 1/512 of it, the mass: is the force not divided by the mass?)";
  if (std::fabs(ratio - kProbeMass * kProbeMass) <= 1e-6 * kProbeMass * kProbeMass)
    return " (exactly 1/512^2 of it, the mass squared: is the force multiplied by the mass "
           "instead of divided by it?)";
  return "";
}

double largest(const std::vector<double>& values) {
  double most = 0;
  for (double value : values) most = std::fmax(most, std::fabs(value));
  return most;
}

CheckResult passed(const std::string& check, std::string line) {
  return {check, Grade::Pass, std::move(line), {}};
}
CheckResult near(const std::string& check, std::string line) {
  return {check, Grade::Near, std::move(line), {}};
}
CheckResult failed(const std::string& check, std::string line) {
  return {check, Grade::Fail, std::move(line), {}};
}
CheckResult info(const std::string& check, std::string line) {
  return {check, Grade::Info, std::move(line), {}};
}

// The accelerations at each of `states`, in one probe run; empty with `failure` set when not.
std::vector<std::vector<double>> accelerationsAt(const std::string& probe, const World& world,
                                                 const std::vector<State>& states,
                                                 std::string* failure) {
  Script script;
  script.world(world, probeRun(), states.front());
  for (const State& s : states) {
    script.state(s);
    script.accelerations();
  }
  ProbeRun run = runProbe(probe, script);
  if (!run.complete()) *failure = run.failure;
  for (std::size_t n = 0; n < run.answers.size() && failure->empty(); ++n) {
    // Every comparison after this is false for a NaN: one would pass for anything.
    if (!allUsable(run.answers[n])) *failure = "computeAcceleration gave NaN or infinity";
  }
  return failure->empty() ? run.answers : std::vector<std::vector<double>>{};
}

ProbeRun oneStep(const std::string& probe, const WorldFile& start, Integrator integrator) {
  Script script;
  script.world(start.world, start.run, start.state);
  script.accelerations();
  script.steps(integrator, 1);
  script.read();
  return runProbe(probe, script);
}

CheckResult crashed(const std::string& check, const ProbeRun& run, const std::string& when) {
  return failed(check, run.failure + " " + when);
}

}  // namespace jello::grader
