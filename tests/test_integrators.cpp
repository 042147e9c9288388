// Time stepping: conservation laws, energy, order of convergence (SPEC.md section 2).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "integrators.h"
#include "physics.h"
#include "test_support.h"

namespace jello {
namespace {

Vec3 cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

// The rest lattice centred on the origin, every point jittered, drifting and spinning.
State tumblingCube(unsigned seed, double jitter) {
  State state = test::restLattice();
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> any(-1, 1);
  Vec3 drift{0.3, -0.2, 0.1}, spin{1.5, -2, 3};
  for (int q = 0; q < kNumPoints; ++q) {
    Vec3 r = load(state.p(), q) - Vec3{0.5, 0.5, 0.5} + jitter * Vec3{any(random), any(random), any(random)};
    store(state.p(), q, r);
    store(state.v(), q, drift + cross(spin, r) + 0.2 * Vec3{any(random), any(random), any(random)});
  }
  return state;
}

bool insideBox(const State& state) {
  for (int c = 0; c < kNumCoords; ++c)
    if (std::fabs(state.p()[c]) > kBoxHalfSize) return false;
  return true;
}

Vec3 momentum(const State& s, double mass) {
  Vec3 total;
  for (int q = 0; q < kNumPoints; ++q) total += mass * load(s.v(), q);
  return total;
}

Vec3 angularMomentum(const State& s, double mass) {
  Vec3 total;
  for (int q = 0; q < kNumPoints; ++q) total += mass * cross(load(s.p(), q), load(s.v(), q));
  return total;
}

double energy(const Model& model, const State& s) {
  double e = 0;
  for (int q = 0; q < kNumPoints; ++q) e += 0.5 * model.world.mass * dot(load(s.v(), q), load(s.v(), q));
  for (const Spring& sp : model.springs) {
    double stretch = length(load(s.p(), sp.a) - load(s.p(), sp.b)) - sp.rest;
    e += 0.5 * model.world.kElastic * stretch * stretch;
  }
  return e;
}

TEST(Conservation, MomentumAndAngularMomentumWithoutWallsPlaneOrField) {
  World w = test::springsOnlyWorld();  // damped springs: internal forces only
  // Momentum is a linear invariant, which RK4 keeps to rounding; angular momentum is quadratic
  // and RK4 keeps it only to its truncation error, O(dt^4): 9e-8 at dt = 1e-4, 2e-10 here.
  w.dt = 2e-5;
  State state = tumblingCube(11, 0.02);
  Model model = makeModel(w, state);
  Vec3 p0 = momentum(state, w.mass), l0 = angularMomentum(state, w.mass);
  Workspace ws;
  double worstP = 0, worstL = 0;
  for (int s = 0; s < 1000; ++s) {
    step(model, Integrator::RK4, w.dt, state, ws);
    ASSERT_TRUE(insideBox(state)) << "the cube touched a wall at step " << s;
    worstP = std::max(worstP, length(momentum(state, w.mass) - p0) / length(p0));
    worstL = std::max(worstL, length(angularMomentum(state, w.mass) - l0) / length(l0));
  }
  EXPECT_LT(worstP, 1e-12);
  EXPECT_LT(worstL, 1e-9);
  // The cube did move and deform: the test measured something.
  EXPECT_GT(length(load(state.p(), 0) - load(tumblingCube(11, 0.02).p(), 0)), 1e-3);
}

TEST(Conservation, UndampedSpringsKeepRk4EnergyOverOneSecond) {
  World w = test::springsOnlyWorld();
  w.dElastic = 0;
  // RK4's energy error per unit time goes as dt^5: 7e-5 at dt = 5e-5, 2e-7 here.
  w.dt = 1.5e-5;
  State state = tumblingCube(12, 0.03);
  Model model = makeModel(w, state);
  const double e0 = energy(model, state);
  Workspace ws;
  double worst = 0;
  const long steps = std::lround(1.0 / w.dt);
  for (long s = 0; s < steps; ++s) {
    step(model, Integrator::RK4, w.dt, state, ws);
    if (s % 100 == 0) worst = std::max(worst, std::fabs(energy(model, state) - e0) / e0);
  }
  ASSERT_TRUE(insideBox(state));
  worst = std::max(worst, std::fabs(energy(model, state) - e0) / e0);
  std::printf("RK4 relative energy drift over 1 s at dt=%g: %.3g\n", w.dt, worst);
  EXPECT_LT(worst, 1e-6);
}

TEST(Conservation, DampedSpringsLoseEnergy) {
  World w = test::springsOnlyWorld();
  w.dElastic = 1;
  State state = tumblingCube(13, 0.03);
  Model model = makeModel(w, state);
  Workspace ws;
  double previous = energy(model, state);
  for (int s = 0; s < 200; ++s) {
    step(model, Integrator::RK4, w.dt, state, ws);
    double e = energy(model, state);
    ASSERT_LE(e, previous * (1 + 1e-12)) << "energy grew at step " << s;
    previous = e;
  }
  EXPECT_LT(previous, 0.9 * energy(model, tumblingCube(13, 0.03)));
}

TEST(Integrators, EulerIsTheStartersExplicitEuler) {
  WorldFile f = readWorldFile(test::dataPath("jello.w"));
  Model model = makeModel(f.world, f.state);
  State before = f.state, after = f.state;
  Workspace ws;
  const double dt = 1e-4;
  step(model, Integrator::Euler, dt, after, ws);
  std::vector<double> dydt(2 * kNumCoords);
  derivative(model, before.y.data(), dydt.data());
  for (int c = 0; c < kNumCoords; ++c) {
    ASSERT_EQ(after.p()[c], before.p()[c] + dt * before.v()[c]);  // old velocity
    ASSERT_EQ(after.v()[c], before.v()[c] + dt * dydt[kNumCoords + c]);
  }
}

TEST(Integrators, Rk4OnALinearEquationIsItsTaylorPolynomial) {
  // y' = lambda y: one RK4 step multiplies y by 1 + z + z^2/2 + z^3/6 + z^4/24, z = lambda dt.
  // A wrong k3 (a common mistake) changes the z^3 or z^4 term.
  const double lambda = -3, dt = 0.1, z = lambda * dt;
  DerivativeFn f = [&](const double* y, double* dydt) { dydt[0] = lambda * y[0]; };
  std::vector<double> y{1};
  Workspace ws;
  rk4Step(f, y, dt, ws);
  EXPECT_NEAR(y[0], 1 + z + z * z / 2 + z * z * z / 6 + z * z * z * z / 24, 1e-15);
}

// A smooth scene: a deformed, damped cube in a smooth (single-cell, trilinear) field, far
// from the walls, no plane.
struct SmoothScene {
  Model model;
  State start;
};

SmoothScene smoothScene() {
  World w = test::springsOnlyWorld();
  w.kElastic = 50;
  w.dElastic = 0.05;
  w.field.resolution = 2;
  for (int node = 0; node < 8; ++node) {
    w.field.forces.insert(w.field.forces.end(),
                          {0.01 * (node & 1), -0.02 * ((node >> 1) & 1), 0.015 * ((node >> 2) & 1) - 0.01});
  }
  State start = tumblingCube(21, 0.04);
  return {makeModel(w, start), start};
}

State runFor(const SmoothScene& scene, Integrator integrator, double dt, double time) {
  State state = scene.start;
  Workspace ws;
  const long steps = std::lround(time / dt);
  for (long s = 0; s < steps; ++s) step(scene.model, integrator, dt, state, ws);
  return state;
}

// Least-squares slope of log(error) against log(dt).
double fittedOrder(const std::vector<double>& dts, const std::vector<double>& errors) {
  double n = dts.size(), sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < dts.size(); ++i) {
    double x = std::log(dts[i]), y = std::log(errors[i]);
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

struct OrderCase {
  Integrator integrator;
  double order;
  double largestDt;
};

void PrintTo(const OrderCase& c, std::ostream* os) { *os << integratorName(c.integrator); }

class ConvergenceOrder : public ::testing::TestWithParam<OrderCase> {};

TEST_P(ConvergenceOrder, MatchesTheory) {
  const OrderCase& c = GetParam();
  const double time = 0.04;
  SmoothScene scene = smoothScene();
  State reference = runFor(scene, Integrator::RK4, 2.5e-6, time);
  ASSERT_TRUE(insideBox(reference));
  std::vector<double> dts, errors;
  for (int level = 0; level < 4; ++level) {
    double dt = c.largestDt / (1 << level);
    State s = runFor(scene, c.integrator, dt, time);
    dts.push_back(dt);
    errors.push_back(test::rmsDistance(s.p(), reference.p()));
    std::printf("%s dt=%g rms error %.3e\n", integratorName(c.integrator), dt, errors.back());
  }
  double order = fittedOrder(dts, errors);
  std::printf("%s fitted order %.3f\n", integratorName(c.integrator), order);
  EXPECT_NEAR(order, c.order, 0.3);
}

INSTANTIATE_TEST_SUITE_P(Integrators, ConvergenceOrder,
                         ::testing::Values(OrderCase{Integrator::Euler, 1, 2e-4}, OrderCase{Integrator::RK4, 4, 2e-3}),
                         [](const auto& info) { return std::string(integratorName(info.param.integrator)); });

}  // namespace
}  // namespace jello
