// checkagreement.cpp: whole runs against this project's. Some worlds amplify rounding (two
// correct programs, 1e-14 m apart at step 120, can be a metre apart at step 2000), so the
// tolerance is the world's own: the spread of this project's run when its start is nudged by one
// ulp, and a world is judged at the last checkpoint where that spread is still small.
#include <atomic>
#include <cmath>
#include <future>
#include <map>
#include <mutex>
#include <random>

#include "core/assert.h"
#include "grader/checkkit.h"
#include "solver/physics.h"
#include "solver/simulation.h"

namespace jello::grader {
namespace {

constexpr int kCheckpoints = 20;
// Tolerance: this many times the nudged spread, and never below kFloor.
constexpr double kSpreadFactor = 100;
constexpr double kFloor = 1e-9;       // m RMS
constexpr double kJudgedUpTo = 1e-6;  // m: a checkpoint whose tolerance is larger is not judged
constexpr double kNear = 1e-2;        // m RMS: beyond the tolerance but below this, near

double rms(const State& a, const State& b) {
  double sum = 0;
  for (int n = 0; n < kNumCoords; ++n) sum += std::pow(a.p()[n] - b.p()[n], 2);
  return std::sqrt(sum / kNumPoints);
}

// False once the grading is over (stopAgreementReferences): a reference still being computed
// then ends at its next checkpoint.
std::atomic<bool> referencesWanted{true};

std::vector<State> runCheckpoints(const WorldFile& file, std::string* diverged) {
  Model model = makeModel(file.world, file.state);
  Simulation run(model, file.state, file.run);
  std::vector<State> states;
  for (int c = 0; c < kCheckpoints && referencesWanted; ++c) {
    RunOutcome outcome = run.advance(kCheckpointSteps);
    if (!outcome.ran()) {
      *diverged = outcome.reason;
      break;
    }
    states.push_back(run.state());
  }
  return states;
}

// Worlds the submission has never seen, from the seed: springs, damping, a field, a plane under
// the cube (its positive side up, as in the course's worlds), a turned, moving, spinning cube.
WorldFile unseenWorld(std::uint64_t seed, int which) {
  std::mt19937_64 random(seed * 2 + static_cast<unsigned>(which));
  auto uniform = [&](double a, double b) {
    return std::uniform_real_distribution<double>(a, b)(random);
  };
  WorldFile file;
  World& w = file.world;
  file.run.integrator = which == 0 ? Integrator::RK4 : Integrator::Euler;
  file.run.dt = which == 0 ? 0.0005 : 0.0001;
  w.kElastic = uniform(200, 500), w.dElastic = uniform(0.1, 0.5);
  w.kCollision = uniform(400, 1000), w.dCollision = uniform(0.1, 0.5);
  w.mass = kProbeMass;
  w.field.resolution = 6;
  for (int n = 0; n < 3 * 216; ++n)
    w.field.forces.push_back(uniform(-0.05, 0.05) - (n % 3 == 2 ? 0.05 : 0));
  file.state =
      restLattice({uniform(-1.2, 0.2), uniform(-1.2, 0.2), uniform(-1.2, 0.2)}, uniform(0, 3));
  Vec3 spin = {uniform(-3, 3), uniform(-3, 3), uniform(-3, 3)},
       drift = {uniform(-3, 3), uniform(-3, 3), uniform(-3, 3)};
  Vec3 normal = {uniform(-0.5, 0.5), uniform(-0.5, 0.5), 1};
  double lowest = INFINITY;
  for (int q = 0; q < kNumPoints; ++q) {
    Vec3 p = load(file.state.p(), q);
    store(file.state.v(), q, drift + cross(spin, p));
    lowest = std::fmin(lowest, dot(normal, p));
  }
  double scale = uniform(0.5, 2);
  w.hasPlane = true;
  w.plane = {scale * normal.x, scale * normal.y, scale * normal.z,
             -scale * (lowest - uniform(0.1, 0.4))};
  return file;
}

struct Judged {
  Grade grade = Grade::Pass;
  std::string line;
};

Judged judgeWorld(const std::string& name, const AgreementReference& ref, const ProbeRun& run,
                  std::size_t first) {
  if (!ref.diverged.empty())
    return {Grade::Info, name + ": this project's run diverged (" + ref.diverged + "); not judged"};
  std::size_t judged = ref.judged;
  long step = static_cast<long>(judged + 1) * kCheckpointSteps;
  if (run.answers.size() < first + 2 * (judged + 1)) {
    return {Grade::Fail, name + ": " + (run.failure.empty() ? "no answer" : run.failure) +
                             " before step " + std::to_string(step)};
  }
  // Beyond the judged step only a crash or a NaN counts.
  for (std::size_t c = judged + 1; c < ref.checkpoints.size(); ++c) {
    long later = static_cast<long>(c + 1) * kCheckpointSteps;
    if (run.answers.size() < first + 2 * (c + 1)) {
      return {Grade::Fail, name + ": " + run.failure + " before step " + std::to_string(later)};
    }
    if (!allUsable(run.answers[first + 2 * c + 1])) {
      return {Grade::Fail, name + ": NaN by step " + std::to_string(later)};
    }
  }
  State theirs = run.state(first + 2 * judged + 1);
  double distance = rms(theirs, ref.checkpoints[judged]);
  std::string where = textf(
      "%s: %.3g m RMS from this project at step %ld (tolerance %.2g m, from the "
      "world's own sensitivity%s)",
      name.c_str(), distance, step, ref.tolerance[judged],
      judged + 1 < ref.checkpoints.size() ? "; later steps amplify rounding too much to judge"
                                          : "");
  if (distance <= ref.tolerance[judged]) return {Grade::Pass, where};
  if (distance <= kNear) return {Grade::Near, where};
  return {Grade::Fail,
          std::isfinite(distance) ? where : name + ": NaN by step " + std::to_string(step)};
}

// Near is a constant rounded in the source, which every world shows. An Euler world that
// drifts while every RK4 world agrees is the Euler step itself: wrong, never near.
void failEulerDriftAlone(const std::vector<std::pair<std::string, WorldFile>>& worlds,
                         std::vector<Judged>& judged) {
  bool rk4Drifts = false;
  for (std::size_t w = 0; w < worlds.size(); ++w) {
    rk4Drifts |= worlds[w].second.run.integrator != Integrator::Euler &&
                 judged[w].grade != Grade::Pass && judged[w].grade != Grade::Info;
  }
  for (std::size_t w = 0; w < worlds.size(); ++w) {
    if (worlds[w].second.run.integrator == Integrator::Euler && judged[w].grade == Grade::Near &&
        !rk4Drifts) {
      judged[w].grade = Grade::Fail;
      judged[w].line +=
          ", while every RK4 world agrees: the Euler step differs (the euler check says how)";
    }
  }
}

}  // namespace

AgreementReference agreementReference(const WorldFile& file) {
  // The three runs are independent: the nudged ones in threads of their own.
  auto nudgedRun = [&file](double toward) {
    WorldFile nudged = file;
    for (int n = 0; n < kNumCoords; ++n)
      nudged.state.p()[n] = std::nextafter(file.state.p()[n], toward);
    std::string ignored;
    return runCheckpoints(nudged, &ignored);
  };
  std::future<std::vector<State>> up = std::async(std::launch::async, nudgedRun, INFINITY),
                                  down = std::async(std::launch::async, nudgedRun, -INFINITY);
  AgreementReference ref;
  ref.checkpoints = runCheckpoints(file, &ref.diverged);
  ref.tolerance.assign(ref.checkpoints.size(), kFloor);
  for (std::future<std::vector<State>>* run : {&up, &down}) {
    std::vector<State> states = run->get();
    for (std::size_t c = 0; c < ref.checkpoints.size(); ++c) {
      double spread = c < states.size() ? rms(states[c], ref.checkpoints[c]) : INFINITY;
      ref.tolerance[c] = std::fmax(ref.tolerance[c], kSpreadFactor * spread);
    }
  }
  for (std::size_t c = 0; c < ref.checkpoints.size(); ++c) {
    if (ref.tolerance[c] <= kJudgedUpTo) ref.judged = c;
  }
  return ref;
}

namespace {

// The worlds of the check: the course's five, then the two unseen ones of the seed.
std::vector<std::pair<std::string, WorldFile>> agreementWorlds(const GradingSetup& setup) {
  std::vector<std::pair<std::string, WorldFile>> worlds;
  for (const char* name : {"rotate.w", "jello.w", "moveLeft.w", "skewedCorner.w", "gravity.w"}) {
    worlds.emplace_back(name, readWorldFile(setup.worldDir + "/" + name));
  }
  for (int which = 0; which < 2; ++which) {
    worlds.emplace_back(textf("unseen %s world (seed %llu)", which == 0 ? "RK4" : "Euler",
                              static_cast<unsigned long long>(setup.seed)),
                        unseenWorld(setup.seed, which));
  }
  return worlds;
}

// A world's reference, the same for every submission of a run: computed once, in a thread of
// its own, from the first time it is asked for (startAgreementReferences asks early).
std::mutex referencesLock;
std::map<std::string, std::shared_future<AgreementReference>> references;

std::shared_future<AgreementReference> referenceOf(const std::string& name, const WorldFile& file) {
  std::lock_guard<std::mutex> hold(referencesLock);
  JELLO_ASSERT(referencesWanted);
  auto found = references.find(name);
  if (found == references.end())
    found =
        references.emplace(name, std::async(std::launch::async, agreementReference, file)).first;
  return found->second;
}

}  // namespace

void startAgreementReferences(const GradingSetup& setup) {
  for (const auto& [name, file] : agreementWorlds(setup)) referenceOf(name, file);
}

void stopAgreementReferences() {
  referencesWanted = false;
  std::lock_guard<std::mutex> hold(referencesLock);
  for (auto& [name, reference] : references) reference.wait();
  references.clear();
}

constexpr double kAgreementScale = 12;  // times kProbeSeconds: 60 CPU seconds a world

CheckResult checkAgreement(const std::string& probe, const GradingSetup& setup) {
  const std::vector<std::pair<std::string, WorldFile>> worlds = agreementWorlds(setup);
  for (const auto& [name, file] : worlds) referenceOf(name, file);  // all started, worlds read once
  std::vector<Judged> judgedWorlds;
  for (const auto& [name, file] : worlds) {
    Script script;
    script.world(file.world, file.run, file.state);
    for (int c = 0; c < kCheckpoints; ++c) {
      script.steps(file.run.integrator, kCheckpointSteps);
      script.read();
    }
    // 2000 steps of a slow but right program (30 ms a step) in CPU seconds: a busy machine
    // takes none of them; the wall clock is the backstop (probe.h).
    ProbeRun run = runProbe(probe, script, {kAgreementScale});
    judgedWorlds.push_back(judgeWorld(name, referenceOf(name, file).get(), run, 0));
  }
  failEulerDriftAlone(worlds, judgedWorlds);
  CheckResult result = passed("agreement", "");
  int off = 0;
  for (const Judged& judged : judgedWorlds) {
    // The diagnosis names the first world of the worst grade; the notes, every world.
    if (judged.grade == Grade::Fail || judged.grade == Grade::Near) {
      ++off;
      if (result.grade == Grade::Pass ||
          (judged.grade == Grade::Fail && result.grade != Grade::Fail)) {
        result.diagnosis = judged.line;
        result.grade = judged.grade;
      }
    }
    result.notes.push_back(judged.line);
  }
  if (result.grade == Grade::Pass) {
    result.diagnosis = textf("%zu worlds within their tolerance", worlds.size());
  } else {
    result.diagnosis = textf("%d of %zu worlds off; ", off, worlds.size()) + result.diagnosis;
  }
  return result;
}

}  // namespace jello::grader
