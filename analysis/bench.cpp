// bench.cpp: timings of the force kernels and the integrators. Medians of repeated runs, as
// the machines are shared and noisy; never used as a pass/fail threshold.

#include "analysis/bench.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "core/limits.h"
#include "core/threadpool.h"
#include "solver/integrators.h"
#include "solver/physics.h"
#include "solver/simulation.h"

namespace jello {

namespace {

using Clock = std::chrono::steady_clock;

using Work = std::function<void(long long)>;

// A kernel timed: a model's, on this thread alone or with a pool's threads, all of them.
struct Kernel {
  const Model* model;
  ThreadPool* pool;  // null: one thread
};

// Seconds per call of each work(count), the medians over `repeats` runs of each. The works
// take turns, so that a change in the machine's load falls on both alike and their ratio
// holds. Without a fixed count, the first work's first calls size it to about kBenchSeconds.
// setups[w], when given, runs before each call of works[w], untimed (a run back to its start).
std::vector<double> medianSecondsPerCall(const std::vector<Work>& works, long long fixedCount,
                                         int repeats,
                                         const std::vector<std::function<void()>>& setups = {}) {
  auto setUp = [&setups](std::size_t w) {
    if (w < setups.size()) setups[w]();
  };
  long long count = fixedCount;
  if (count <= 0) {
    count = 1;
    for (;;) {
      setUp(0);
      Clock::time_point start = Clock::now();
      works.front()(count);
      double seconds = std::chrono::duration<double>(Clock::now() - start).count();
      if (seconds >= kBenchSeconds / 4 || count >= (1LL << 30)) {
        count =
            std::max(1LL, static_cast<long long>(count * kBenchSeconds / std::max(seconds, 1e-9)));
        break;
      }
      count *= 4;
    }
  }
  std::vector<std::vector<double>> perCall(works.size());
  for (int r = 0; r < repeats; ++r) {
    for (std::size_t w = 0; w < works.size(); ++w) {
      setUp(w);
      Clock::time_point start = Clock::now();
      works[w](count);
      perCall[w].push_back(std::chrono::duration<double>(Clock::now() - start).count() / count);
    }
  }
  std::vector<double> medians;
  for (std::vector<double>& times : perCall) {
    std::sort(times.begin(), times.end());
    medians.push_back(times[times.size() / 2]);
  }
  return medians;
}

struct StepTiming {
  double seconds = 0;
  double evaluationsPerStep = 0;
  bool diverged = false;
};

// Steps of each model as a run takes them (Simulation: the stepper and the checks), from the
// initial state every time, so that each run does the same work.
std::vector<StepTiming> timeSteps(const std::vector<Kernel>& kernels, const State& initial,
                                  const RunSettings& settings, const RunOptions& run,
                                  long long fixedSteps, int repeats) {
  std::vector<StepTiming> timings(kernels.size());
  std::vector<long long> steps(kernels.size()), evaluations(kernels.size());
  // Made once, outside the timing: making one passes over the field's nodes (the guard's bound).
  std::vector<std::unique_ptr<Simulation>> simulations;
  for (const Kernel& kernel : kernels) {
    simulations.push_back(
        std::make_unique<Simulation>(*kernel.model, initial, settings, run.tolerances));
    simulations.back()->setPool(kernel.pool, false);
  }
  // Back to the start before each timed run, untimed: a restart computes the state's energy,
  // which for a large body costs as much as a few steps.
  std::vector<Work> works;
  std::vector<std::function<void()>> restarts;
  for (std::size_t m = 0; m < kernels.size(); ++m) {
    restarts.push_back([&, m] { simulations[m]->restart(initial); });
    works.push_back([&, m](long long count) {
      Simulation& simulation = *simulations[m];
      timings[m].diverged = !simulation.advance(count).ran() || timings[m].diverged;
      steps[m] += simulation.step();
      evaluations[m] += simulation.stats().evaluations + simulation.stats().jacobians;
    });
  }
  std::vector<double> seconds = medianSecondsPerCall(works, fixedSteps, repeats, restarts);
  for (std::size_t m = 0; m < kernels.size(); ++m) {
    timings[m].seconds = seconds[m];
    timings[m].evaluationsPerStep = static_cast<double>(evaluations[m]) / steps[m];
  }
  return timings;
}

std::vector<double> timeForces(const std::vector<Kernel>& kernels, const State& state,
                               long long fixedCount, int repeats) {
  std::vector<double> force(state.coords());
  std::vector<Work> works;
  for (const Kernel& kernel : kernels) {
    const Workers workers = workersFor(*kernel.model, kernel.pool, false);
    works.push_back([&, kernel, workers](long long count) {
      for (long long i = 0; i < count; ++i)
        computeForces(*kernel.model, state.p(), state.v(), force.data(), nullptr, &workers);
    });
  }
  return medianSecondsPerCall(works, fixedCount, repeats);
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

namespace {

// What --bench times, in its columns' order: the specialised kernel on one thread, the general
// one (the reference), the specialised kernel on two threads and on all the cores (when there
// are more than two).
struct Columns {
  std::vector<Kernel> kernels;
  std::vector<std::string> names;
};

// One integrator's row: the step it was timed at (the world's, or the largest of dt/2, dt/4, ...
// at which it does not diverge) and its timings with each kernel.
struct BenchRow {
  Integrator integrator = Integrator::RK4;
  double dt = 0;
  std::vector<StepTiming> timings;
};

// What --bench measured.
struct BenchFigures {
  int repeats = 0;
  std::vector<double> forces;  // s per evaluation, by column
  double loading = 0;          // s to parse the world's text
  std::vector<BenchRow> rows;
};

bool anyDiverged(const std::vector<StepTiming>& timings) {
  for (const StepTiming& t : timings)
    if (t.diverged) return true;
  return false;
}

// Each integrator's steps, timed (a diverging run would time arithmetic on huge numbers).
BenchRow timeIntegrator(const std::vector<Kernel>& kernels, const State& initial,
                        const IntegratorInfo& row, const RunSettings& world, const RunOptions& run,
                        long long fixed, int repeats) {
  // A step that assembles and solves with the Jacobian (IMPLICIT) takes milliseconds: a few
  // steps tell.
  const long long steps = fixed ? fixed : row.needsJacobian ? 3 : 0;
  constexpr int kHalvings = 12;
  RunSettings settings{row.integrator, world.dt, world.n};
  std::vector<StepTiming> timings = timeSteps(kernels, initial, settings, run, steps, repeats);
  for (int h = 0; h < kHalvings && anyDiverged(timings); ++h) {
    settings.dt /= 2;
    timings = timeSteps(kernels, initial, settings, run, steps, repeats);
  }
  return {row.integrator, settings.dt, timings};
}

BenchFigures measureBench(const RunOptions& run, const WorldFile& file, const Columns& columns) {
  BenchFigures figures;
  const long long fixed = run.steps ? std::max(1LL, *run.steps) : 0;
  figures.repeats = run.steps ? 3 : kBenchRepeats;
  figures.forces = timeForces(columns.kernels, file.state, fixed, figures.repeats);
  // The world's text is parsed from memory: the file itself may be a pipe, read once already. A
  // world file holds the course cube only: a scene's other jelly has no such text to parse.
  figures.loading = NAN;
  if (bodyOf(file.world).courseLattice) {
    const std::string text = formatWorld(file);
    figures.loading = medianSecondsPerCall({[&](long long count) {
                                             for (long long i = 0; i < count; ++i)
                                               parseWorld(text, run.worldPath);
                                           }},
                                           run.steps ? 1 : 0, figures.repeats)[0];
  }
  // --integrator NAME times that one alone (a large body's IMPLICIT steps take seconds).
  for (const IntegratorInfo& row : integratorTable())
    if (!run.integrator || *run.integrator == row.integrator)
      figures.rows.push_back(
          timeIntegrator(columns.kernels, file.state, row, file.run, run, fixed, figures.repeats));
  return figures;
}

// The table's head: a name column, then each kernel's column (with its speed-up against the
// first, except the general one's, whose speed-up is the first's against it).
void printHead(const char* title, const Columns& c, const char* last) {
  std::printf("%-22s", title);
  for (std::size_t k = 0; k < c.names.size(); ++k) {
    std::printf(" %14s", c.names[k].c_str());
    if (k > 0) std::printf(" %9s", "speed-up");
  }
  std::printf("%s\n", last);
}
void printTimes(const char* name, const std::vector<double>& seconds, double scale,
                const char* unit) {
  std::printf("%-22s", name);
  for (std::size_t k = 0; k < seconds.size(); ++k) {
    std::printf(" %11.2f%s", seconds[k] * scale, unit);
    if (k == 1) std::printf(" %8.2fx", seconds[1] / seconds[0]);
    if (k > 1) std::printf(" %8.2fx", seconds[0] / seconds[k]);
  }
}

void printBench(const RunOptions& run, const WorldFile& file, const Model& specialised,
                const Columns& columns, int runThreads, const BenchFigures& f) {
  std::printf("%s\n", termsLine(specialised.forces).c_str());
  std::printf("bench %s on %s\n", run.worldPath.c_str(), machineDescription().c_str());
  const int points = specialised.points();
  std::printf(
      "%d points; medians of %d runs each, the kernels taking turns, from the initial state at "
      "dt=%.9g s;\ngeneral = every term at every point, the springs from their list; a run of "
      "this body uses %d thread%s (--threads; one below %d points, else one for each %d)\n\n",
      points, f.repeats, file.run.dt, runThreads, runThreads == 1 ? "" : "s", kFewestPointsShared,
      kPointsPerThread);
  const World& world = file.world;
  if (std::isnan(f.loading))
    std::printf("%-22s %14s  (a scene's jelly other than the course cube: no world file)\n",
                "world parsing", "-");
  else
    std::printf("%-22s %11.2f ms  (%s)\n", "world parsing", f.loading * 1e3,
                world.field.resolution > 0
                    ? (std::to_string(world.field.resolution) + "^3 field nodes").c_str()
                    : "no field");
  printHead("", columns, "");
  printTimes("force evaluation", f.forces, 1e6, " us");
  std::printf("\n");
  printTimes("  per point", f.forces, 1e9 / points, " ns");
  std::printf("\n");
  printHead("\nus per step", columns, "  evaluations/step");
  for (const BenchRow& r : f.rows) {
    std::vector<double> seconds;
    for (const StepTiming& t : r.timings) seconds.push_back(t.seconds);
    char note[96] = "";
    if (anyDiverged(r.timings))
      std::snprintf(note, sizeof note, "  (diverges even at dt=%.3g)", r.dt);
    else if (r.dt != file.run.dt)
      std::snprintf(note, sizeof note, "  (diverges at dt=%.3g; timed at dt=%.3g)", file.run.dt,
                    r.dt);
    printTimes(integratorName(r.integrator), seconds, 1e6, "   ");
    std::printf("  %.1f%s\n", r.timings[0].evaluationsPerStep, note);
  }
}

}  // namespace

Outcome runBench(const RunOptions& run) {
  WorldFile file;
  if (Outcome loaded = loadRun(run, &file); !loaded.ok()) return loaded;
  const Model specialised = makeModel(file.world, file.state, KernelChoice::Specialised);
  const Model general = makeModel(file.world, file.state, KernelChoice::General);
  const int cores = std::min(availableCores(), kMostThreads);
  ThreadPool two(2), all(cores);
  Columns columns{{{&specialised, nullptr}, {&general, nullptr}, {&specialised, &two}},
                  {"one thread", "general", "2 threads"}};
  if (cores > 2) {
    columns.kernels.push_back({&specialised, &all});
    columns.names.push_back(std::to_string(cores) + " threads");
  }
  const int runThreads = threadsFor(specialised, run.threads);
  const BenchFigures figures = measureBench(run, file, columns);
  printBench(run, file, specialised, columns, runThreads, figures);
  return succeeded();
}

}  // namespace jello
