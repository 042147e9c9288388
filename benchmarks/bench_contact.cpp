// Google Benchmark: contact between bodies (model/bodycontact.h) against the points: 2 to 16
// jellies of 8^3 and two of 24^3, each touching its neighbours face to face; the broad phase
// alone (the pairs found), the contact term's forces, and one RK4 step of the whole scene.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "io/scenereader.h"
#include "model/bodycontact.h"
#include "solver/integrators.h"
#include "solver/physics.h"

namespace {

using namespace jello;

struct Case {
  int bodies, side;  // jellies, points along each edge of each
};
const Case kCases[] = {{2, 8}, {4, 8}, {8, 8}, {16, 8}, {2, 24}};

// The jellies in a row of rows (4 a row), spacing 0.1 m, read 0.11 m apart (the reader refuses
// overlapping starts), then moved 0.03 m closer: every facing pair of surface points in contact.
struct Scene {
  WorldFile file;
  Model model;
  const BodyContactTerm* contact = nullptr;
};

Scene& sceneOf(int index) {
  static std::vector<Scene> scenes(std::size(kCases));
  Scene& s = scenes[index];
  if (s.contact) return s;
  const Case c = kCases[index];
  const double edge = 0.1 * (c.side - 1), pitch = edge + 0.11;
  std::string text = "[bounds]\npresent = false\n[contact]\nstiffness = 2000\ndamping = 0.5\n";
  for (int b = 0; b < c.bodies; ++b)
    text += "[[jelly]]\nshape = \"lattice\"\nsize = [" + std::to_string(c.side) + ", " +
            std::to_string(c.side) + ", " + std::to_string(c.side) +
            "]\nspacing = 0.1\noffset = [" + std::to_string(pitch * (b % 4)) + ", " +
            std::to_string(pitch * (b / 4)) + ", 0]\n";
  s.file = parseScene(text, "bench.toml", "");
  const Body& body = *s.file.world.scene->body;
  const int n = body.count();
  for (int q = 0; q < n; ++q) {
    const int b = body.partOf(q);
    s.file.state.p()[q] -= 0.03 * (b % 4);
    s.file.state.p()[n + q] -= 0.03 * (b / 4);
  }
  s.model = makeModel(s.file.world, s.file.state);
  for (const auto& term : s.model.forces.terms)
    if (auto* contact = dynamic_cast<const BodyContactTerm*>(term.get())) s.contact = contact;
  return s;
}

void label(benchmark::State& bench, const Scene& s, int index) {
  bench.SetLabel(std::to_string(kCases[index].bodies) + " x " + std::to_string(kCases[index].side) +
                 "^3, " + std::to_string(s.model.points()) + " points, " +
                 std::to_string(s.contact->contacts(s.file.state.p()).size()) + " pairs");
}

void BroadPhase(benchmark::State& bench, int index) {
  Scene& s = sceneOf(index);
  for (auto _ : bench) benchmark::DoNotOptimize(s.contact->contacts(s.file.state.p()));
  label(bench, s, index);
}

void ContactForces(benchmark::State& bench, int index) {
  Scene& s = sceneOf(index);
  std::vector<double> force(s.model.coords());
  for (auto _ : bench) {
    s.contact->addForces(s.file.state.p(), s.file.state.v(), nullptr, force.data());
    benchmark::DoNotOptimize(force.data());
  }
  label(bench, s, index);
}

void Rk4Step(benchmark::State& bench, int index) {
  Scene& s = sceneOf(index);
  State state = s.file.state;
  Stepper stepper(Integrator::RK4);
  for (auto _ : bench) {
    state = s.file.state;
    stepper.step(s.model, state, 0.0002);
  }
  label(bench, s, index);
}

void registerAll() {
  for (int i = 0; i < static_cast<int>(std::size(kCases)); ++i) {
    const std::string n = std::to_string(kCases[i].bodies) + "x" + std::to_string(kCases[i].side);
    benchmark::RegisterBenchmark(("BroadPhase/" + n).c_str(), BroadPhase, i)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("ContactForces/" + n).c_str(), ContactForces, i)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("Rk4Step/" + n).c_str(), Rk4Step, i)
        ->Unit(benchmark::kMicrosecond);
  }
}

const bool kRegistered = (registerAll(), true);

}  // namespace
