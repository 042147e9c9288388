// A program of its own, because it replaces the global operator new to count allocations:
// nothing else (no GL driver, no other test) runs under that replacement.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "jellyscenes.h"
#include "solver/integrators.h"
#include "solver/physics.h"
#include "solver/simulation.h"
#include "test_support.h"

namespace {
std::atomic<long long> allocations{0};

void* counted(std::size_t size) {
  ++allocations;
  if (void* p = std::malloc(size ? size : 1)) return p;
  throw std::bad_alloc();
}
}  // namespace

void* operator new(std::size_t size) { return counted(size); }
void* operator new[](std::size_t size) { return counted(size); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

namespace jello {
namespace {

// After its first step, a Stepper allocates nothing: not the kernel, not the integrator.
TEST(Allocation, StepsAllocateNothingOnceStarted) {
  WorldFile f = readWorldFile(test::dataPath("rotate.w"));
  for (Integrator integrator : {Integrator::Euler, Integrator::Midpoint, Integrator::RK4,
                                Integrator::Symplectic, Integrator::Verlet, Integrator::RK45}) {
    Model model = makeModel(f.world, f.state);
    State state = f.state;
    Stepper stepper(integrator);
    stepper.step(model, state, 2e-4);
    const long long before = allocations.load();
    for (int s = 0; s < 50; ++s) stepper.step(model, state, 2e-4);
    EXPECT_EQ(allocations.load() - before, 0) << integratorName(integrator);
  }
}

// Nor does the loop every run steps through: its checks, the energy bound included (every 8th
// step of rotate.w), allocate nothing either.
TEST(Allocation, ASimulationAdvancesWithoutAllocatingOnceStarted) {
  WorldFile f = readWorldFile(test::dataPath("rotate.w"));
  Model model = makeModel(f.world, f.state);
  for (Integrator integrator : {Integrator::Euler, Integrator::Midpoint, Integrator::RK4,
                                Integrator::Symplectic, Integrator::Verlet, Integrator::RK45}) {
    Simulation simulation(model, f.state, integrator, 2e-4);
    ASSERT_TRUE(simulation.advance(1).ran());
    const long long before = allocations.load();
    const bool ran = simulation.advance(50).ran();
    EXPECT_EQ(allocations.load() - before, 0) << integratorName(integrator);
    EXPECT_TRUE(ran) << integratorName(integrator);
  }
}

// Two jellies pressed together: the contact between them (its broad phase, its pairs) reuses its
// buffers, so that steps and the run's checks allocate nothing once they have grown to the most
// pairs in contact yet.
TEST(Allocation, ContactBetweenJelliesAllocatesNothingOnceStarted) {
  WorldFile f = test::scene(test::kHeadOn);
  const int n = f.state.points();
  for (int q = f.world.scene->body->partFirst[1]; q < n; ++q) {
    f.state.p()[q] -= 0.12;  // 2 cm into the first jelly's reach, at rest
    f.state.v()[q] = 0;
  }
  for (int q = 0; q < f.world.scene->body->partFirst[1]; ++q) f.state.v()[q] = 0;
  Model model = makeModel(f.world, f.state);
  Simulation simulation(model, f.state, Integrator::RK4, 2e-4);
  // The buffers grow while the touching spreads (more pairs than ever before), then hold.
  ASSERT_TRUE(simulation.advance(30).ran());
  const long long before = allocations.load();
  EXPECT_TRUE(simulation.advance(50).ran());
  EXPECT_EQ(allocations.load() - before, 0);
  EXPECT_GT(test::contactTerm(model)->contacts(simulation.state().p()).size(), 10u);
}

}  // namespace
}  // namespace jello
