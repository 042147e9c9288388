// checkmotion.cpp: the integrators (one step on the submission's own accelerations; RK4's
// order) and the robustness and speed of whole runs.
#include <cmath>
#include <map>
#include <random>

#include "grader/checkkit.h"
#include "solver/physics.h"
#include "solver/simulation.h"

namespace jello::grader {
namespace {

// A cube in motion, deformed, one face across the wall x = 2, in a field, over a plane: every
// term at work.
WorldFile busyWorld(Vec3 place = {1.03, -0.4, -0.6}) {
  WorldFile file{probeWorld(), probeRun(), restLattice(place, 0.3), {}};
  std::mt19937_64 random(42);
  std::uniform_real_distribution<double> jitter(-0.02, 0.02), speed(-0.5, 0.5);
  for (int n = 0; n < kNumCoords; ++n) {
    file.state.p()[n] += jitter(random);
    file.state.v()[n] = speed(random);
  }
  file.world.field.resolution = 3;
  file.world.field.forces = std::vector<double>(81, 0.0);
  for (std::size_t n = 0; n < file.world.field.forces.size(); ++n)
    file.world.field.forces[n] = 0.01 * double(n % 7) - 0.03;
  file.world.hasPlane = true;
  file.world.plane = {0.2, 0.3, 1, 1.7};
  return file;
}

// The largest difference between states a and b, positions over pScale, velocities over vScale.
double relativeDifference(const State& a, const State& b, double pScale, double vScale) {
  double worst = 0;
  for (int n = 0; n < kNumCoords; ++n) {
    double p = std::fabs(a.p()[n] - b.p()[n]) / pScale, v = std::fabs(a.v()[n] - b.v()[n]) / vScale;
    if (!(p <= worst)) worst = std::isnan(p) ? INFINITY : p;  // a NaN is never close
    if (!(v <= worst)) worst = std::isnan(v) ? INFINITY : v;
  }
  return worst;
}

// start + h * (velocities of k, accelerations of k): the state of an explicit stage.
State stage(const State& start, double h, const State& k) {
  State s = start;
  for (std::size_t n = 0; n < s.y.size(); ++n) s.y[n] += h * k.y[n];
  return s;
}

// The derivative (v, a) at `state` from an answer of accelerations.
State derivativeOf(const State& state, const std::vector<double>& a) {
  State k;
  std::copy(state.v(), state.v() + kNumCoords, k.p());
  std::copy(a.begin(), a.end(), k.v());
  return k;
}

constexpr double kOneStepExact = 1e-9;
// A step whose result is NaN where the accelerations at its start were not: the integrator cannot
// be told from computeAcceleration, whose answers change from one call to the next.
const char* const kUnsteady =
    "the step gave NaN or infinity where computeAcceleration's answer at its start was finite: "
    "computeAcceleration answers differently from one call to the next (an uninitialised "
    "variable?)";
const char* const kNotJudged =
    "computeAcceleration gave NaN or infinity on a cube in motion: the step cannot be judged";  // relative to dt * (largest velocity or acceleration)

// One RK4 of the variants below: stage j (2, 3, 4) evaluated at start + c[j] * dt * k[m[j]],
// m = 0 meaning the start itself.
struct Rk4Variant {
  int m[5] = {0, 0, 1, 2, 3};
  double c[5] = {0, 0, 0.5, 0.5, 1};
  // Every stage's acceleration taken at the start (its velocity at the stage's state): what a
  // computeAcceleration that reads the global jello, not its argument, makes of RK4.
  bool accelerationsAtStart = false;
  std::string name;  // "" for classic RK4
};

// The steps a stage may wrongly be taken with: a quarter, half, whole or double step.
struct StageStep {
  double times;  // of dt
  const char* words;
};
constexpr StageStep kStageSteps[] = {{0.5, "dt/2"}, {1.0, "dt"}, {0.25, "dt/4"}, {2.0, "2dt"}};

std::vector<Rk4Variant> rk4Variants() {
  static const char* const stageNames[5] = {"", "", "second stage (k2)", "third stage (k3)",
                                            "fourth stage (k4)"};
  std::vector<Rk4Variant> variants(2);
  variants[1].accelerationsAtStart = true;
  variants[1].name =
      "every stage of RK4 gets the accelerations of the start of the step: does "
      "computeAcceleration "
      "read the global jello instead of its argument?";
  for (int j = 2; j <= 4; ++j) {
    for (int m = 0; m < j; ++m) {
      for (std::size_t n = 0; n < std::size(kStageSteps); ++n) {
        const double c = kStageSteps[n].times;
        Rk4Variant v;
        if ((m == 0 && n > 0) || (m == v.m[j] && c == v.c[j])) continue;
        v.m[j] = m;
        v.c[j] = c;
        v.name = "RK4's " + std::string(stageNames[j]) + " is evaluated at " +
                 (m == 0 ? std::string("the start of the step")
                         : textf("state + %s*k%d", kStageSteps[n].words, m)) +
                 textf("; classic RK4 takes state + %s*k%d", j == 4 ? "dt" : "dt/2", j - 1);
        variants.push_back(v);
      }
    }
  }
  return variants;
}

// Observed order of the submission's RK4 on a smooth scene (no contact, no field): from the
// differences between runs to one time at dt, dt/2, dt/4, dt/8.
std::string rk4Order(const std::string& probe, double* order) {
  World world = probeWorld();
  world.dElastic = 0;  // undamped: a damping mistake is the dampers check's, not this one's
  State start = restLattice(kCentred);
  for (int q = 0; q < kNumPoints; ++q) {
    Vec3 p = load(start.p(), q);
    store(start.p(), q, p + 0.03 * Vec3{std::sin(3 * p.y), std::sin(2 * p.z), std::sin(4 * p.x)});
    store(start.v(), q, 0.5 * Vec3{-p.y, p.x, 0.2});
  }
  Script script;
  std::vector<State> ends;
  RunSettings settings = probeRun();
  for (int halvings = 0; halvings < 4; ++halvings) {
    settings.dt = 4e-4 / (1 << halvings);
    script.world(world, settings, start);
    script.steps(Integrator::RK4, 25L << halvings);
    script.read();
  }
  ProbeRun run = runProbe(probe, script);
  if (!run.complete()) return run.failure;
  auto difference = [&](int a, int b) {
    double sum = 0;
    for (int n = 0; n < kNumCoords; ++n)
      sum += std::pow(run.state(2 * a + 1).p()[n] - run.state(2 * b + 1).p()[n], 2);
    return std::sqrt(sum);
  };
  *order = std::log2(difference(1, 2) / difference(2, 3));
  return "";
}

// Which RK4 the submission's step `result` from busy.state is: "" for classic RK4 on its own
// accelerations (k1's given), a variant's words when it is RK4 with one stage at a usual wrong
// state, or a line saying neither; *failure when the probe could not answer. Every variant's
// stages are asked for a round (a probe run) at a time, each state once.
std::string whichRk4(const std::string& probe, const WorldFile& busy, const std::vector<double>& k1,
                     const State& result, std::string* failure) {
  double dt = busy.run.dt;
  std::vector<Rk4Variant> variants = rk4Variants();
  std::vector<std::vector<State>> k(variants.size(), std::vector<State>(5));  // k[v][stage]
  for (auto& stages : k) stages[1] = derivativeOf(busy.state, k1);
  for (int j = 2; j <= 4; ++j) {
    std::vector<State> states;
    std::map<std::vector<double>, std::size_t> asked;
    std::vector<std::size_t> which(variants.size());
    for (std::size_t v = 0; v < variants.size(); ++v) {
      const Rk4Variant& var = variants[v];
      State s = var.m[j] == 0 ? busy.state : stage(busy.state, var.c[j] * dt, k[v][var.m[j]]);
      auto found = asked.emplace(s.y, states.size());
      if (found.second) states.push_back(s);
      which[v] = found.first->second;
    }
    auto answers = accelerationsAt(probe, busy.world, states, failure);
    if (!failure->empty()) return "";
    for (std::size_t v = 0; v < variants.size(); ++v) {
      k[v][j] =
          derivativeOf(states[which[v]], variants[v].accelerationsAtStart ? k1 : answers[which[v]]);
    }
  }
  double pScale = dt * largest(busy.state.y), vScale = dt * largest(k1);
  for (std::size_t v = 0; v < variants.size(); ++v) {
    State y = busy.state;
    for (std::size_t n = 0; n < y.y.size(); ++n) {
      y.y[n] += dt / 6 * (k[v][1].y[n] + 2 * k[v][2].y[n] + 2 * k[v][3].y[n] + k[v][4].y[n]);
    }
    if (relativeDifference(result, y, pScale, vScale) <= kOneStepExact) return variants[v].name;
  }
  return "one RK4 step is not classic RK4 on its own accelerations, nor RK4 with one stage (k2, "
         "k3 or k4) at another state (the start of the step, or state + dt/4, dt/2, dt or 2dt "
         "times an earlier k), nor RK4 on the accelerations of the start: compare each stage's "
         "state and the final sum, dt/6 (k1 + 2 k2 + 2 k3 + k4), with the course's";
}

// The world the integrators' checks step from: busyWorld, unless the submission's
// computeAcceleration changes the state it is given there (a wall that zeroes the velocities of
// the points across it), gives a NaN, or answers differently when asked twice (a wall that keeps
// where a point crossed it): the step then cannot be told from its accelerations, so
// it is judged on the same cube away from every contact (inside the box, over the plane), with a
// note; the walls' and the plane's checks judge the contact.
WorldFile stepWorld(const std::string& probe, std::vector<std::string>* notes) {
  WorldFile busy = busyWorld();
  Script script;
  script.world(busy.world, busy.run, busy.state);
  script.accelerations();
  script.read();
  script.state(busy.state);
  script.accelerations();
  ProbeRun run = runProbe(probe, script);
  if (!run.complete()) return busy;
  if (!allUsable(run.answers[0])) {
    notes->push_back(
        "computeAcceleration gives NaN or infinity on a cube across a wall: the step was judged "
        "on the same cube away from every contact");
  } else if (run.state(1).y != busy.state.y) {
    notes->push_back(
        "computeAcceleration changes the state it is given (its positions or velocities) on a "
        "cube across a wall: the step was judged on the same cube away from every contact");
  } else if (run.answers[2] != run.answers[0]) {
    notes->push_back(
        "computeAcceleration answers differently when asked twice at the same state of a cube "
        "across a wall (it keeps a state of its own, or reads memory it never set): the step was "
        "judged on the same cube away from every contact");
  } else {
    return busy;
  }
  return busyWorld({0.3, -0.4, -0.6});
}

}  // namespace

// One step of each integrator from `busy`, judged (below the checks that choose the world).
CheckResult judgeEuler(const std::string& probe, const WorldFile& busy);
CheckResult judgeRk4(const std::string& probe, const WorldFile& busy);

// `judge` on stepWorld's world, with its note.
CheckResult judgedOnStepWorld(const std::string& probe,
                              CheckResult (*judge)(const std::string&, const WorldFile&)) {
  std::vector<std::string> notes;
  WorldFile world = stepWorld(probe, &notes);
  CheckResult result = judge(probe, world);
  result.notes.insert(result.notes.end(), notes.begin(), notes.end());
  return result;
}

CheckResult checkEuler(const std::string& probe) { return judgedOnStepWorld(probe, judgeEuler); }

CheckResult judgeEuler(const std::string& probe, const WorldFile& busy) {
  ProbeRun run = oneStep(probe, busy, Integrator::Euler);
  if (!run.complete()) return crashed("euler", run, "on one step of a cube in motion");
  if (!allUsable(run.answers[0])) return failed("euler", kNotJudged);
  const State& s = busy.state;
  State after = run.state(2), course = s, symplectic = s;
  if (!allUsable(after.y)) return failed("euler", kUnsteady);
  double dt = busy.run.dt;
  for (int n = 0; n < kNumCoords; ++n) {
    course.v()[n] = s.v()[n] + dt * run.answers[0][n];
    course.p()[n] = s.p()[n] + dt * s.v()[n];
    symplectic.v()[n] = course.v()[n];
    symplectic.p()[n] = s.p()[n] + dt * course.v()[n];
  }
  double pScale = dt * largest(s.y), vScale = dt * largest(run.answers[0]);
  double off = relativeDifference(after, course, pScale, vScale);
  if (off <= kOneStepExact)
    return passed("euler", "p += dt v; v += dt a, on its own accelerations");
  if (relativeDifference(after, symplectic, pScale, vScale) <= kOneStepExact) {
    return failed("euler",
                  "Euler moves p with the new velocity (semi-implicit Euler); the course's "
                  "Euler uses the velocity from before the step");
  }
  return failed("euler", textf("one Euler step differs from p += dt v, v += dt a(p, v) on its own "
                               "accelerations by %.3g of a step",
                               off));
}

CheckResult checkRk4(const std::string& probe) { return judgedOnStepWorld(probe, judgeRk4); }

CheckResult judgeRk4(const std::string& probe, const WorldFile& busy) {
  ProbeRun run = oneStep(probe, busy, Integrator::RK4);
  if (!run.complete()) return crashed("rk4", run, "on one step of a cube in motion");
  if (!allUsable(run.answers[0])) return failed("rk4", kNotJudged);
  std::string failure;
  std::string wrong = whichRk4(probe, busy, run.answers[0], run.state(2), &failure);
  if (!failure.empty()) return failed("rk4", failure + " at a stage of RK4");
  if (!allUsable(run.state(2).y)) return failed("rk4", kUnsteady);
  double order = 0;
  failure = rk4Order(probe, &order);
  if (!failure.empty()) return failed("rk4", failure + " on a smooth scene");
  std::string orderLine = textf("observed order %.2f on a smooth scene", order);
  if (!wrong.empty()) return failed("rk4", wrong + " (" + orderLine + ")");
  // Its step is classic RK4 on its own accelerations: an order below 4 then comes from those
  // accelerations (a term of its own that is not smooth, an obstacle beyond the course's), which
  // the term checks and the agreement judge, not from the integrator.
  if (!std::isfinite(order)) return failed("rk4", orderLine + ": NaN or infinity in its run");
  if (!(std::fabs(order - 4) <= 0.5))
    return passed("rk4", "classic RK4 on its own accelerations; " + orderLine +
                             ", not 4: its own accelerations are not smooth on that scene (a "
                             "term of its own? the term checks and the agreement judge them)");
  return passed("rk4", "classic RK4 on its own accelerations; " + orderLine);
}

// Beyond the course's worlds (each finding through outsideDomain): a cube thrown at 52 m/s into
// the corner, one collapsed to a point, one collapsed flat.
CheckResult checkRobust(const std::string& probe, const GradingSetup& setup) {
  World world = probeWorld();
  State thrown = restLattice(kCentred), point = thrown, flat = thrown;
  for (int q = 0; q < kNumPoints; ++q) {
    store(thrown.v(), q, {-30, -30, -30});
    store(point.p(), q, {0.1, 0.2, 0.3});
    Vec3 p = load(flat.p(), q);
    store(flat.p(), q, {p.x, p.y, 0.1});
  }
  // The throw: its accelerations along this project's run into the corner, so that a mistake
  // elsewhere in its physics (which may make its own run explode) does not count here.
  Model model = makeModel(world, thrown);
  Simulation reference(model, thrown, Integrator::RK4, probeRun().dt);
  std::vector<State> throw_;
  for (int n = 0; n < 10; ++n) {
    reference.advance(40);
    throw_.push_back(reference.state());
  }
  const char* throwWords = "a cube thrown at 52 m/s into the corner (-2,-2,-2)";
  std::string failure;
  auto answers = accelerationsAt(probe, world, throw_, &failure);
  if (!failure.empty()) return outsideDomain("robust", failure + " on " + throwWords, setup);
  for (const auto& [what, state] :
       {std::pair<const char*, const State&>{"a cube collapsed to one point (all 512 points at one "
                                             "place)",
                                             point},
        {"a cube collapsed flat (eight points at each place)", flat}}) {
    Script script;
    script.world(world, probeRun(), state);
    script.accelerations();
    script.steps(Integrator::RK4, 10);
    script.read();
    ProbeRun run = runProbe(probe, script);
    if (!run.complete())
      return outsideDomain("robust", run.failure + " on " + std::string(what), setup);
    if (!allUsable(run.answers[0]) || !allUsable(run.answers[2])) {
      return outsideDomain("robust",
                           std::string("NaN or infinity on ") + what +
                               ": a spring of zero length should exert no force",
                           setup);
    }
  }
  return passed("robust", "finite through a hard corner throw and two collapses");
}

CheckResult checkSpeed(const std::string& probe, const GradingSetup& setup) {
  WorldFile rotate = readWorldFile(setup.worldDir + "/rotate.w");
  Script script;
  script.world(rotate.world, rotate.run, rotate.state);
  script.timing(500);
  ProbeRun run = runProbe(probe, script);
  if (!run.complete()) return info("speed", "not measured: " + run.failure);
  // The figure comes from the program's own process: kept only when it is a time.
  if (!(run.answers[0][0] >= 0 && run.answers[0][0] <= 1e9))
    return info("speed", "not measured: the timing answered no time");
  CheckResult result = info(
      "speed",
      textf("%.0f us per RK4 step on rotate.w (500 steps, in the sandbox)", run.answers[0][0]));
  result.figure = run.answers[0][0];
  return result;
}

}  // namespace jello::grader
