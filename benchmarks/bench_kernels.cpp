// Google Benchmark: the force kernel (specialised and general) and one step of each integrator
// on the course worlds. Run `build/benchmarks/jello_benchmarks` from the project's top folder;
// `jello --bench WORLD` prints the same figures for any one world.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "io/input.h"
#include "model/term.h"
#include "model/world.h"
#include "solver/integrators.h"
#include "solver/physics.h"

namespace {

using namespace jello;

const char* const kWorlds[] = {"rotate", "jello", "moveLeft", "skewedCorner", "gravity"};

const WorldFile& courseWorld(int index) {
  static std::vector<WorldFile> files = [] {
    std::vector<WorldFile> out;
    for (const char* name : kWorlds)
      out.push_back(readWorldFile(std::string(JELLO_WORLD_DIR) + "/" + name + ".w"));
    return out;
  }();
  return files[index];
}

void Forces(benchmark::State& bench, int world, KernelChoice choice) {
  const WorldFile& f = courseWorld(world);
  Model model = makeModel(f.world, f.state, choice);
  std::vector<double> force(kNumCoords);
  for (auto _ : bench) {
    computeForces(model, f.state.p(), f.state.v(), force.data());
    benchmark::DoNotOptimize(force.data());
  }
  bench.counters["evaluations/s"] =
      benchmark::Counter(static_cast<double>(bench.iterations()), benchmark::Counter::kIsRate);
}

// One force term alone (the scene's term `index`, in its list order), everything in reach: where
// an evaluation's time goes.
void Term(benchmark::State& bench, int world, int index) {
  const WorldFile& f = courseWorld(world);
  Model model = makeModel(f.world, f.state, KernelChoice::Specialised);
  const ForceTerm& term = *model.forces.terms[static_cast<std::size_t>(index)];
  std::vector<double> force(kNumCoords);
  for (auto _ : bench) {
    term.addForces(f.state.p(), f.state.v(), nullptr, force.data());
    benchmark::DoNotOptimize(force.data());
  }
}

void Step(benchmark::State& bench, int world, KernelChoice choice, Integrator integrator) {
  const WorldFile& f = courseWorld(world);
  Model model = makeModel(f.world, f.state, choice);
  State state = f.state;
  Stepper stepper(integrator);
  long long steps = 0;
  for (auto _ : bench) {
    stepper.step(model, state, f.run.dt);
    // Back to the start now and then, so that every world is timed in its own regime.
    if (++steps % 1000 == 0) state = f.state;
  }
}

void WorldLoading(benchmark::State& bench) {
  const std::string path = std::string(JELLO_WORLD_DIR) + "/rotate.w";
  for (auto _ : bench) benchmark::DoNotOptimize(readWorldFile(path));
}

void registerAll() {
  for (int w = 0; w < static_cast<int>(std::size(kWorlds)); ++w) {
    for (auto [choice, name] : {std::pair{KernelChoice::Specialised, "specialised"},
                                {KernelChoice::General, "general"}}) {
      benchmark::RegisterBenchmark((std::string("Forces/") + kWorlds[w] + "/" + name).c_str(),
                                   Forces, w, choice)
          ->Unit(benchmark::kMicrosecond);
      benchmark::RegisterBenchmark((std::string("StepRK4/") + kWorlds[w] + "/" + name).c_str(),
                                   Step, w, choice, Integrator::RK4)
          ->Unit(benchmark::kMicrosecond);
    }
  }
  for (int w = 0; w < static_cast<int>(std::size(kWorlds)); ++w) {
    const WorldFile& f = courseWorld(w);
    const Model model = makeModel(f.world, f.state, KernelChoice::Specialised);
    for (std::size_t t = 0; t < model.forces.terms.size(); ++t) {
      std::vector<std::string> kept, leftOut;
      model.forces.terms[t]->summarise(&kept, &leftOut);
      const std::string name = kept.empty() ? std::to_string(t) : kept.front();
      benchmark::RegisterBenchmark(
          (std::string("Term/") + kWorlds[w] + "/" + std::to_string(t) + " " + name).c_str(), Term,
          w, static_cast<int>(t))
          ->Unit(benchmark::kMicrosecond);
    }
  }
  for (Integrator integrator : {Integrator::Euler, Integrator::Midpoint, Integrator::Symplectic,
                                Integrator::Verlet, Integrator::RK45}) {
    benchmark::RegisterBenchmark((std::string("Step/rotate/") + integratorName(integrator)).c_str(),
                                 Step, 0, KernelChoice::Specialised, integrator)
        ->Unit(benchmark::kMicrosecond);
  }
  benchmark::RegisterBenchmark("WorldLoading/rotate", WorldLoading)->Unit(benchmark::kMillisecond);
}

}  // namespace

int main(int argc, char** argv) {
  registerAll();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
