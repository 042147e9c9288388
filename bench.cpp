// bench.cpp: timings of the force kernels and the integrators. Medians of repeated runs, as
// the machines are shared and noisy; never used as a pass/fail threshold.

#include "bench.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include "integrators.h"
#include "physics.h"

namespace jello {

namespace {

using Clock = std::chrono::steady_clock;

constexpr Integrator kBenchIntegrators[] = {Integrator::Euler,  Integrator::Midpoint, Integrator::RK4,
                                            Integrator::Symplectic, Integrator::Verlet, Integrator::RK45,
                                            Integrator::Implicit};

// Seconds per call of `work(count)`, the median over kBenchRepeats. Without a fixed count the
// first call sizes it to about kBenchSeconds.
double medianSecondsPerCall(const std::function<void(long long)>& work, long long fixedCount, int repeats) {
  long long count = fixedCount;
  if (count <= 0) {
    count = 1;
    for (;;) {
      Clock::time_point start = Clock::now();
      work(count);
      double seconds = std::chrono::duration<double>(Clock::now() - start).count();
      if (seconds >= kBenchSeconds / 4 || count >= (1LL << 30)) {
        count = std::max(1LL, static_cast<long long>(count * kBenchSeconds / std::max(seconds, 1e-9)));
        break;
      }
      count *= 4;
    }
  }
  std::vector<double> perCall;
  for (int r = 0; r < repeats; ++r) {
    Clock::time_point start = Clock::now();
    work(count);
    perCall.push_back(std::chrono::duration<double>(Clock::now() - start).count() / count);
  }
  std::sort(perCall.begin(), perCall.end());
  return perCall[perCall.size() / 2];
}

struct StepTiming {
  double seconds = 0;
  double evaluationsPerStep = 0;
  bool diverged = false;
};

StepTiming timeSteps(const Model& model, const State& initial, Integrator integrator, const RunOptions& run,
                     long long fixedSteps, int repeats) {
  StepTiming timing;
  long long steps = 0, evaluations = 0;
  auto work = [&](long long count) {
    // From the initial state every time: each repeat does the same work.
    State state = initial;
    Stepper stepper(integrator, run.tolerances);
    for (long long s = 0; s < count; ++s) stepper.step(model, state, model.world.dt);
    steps += count;
    evaluations += stepper.stats().evaluations + stepper.stats().jacobians;
    timing.diverged = timing.diverged || findDivergedPoint(state) >= 0;
  };
  timing.seconds = medianSecondsPerCall(work, fixedSteps, repeats);
  timing.evaluationsPerStep = static_cast<double>(evaluations) / steps;
  return timing;
}

double timeForces(const Model& model, const State& state, long long fixedCount, int repeats) {
  std::vector<double> force(kNumCoords);
  auto work = [&](long long count) {
    for (long long i = 0; i < count; ++i) computeForces(model, state.p(), state.v(), force.data());
  };
  return medianSecondsPerCall(work, fixedCount, repeats);
}

}  // namespace

std::string machineDescription() {
  std::string cpu = "unknown processor";
  std::ifstream info("/proc/cpuinfo");
  for (std::string line; std::getline(info, line);) {
    if (line.rfind("model name", 0) == 0) {
      cpu = line.substr(line.find(':') + 2);
      break;
    }
  }
  std::string compiler =
#if defined(__clang__)
      "clang++ " __clang_version__;
#elif defined(__GNUC__)
      "g++ " __VERSION__;
#else
      "unknown compiler";
#endif
  return cpu + ", " + std::to_string(std::thread::hardware_concurrency()) + " cores, " + compiler;
}

int runBench(const RunOptions& run) {
  WorldFile file;
  if (!loadRun(run, &file)) return kExitBadInput;
  const World& world = file.world;
  const Model specialised = makeModel(world, file.state, KernelChoice::Specialised);
  const Model general = makeModel(world, file.state, KernelChoice::General);
  const long long fixed = run.steps ? std::max(1LL, *run.steps) : 0;
  const int repeats = run.steps ? 3 : kBenchRepeats;

  std::printf("%s\n", sceneLine(specialised.scene, world).c_str());
  std::printf("bench %s on %s\n", run.worldPath.c_str(), machineDescription().c_str());
  std::printf("medians of %d runs from the initial state at dt=%.9g s; general = every term at every point\n\n",
              repeats, world.dt);
  std::fflush(stdout);

  double forcesS = timeForces(specialised, file.state, fixed, repeats);
  double forcesG = timeForces(general, file.state, fixed, repeats);
  double loading = medianSecondsPerCall([&](long long count) {
    for (long long i = 0; i < count; ++i) readWorldFile(run.worldPath);
  }, run.steps ? 1 : 0, repeats);
  std::printf("%-22s %11.2f ms  (%s)\n", "world loading", loading * 1e3, world.field.resolution > 0
              ? (std::to_string(world.field.resolution) + "^3 field nodes").c_str() : "no field");
  std::printf("%-22s %14s %14s %9s\n", "", "specialised", "general", "speed-up");
  std::printf("%-22s %11.2f us %11.2f us %8.2fx\n", "force evaluation", forcesS * 1e6, forcesG * 1e6, forcesG / forcesS);
  std::printf("%-22s %14.0f %14.0f\n", "evaluations per second", 1 / forcesS, 1 / forcesG);
  std::printf("\n%-22s %14s %14s %9s  %s\n", "us per step", "specialised", "general", "speed-up", "evaluations/step");
  for (Integrator integrator : kBenchIntegrators) {
    // IMPLICIT takes milliseconds a step: a few steps tell.
    long long steps = fixed ? fixed : integrator == Integrator::Implicit ? 3 : 0;
    StepTiming s = timeSteps(specialised, file.state, integrator, run, steps, repeats);
    StepTiming g = timeSteps(general, file.state, integrator, run, steps, repeats);
    std::printf("%-22s %14.2f %14.2f %8.2fx  %.1f%s\n", integratorName(integrator), s.seconds * 1e6, g.seconds * 1e6,
                g.seconds / s.seconds, s.evaluationsPerStep, s.diverged ? "  (diverges at this dt)" : "");
    std::fflush(stdout);
  }
  return kExitOk;
}

}  // namespace jello
