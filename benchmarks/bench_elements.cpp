// Google Benchmark: the finite elements' force (model/elements.h) against the springs' on the
// same lattice, per point: an 8^3 and a 16^3 jelly (spacing 0.1 m, the same shaken state), as
// springs, fixed corotated and stable Neo-Hookean elements, with their dampers on (Rayleigh's
// stiffness damping for the elements, the springs' dampers).
#include <benchmark/benchmark.h>

#include <random>
#include <string>
#include <vector>

#include "io/scenereader.h"
#include "solver/physics.h"

namespace {

using namespace jello;

const char* const kMaterials[] = {"springs", "corotated", "neohookean"};
const int kSides[] = {8, 16};

struct ElementScene {
  WorldFile file;
  Model model;
  std::vector<double> force;
};

ElementScene& sceneOf(int material, int side) {
  static std::vector<ElementScene> scenes(std::size(kMaterials) * std::size(kSides));
  ElementScene& s = scenes[material * std::size(kSides) + (side == 8 ? 0 : 1)];
  if (!s.force.empty()) return s;
  std::string text = "[bounds]\npresent = false\n[jelly]\nshape = \"lattice\"\nsize = [" +
                     std::to_string(side) + ", " + std::to_string(side) + ", " +
                     std::to_string(side) + "]\nspacing = 0.1\n";
  if (material == 0)
    text += "stiffness = 300\ndamping = 0.5\n";
  else
    text += std::string("material = \"") + kMaterials[material] +
            "\"\nyoungs_modulus = 1e4\npoisson_ratio = 0.45\ndensity = 1000\n"
            "stiffness_damping = 0.002\n";
  s.file = parseScene(text, "bench.toml", "");
  const int n = s.file.state.points();
  std::mt19937 random(3);
  std::uniform_real_distribution<double> jitter(-0.01, 0.01);
  for (int c = 0; c < 3 * n; ++c) {
    s.file.state.p()[c] += jitter(random);
    s.file.state.v()[c] = 10 * jitter(random);
  }
  s.model = makeModel(s.file.world, s.file.state);
  s.force.resize(3 * n);
  return s;
}

// One force evaluation of the whole scene (every term; here the springs or the elements alone).
void BM_ElasticForce(benchmark::State& bench) {
  const int material = static_cast<int>(bench.range(0)), side = static_cast<int>(bench.range(1));
  ElementScene& s = sceneOf(material, side);
  for (auto _ : bench) {
    computeForces(s.model, s.file.state.p(), s.file.state.v(), s.force.data());
    benchmark::DoNotOptimize(s.force.data());
  }
  const int n = s.model.points();
  bench.SetLabel(std::string(kMaterials[material]) + ", " + std::to_string(n) + " points");
  bench.counters["ns_per_point"] = benchmark::Counter(
      double(n), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_ElasticForce)->ArgsProduct({{0, 1, 2}, {8, 16}})->Unit(benchmark::kMicrosecond);

}  // namespace
