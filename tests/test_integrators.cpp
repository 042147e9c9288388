// Time stepping: conservation laws, energy, order of convergence (docs/physics.md).
#include <gtest/gtest.h>

#include <Eigen/IterativeLinearSolvers>
#include <cctype>
#include <cmath>
#include <random>
#include <set>
#include <sstream>
#include <stdexcept>

#include "analysis/stability.h"
#include "solver/integrators.h"
#include "solver/jacobian.h"
#include "solver/physics.h"
#include "test_support.h"

namespace jello {
namespace {

// The rest lattice centred on the origin, every point jittered, drifting and spinning.
State tumblingCube(unsigned seed, double jitter) {
  State state = test::restLattice();
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> any(-1, 1);
  Vec3 drift{0.3, -0.2, 0.1}, spin{1.5, -2, 3};
  for (int q = 0; q < kNumPoints; ++q) {
    Vec3 r = load(state.p(), q) - Vec3{0.5, 0.5, 0.5} +
             jitter * Vec3{any(random), any(random), any(random)};
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
  for (int q = 0; q < kNumPoints; ++q)
    e += 0.5 * model.world.mass * dot(load(s.v(), q), load(s.v(), q));
  for (const Spring& sp : model.springs()) {
    double stretch = length(load(s.p(), sp.a) - load(s.p(), sp.b)) - sp.rest;
    e += 0.5 * model.world.kElastic * stretch * stretch;
  }
  return e;
}

TEST(Conservation, MomentumAndAngularMomentumWithoutWallsPlaneOrField) {
  World w = test::springsOnlyWorld();  // damped springs: internal forces only
  // Momentum is a linear invariant, which RK4 keeps to rounding; angular momentum is quadratic
  // and RK4 keeps it only to its truncation error, O(dt^4): 9e-8 at dt = 1e-4, 2e-10 here.
  const double dt = 2e-5;
  State state = tumblingCube(11, 0.02);
  Model model = makeModel(w, state);
  Vec3 p0 = momentum(state, w.mass), l0 = angularMomentum(state, w.mass);
  Stepper stepper(Integrator::RK4);
  double worstP = 0, worstL = 0;
  for (int s = 0; s < 1000; ++s) {
    stepper.step(model, state, dt);
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
  const double dt = 1.5e-5;
  State state = tumblingCube(12, 0.03);
  Model model = makeModel(w, state);
  const double e0 = energy(model, state);
  Stepper stepper(Integrator::RK4);
  double worst = 0;
  const long steps = std::lround(1.0 / dt);
  for (long s = 0; s < steps; ++s) {
    stepper.step(model, state, dt);
    if (s % 100 == 0) worst = std::max(worst, std::fabs(energy(model, state) - e0) / e0);
  }
  ASSERT_TRUE(insideBox(state));
  worst = std::max(worst, std::fabs(energy(model, state) - e0) / e0);
  std::printf("RK4 relative energy drift over 1 s at dt=%g: %.3g\n", dt, worst);
  EXPECT_LT(worst, 1e-6);
}

TEST(Conservation, DampedSpringsLoseEnergy) {
  World w = test::springsOnlyWorld();
  w.dElastic = 1;
  State state = tumblingCube(13, 0.03);
  Model model = makeModel(w, state);
  Stepper stepper(Integrator::RK4);
  double previous = energy(model, state);
  for (int s = 0; s < 200; ++s) {
    stepper.step(model, state, test::kSpringsOnlyDt);
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
  Stepper stepper(Integrator::Euler);
  const double dt = 1e-4;
  stepper.step(model, after, dt);
  std::vector<double> dydt(2 * kNumCoords);
  derivative(model, before.y.data(), dydt.data());
  for (int c = 0; c < kNumCoords; ++c) {
    ASSERT_EQ(after.p()[c], before.p()[c] + dt * before.v()[c]);  // old velocity
    ASSERT_EQ(after.v()[c], before.v()[c] + dt * dydt[kNumCoords + c]);
  }
}

TEST(Integrators, SymplecticEulerMovesWithTheNewVelocity) {
  WorldFile f = readWorldFile(test::dataPath("jello.w"));
  Model model = makeModel(f.world, f.state);
  State before = f.state, after = f.state;
  Stepper stepper(Integrator::Symplectic);
  const double dt = 1e-4;
  stepper.step(model, after, dt);
  std::vector<double> dydt(2 * kNumCoords);
  derivative(model, before.y.data(), dydt.data());
  for (int c = 0; c < kNumCoords; ++c) {
    double v = before.v()[c] + dt * dydt[kNumCoords + c];
    ASSERT_EQ(after.v()[c], v);
    ASSERT_EQ(after.p()[c], before.p()[c] + dt * v);
  }
}

// y' = lambda y: one step multiplies y by the method's stability polynomial R(z), z = lambda dt.
// A wrong stage (RK4's k3 is a common mistake) changes a coefficient.
TEST(Integrators, OneStepOnALinearEquationIsTheStabilityPolynomial) {
  const double lambda = -3, dt = 0.1, z = lambda * dt;
  OdeSystem system;
  system.derivative = [&](const double* y, double* dydt) { dydt[0] = lambda * y[0]; };
  const std::pair<Integrator, double> expected[] = {
      {Integrator::Euler, 1 + z},
      {Integrator::Midpoint, 1 + z + z * z / 2},
      {Integrator::RK4, 1 + z + z * z / 2 + z * z * z / 6 + z * z * z * z / 24},
  };
  for (auto [integrator, factor] : expected) {
    std::vector<double> y{1};
    Stepper stepper(integrator);
    stepper.step(system, y, dt);
    EXPECT_NEAR(y[0], factor, 1e-15) << integratorName(integrator);
  }
}

// The harmonic oscillator x'' = -x as y = [x; v]: Verlet's and the symplectic Euler's one-step
// maps, by hand.
TEST(Integrators, VerletAndSymplecticEulerOnTheHarmonicOscillator) {
  OdeSystem system;
  system.derivative = [](const double* y, double* dydt) {
    dydt[0] = y[1];
    dydt[1] = -y[0];
  };
  const double h = 0.1;
  std::vector<double> y{1, 0.5};
  Stepper verlet(Integrator::Verlet);
  verlet.step(system, y, h);
  double x1 = 1 + h * 0.5 - h * h / 2 * 1;
  EXPECT_NEAR(y[0], x1, 1e-15);
  EXPECT_NEAR(y[1], 0.5 + h / 2 * (-1 - x1), 1e-15);
  std::vector<double> s{1, 0.5};
  Stepper symplectic(Integrator::Symplectic);
  symplectic.step(system, s, h);
  EXPECT_NEAR(s[1], 0.5 - h, 1e-15);
  EXPECT_NEAR(s[0], 1 + h * (0.5 - h), 1e-15);
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
    w.field.forces.insert(w.field.forces.end(), {0.01 * (node & 1), -0.02 * ((node >> 1) & 1),
                                                 0.015 * ((node >> 2) & 1) - 0.01});
  }
  // Stretched and squeezed, spinning, drifting: the smooth, slow deformation of a jello, with
  // a little jitter so that every mode is in play.
  State start = tumblingCube(21, 0.002);
  for (int q = 0; q < kNumPoints; ++q) {
    Vec3 p = load(start.p(), q);
    store(start.p(), q, {1.1 * p.x, 0.95 * p.y, p.z});
  }
  return {makeModel(w, start), start};
}

State runFor(const SmoothScene& scene, Stepper& stepper, double dt, double time) {
  State state = scene.start;
  const long steps = std::lround(time / dt);
  for (long s = 0; s < steps; ++s) stepper.step(scene.model, state, dt);
  return state;
}

State runFor(const SmoothScene& scene, Integrator integrator, double dt, double time) {
  Stepper stepper(integrator);
  return runFor(scene, stepper, dt, time);
}

const double kSmoothTime = 0.04;

const State& smoothReference() {
  static const State reference = runFor(smoothScene(), Integrator::RK4, 2.5e-6, kSmoothTime);
  return reference;
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
  double largestDt;
};

void PrintTo(const OrderCase& c, std::ostream* os) { *os << integratorName(c.integrator); }

class ConvergenceOrder : public ::testing::TestWithParam<OrderCase> {};

TEST_P(ConvergenceOrder, MatchesTheory) {
  const OrderCase& c = GetParam();
  SmoothScene scene = smoothScene();
  const State& reference = smoothReference();
  ASSERT_TRUE(insideBox(reference));
  std::vector<double> dts, errors;
  for (int level = 0; level < 4; ++level) {
    double dt = c.largestDt / (1 << level);
    State s = runFor(scene, c.integrator, dt, kSmoothTime);
    dts.push_back(dt);
    errors.push_back(test::rmsDistance(s.p(), reference.p()));
    std::printf("%s dt=%g rms error %.3e\n", integratorName(c.integrator), dt, errors.back());
  }
  double order = fittedOrder(dts, errors);
  std::printf("%s fitted order %.3f (theory %d)\n", integratorName(c.integrator), order,
              orderOf(c.integrator));
  EXPECT_NEAR(order, orderOf(c.integrator), 0.3);
}

INSTANTIATE_TEST_SUITE_P(
    Integrators, ConvergenceOrder,
    ::testing::Values(OrderCase{Integrator::Euler, 2e-4}, OrderCase{Integrator::Symplectic, 2e-4},
                      OrderCase{Integrator::Midpoint, 1e-3}, OrderCase{Integrator::Verlet, 1e-3},
                      OrderCase{Integrator::RK4, 2e-3}, OrderCase{Integrator::Implicit, 1e-3}),
    [](const auto& testInfo) { return std::string(integratorName(testInfo.param.integrator)); });

TEST(Rk45, MeetsItsToleranceWithinAFactorOfTen) {
  SmoothScene scene = smoothScene();
  const State& reference = smoothReference();
  for (double tolerance : {1e-5, 1e-7, 1e-9}) {
    Stepper stepper(Integrator::RK45, {tolerance, tolerance});
    State s = runFor(scene, stepper, 0.01, kSmoothTime);  // dt: the first and largest step
    double error = test::rmsDistance(s.p(), reference.p());
    std::printf("RK45 tolerance %g: rms error %.3e, %lld steps, %lld rejected, %lld evaluations\n",
                tolerance, error, stepper.stats().steps, stepper.stats().rejected,
                stepper.stats().evaluations);
    EXPECT_LT(error, 10 * tolerance);
    EXPECT_GT(stepper.stats().steps, 4) << "the steps did not adapt";
  }
}

TEST(Rk45, TheErrorNormNeitherOverflowsNorUnderflows) {
  const double ordinary[] = {3, 4}, huge[] = {3e200, 4e200}, tiny[] = {3e-200, 4e-200};
  EXPECT_EQ(rmsNorm(ordinary, 2), std::sqrt(12.5)) << "the usual formula, bit for bit";
  EXPECT_NEAR(rmsNorm(huge, 2), std::sqrt(12.5) * 1e200, 1e-15 * 1e200);    // the squares overflow
  EXPECT_NEAR(rmsNorm(tiny, 2), std::sqrt(12.5) * 1e-200, 1e-15 * 1e-200);  // ... or underflow
  const double infinite[] = {1, INFINITY}, notANumber[] = {NAN, 1e300};
  EXPECT_EQ(rmsNorm(infinite, 2), INFINITY);
  EXPECT_TRUE(std::isnan(rmsNorm(notANumber, 2)));
}

TEST(Rk45, AToleranceBelowWhatDoublesResolveIsRejectedNeverAccepted) {
  // rtol = atol = 1e-300: the scaled errors are about 1e290, their squares overflow. Before,
  // the infinite norm was taken for a blown-up state and the step of 0.01 s accepted
  // unchecked (the run diverged at step 2).
  WorldFile f = readWorldFile(test::dataPath("rotate.w"));
  Model model = makeModel(f.world, f.state);
  Stepper stepper(Integrator::RK45, {1e-300, 1e-300});
  State s = f.state;
  stepper.step(model, s, 0.01);
  EXPECT_EQ(stepper.stats().steps, 0) << "no substep meets 1e-300";
  // Shrunk by the controller's 0.2 from 0.01 s to the smallest substep, 3.6e-17 s, then given up.
  EXPECT_EQ(stepper.stats().rejected, 22);
  EXPECT_EQ(stepper.stats().failed, 1);
  EXPECT_TRUE(std::isnan(s.y[0])) << "an abandoned step is never mistaken for a result";
  // A tolerance double arithmetic can still resolve, 1e-14, is met in small substeps.
  Stepper fine(Integrator::RK45, {1e-14, 1e-14});
  State t = f.state;
  fine.step(model, t, 0.01);
  EXPECT_EQ(fine.stats().failed, 0);
  EXPECT_GT(fine.stats().steps, 100);
  EXPECT_EQ(findDivergedPoint(t), -1);
}

TEST(Conservation, SymplecticSchemesKeepTheEnergyOfAnUndampedCubeForTenSeconds) {
  World w = test::springsOnlyWorld();
  w.kElastic = 100;
  w.dElastic = 0;
  // Stretched along x, squeezed along y, spinning: energy in the cube's slow modes, as a
  // bouncing jello has it. No drift, so that it never reaches a wall, whose springs and dampers
  // would take energy.
  State start = tumblingCube(14, 0);
  Vec3 drift = (1.0 / (kNumPoints * w.mass)) * momentum(start, w.mass);
  for (int q = 0; q < kNumPoints; ++q) {
    Vec3 p = load(start.p(), q);
    store(start.p(), q, {1.1 * p.x, 0.95 * p.y, p.z});
    store(start.v(), q, load(start.v(), q) - drift);
  }
  Model model = makeModel(w, start);
  const double e0 = energy(model, start);
  // Stable steps. The symplectic Euler's energy oscillates by O(omega dt), Verlet's by
  // O((omega dt)^2): the first needs the smaller step to stay within 1%.
  const std::pair<Integrator, double> runs[] = {
      {Integrator::Symplectic, 5e-5}, {Integrator::Verlet, 2e-4}, {Integrator::Euler, 2e-4}};
  for (auto [integrator, dt] : runs) {
    State state = start;
    Stepper stepper(integrator);
    double worst = 0;
    const long steps = std::lround(10.0 / dt);
    for (long s = 1; s <= steps && findDivergedPoint(state) < 0; ++s) {
      stepper.step(model, state, dt);
      if (s % 500 == 0) worst = std::max(worst, std::fabs(energy(model, state) - e0) / e0);
    }
    double final = energy(model, state);
    std::printf("%s at dt=%g: energy after 10 s %.6g (start %.6g), worst relative change %.3g\n",
                integratorName(integrator), dt, final, e0, worst);
    if (integrator == Integrator::Euler) {
      EXPECT_FALSE(final < 1.5 * e0) << "explicit Euler's energy should grow";
    } else {
      EXPECT_TRUE(insideBox(state)) << integratorName(integrator);
      EXPECT_LT(worst, 0.01) << integratorName(integrator);
    }
  }
}

// RK4's largest stable step on a world, by bisection on real runs (0.1 s).
double largestStableStep(const Model& model, const State& start, Integrator integrator) {
  auto stable = [&](double dt) {
    State s = start;
    Stepper stepper(integrator);
    for (long i = 0, n = std::lround(0.1 / dt); i < n; ++i) {
      stepper.step(model, s, dt);
      if (findDivergedPoint(s) >= 0) return false;
    }
    return true;
  };
  double low = 1e-6, high = 1e-2;
  for (int i = 0; i < 10; ++i) {  // to within 1% of the limit
    double middle = std::sqrt(low * high);
    (stable(middle) ? low : high) = middle;
  }
  return low;
}

TEST(Implicit, StableAtTenTimesRk4sLargestStableStepOnAStiffWorld) {
  World w = test::springsOnlyWorld();
  w.kElastic = 1e4;
  State start = tumblingCube(15, 0.03);
  Model model = makeModel(w, start);
  const double rk4Limit = largestStableStep(model, start, Integrator::RK4);
  std::printf("RK4's largest stable step with kElastic 1e4: %.3g s\n", rk4Limit);
  ASSERT_GT(rk4Limit, 1e-5);
  State state = start;
  Stepper stepper(Integrator::Implicit);
  const double dt = 10 * rk4Limit;
  for (long i = 0, n = std::lround(0.5 / dt); i < n; ++i) {
    stepper.step(model, state, dt);
    ASSERT_LT(findDivergedPoint(state), 0) << "step " << i;
  }
  // Backward Euler dissipates: the vibration is gone, the motion bounded.
  EXPECT_LT(energy(model, state), energy(model, start));
  std::printf("IMPLICIT at %.3g s: %lld Newton iterations over %lld steps\n", dt,
              stepper.stats().newtonIterations, stepper.stats().steps);
}

// A world and state that exercise every term: deformed springs with dampers, a point past two
// walls, points across the plane, a non-uniform field of random nodes (the pull is the caller's).
std::pair<World, State> everyTermCase(std::mt19937_64& random, unsigned tumble) {
  World w = test::springsOnlyWorld();
  w.dElastic = 0.8;
  w.hasPlane = true;
  w.plane = {1, 1, 1, 0.6};
  w.field.resolution = 3;
  std::uniform_real_distribution<double> any(-0.05, 0.05);
  for (int i = 0; i < 27 * 3; ++i) w.field.forces.push_back(any(random));
  State state = tumblingCube(tumble, 0.05);
  for (int c = 0; c < kNumCoords; ++c)
    state.p()[c] += 0.3;                    // centroid on the plane's positive side
  store(state.p(), 0, {-2.1, 2.05, 0.2});   // past two walls
  store(state.p(), 1, {-0.5, -0.5, -0.5});  // across the plane
  return {w, state};
}

// Central differences of the total force against the analytic Jacobians, on a state that
// exercises every term: deformed springs with dampers, a point past two walls, points across
// the plane, a non-uniform field, the user's pull.
TEST(Implicit, JacobianMatchesCentralDifferencesOfTheForce) {
  std::mt19937_64 random(4);
  auto [w, state] = everyTermCase(random, 16);
  Model model = makeModel(w, state);
  Pull pull{100, {1, 1, 1}, 300};
  AccelerationJacobian jacobian;
  accelerationJacobian(model, state.p(), state.v(), &pull, &jacobian);
  Eigen::MatrixXd dAdp(jacobian.dAdp), dAdv(jacobian.dAdv);

  const double h = 1e-7;
  std::vector<double> up(kNumCoords), down(kNumCoords);
  double errorSquared = 0, normSquared = 0;
  for (int which = 0; which < 2; ++which) {
    const Eigen::MatrixXd& analytic = which == 0 ? dAdp : dAdv;
    for (int c = 0; c < kNumCoords; ++c) {
      State s = state;
      double* x = which == 0 ? s.p() : s.v();
      double saved = x[c];
      x[c] = saved + h;
      computeForces(model, s.p(), s.v(), up.data(), &pull);
      x[c] = saved - h;
      computeForces(model, s.p(), s.v(), down.data(), &pull);
      for (int r = 0; r < kNumCoords; ++r) {
        double numeric = (up[r] - down[r]) / (2 * h) / w.mass;
        errorSquared += (numeric - analytic(r, c)) * (numeric - analytic(r, c));
        normSquared += analytic(r, c) * analytic(r, c);
      }
    }
  }
  double relative = std::sqrt(errorSquared / normSquared);
  std::printf("Jacobian against central differences: relative error %.3g\n", relative);
  EXPECT_LT(relative, 1e-6);
}

// The Newton matrix's blocks make I - cv dA/dv - cp dA/dp of the Jacobians checked above against
// differences of the force, on a state with every term and the user's pull; and their product
// with a vector is the matrix's.
TEST(Implicit, NewtonBlocksAreTheIdentityLessTheScaledJacobians) {
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> any(-0.05, 0.05);
  auto [w, state] = everyTermCase(random, 17);
  Model model = makeModel(w, state);
  Pull pull{100, {1, 1, 1}, 300};
  const double cv = 0.01, cp = 1e-4;
  AccelerationJacobian jacobian;
  accelerationJacobian(model, state.p(), state.v(), &pull, &jacobian);
  NewtonBlocks newton;
  newtonBlocks(model, state.p(), state.v(), &pull, cv, cp, &newton);
  const Eigen::MatrixXd identity = Eigen::MatrixXd::Identity(kNumCoords, kNumCoords);
  const Eigen::MatrixXd expected =
      identity - cv * Eigen::MatrixXd(jacobian.dAdv) - cp * Eigen::MatrixXd(jacobian.dAdp);
  const Eigen::MatrixXd assembled(sparseOf(newton));
  const double relative = (assembled - expected).norm() / expected.norm();
  std::printf("Newton blocks against the Jacobians: relative difference %.3g\n", relative);
  EXPECT_LT(relative, 1e-14);
  Eigen::VectorXd x(kNumCoords), product(kNumCoords), diagonal(kNumCoords);
  for (double& e : x) e = any(random);
  newton.multiply(x.data(), product.data());
  EXPECT_LT((product - expected * x).norm(), 1e-14 * (expected * x).norm());
  newton.diagonal(diagonal.data());
  EXPECT_LT((diagonal - expected.diagonal()).norm(), 1e-14 * expected.diagonal().norm());
  // A second assembly at another state reuses the list of pairs and leaves nothing of the first.
  const State rest = test::restLattice();
  newtonBlocks(model, rest.p(), rest.v(), nullptr, cv, cp, &newton);
  accelerationJacobian(model, rest.p(), rest.v(), nullptr, &jacobian);
  EXPECT_LT((Eigen::MatrixXd(sparseOf(newton)) - identity + cv * Eigen::MatrixXd(jacobian.dAdv) +
             cp * Eigen::MatrixXd(jacobian.dAdp))
                .norm(),
            1e-14 * expected.norm());
}

// Each IMPLICIT step solves backward Euler, v' = v + dt a(p + dt v', v'), to its tolerance: the
// Newton update its residual still asks for is below 1e-12 (1 + |v'|), at steps from the small
// ones a user takes to T/16 of a report on rotate.w. At the small ones it takes one Jacobian a
// step (the Newton matrix kept for the update that confirms convergence, after a fixed-point first
// iterate).
TEST(Implicit, EachStepSolvesBackwardEulerToItsTolerance) {
  WorldFile f = readWorldFile(test::dataPath("rotate.w"));
  Model model = makeModel(f.world, f.state);
  for (double dt : {0.0625, 0.00390625, 1.220703125e-4}) {
    Stepper stepper(Integrator::Implicit);
    State state = f.state;
    std::vector<double> rate(2 * kNumCoords);
    Eigen::VectorXd residual(kNumCoords);
    NewtonBlocks newton;
    Eigen::BiCGSTAB<SparseMatrix> solver;
    solver.setTolerance(1e-14);
    double worst = 0;
    const int steps = dt > 0.01 ? 4 : 40;
    for (int s = 0; s < steps; ++s) {
      const State before = state;
      stepper.step(model, state, dt);
      derivative(model, state.y.data(), rate.data());
      for (int c = 0; c < kNumCoords; ++c) {
        residual[c] = state.v()[c] - before.v()[c] - dt * rate[kNumCoords + c];
        EXPECT_EQ(state.p()[c], before.p()[c] + dt * state.v()[c]);
      }
      newtonBlocks(model, state.p(), state.v(), nullptr, dt, dt * dt, &newton);
      const SparseMatrix matrix = sparseOf(newton);
      const Eigen::VectorXd update = solver.compute(matrix).solve(residual);
      const double largestVelocity =
          Eigen::Map<const Eigen::VectorXd>(state.v(), kNumCoords).cwiseAbs().maxCoeff();
      worst = std::max(worst, update.cwiseAbs().maxCoeff() / (1 + largestVelocity));
    }
    const StepStats& stats = stepper.stats();
    std::printf(
        "IMPLICIT dt=%g: largest update left %.3g (against 1 + |v|); %.2f Newton "
        "iterations, %.2f Jacobians a step\n",
        dt, worst, double(stats.newtonIterations) / steps, double(stats.jacobians) / steps);
    EXPECT_LT(worst, 1e-12) << dt;
    if (dt < 1e-3) {
      EXPECT_EQ(stats.jacobians, steps) << dt;
      EXPECT_EQ(stats.newtonIterations, 2 * steps) << dt;
    }
  }
}

// The table: a row per enumerator, in enum order, and names that read back as the integrator.
TEST(IntegratorTable, HasARowPerEnumeratorInOrderWhoseNameParsesBackInAnyCase) {
  std::set<std::string> names;
  for (int i = 0; i < kIntegratorCount; ++i) {
    const Integrator integrator = static_cast<Integrator>(i);
    const IntegratorInfo& row = integratorInfo(integrator);
    EXPECT_EQ(row.integrator, integrator) << i;
    EXPECT_STREQ(integratorName(integrator), row.name());
    EXPECT_EQ(orderOf(integrator), row.order);
    EXPECT_GE(row.order, 1) << row.name();
    EXPECT_NE(row.step, nullptr) << row.name();
    EXPECT_GT(std::string(row.description).size(), 10u) << row.name();
    EXPECT_TRUE(names.insert(row.name()).second) << row.name() << " twice";
    std::string lower = row.name();
    for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    for (const std::string& spelling : {std::string(row.name()), lower}) {
      Integrator parsed = integrator == Integrator::RK4 ? Integrator::Euler : Integrator::RK4;
      EXPECT_TRUE(parseIntegratorName(spelling, &parsed)) << spelling;
      EXPECT_EQ(parsed, integrator) << spelling;
    }
    EXPECT_NE(integratorNameList().find(row.name()), std::string::npos) << row.name();
  }
  EXPECT_EQ(integratorTable().size(), static_cast<std::size_t>(kIntegratorCount));
  Integrator unused;
  EXPECT_FALSE(parseIntegratorName("RK3", &unused));
  EXPECT_FALSE(parseIntegratorName("", &unused));
}

// The world reader takes every table name (and the writer writes it), whatever its length.
TEST(IntegratorTable, EveryNameReadsBackFromAWorldFile) {
  WorldFile f = readWorldFile(test::dataPath("jello.w"));
  for (const IntegratorInfo& row : integratorTable()) {
    f.run.integrator = row.integrator;
    EXPECT_EQ(parseWorld(formatWorld(f), "table.w").run.integrator, row.integrator) << row.name();
  }
}

// A row without a stable-step bound has no predicted limit, and only such rows are left out of
// --check's limits; a row that needs the Jacobian refuses a system without one, and only it.
TEST(IntegratorTable, ItsFactsAreWhatTheIntegratorsDo) {
  const std::vector<Mode> stiffMode = {{1e6, 0}};  // omega = 1000 rad/s
  OdeSystem withoutJacobian;
  withoutJacobian.derivative = [](const double* y, double* dydt) {
    dydt[0] = y[1];
    dydt[1] = -y[0];
  };
  std::vector<Integrator> bounded;
  for (const IntegratorInfo& row : integratorTable()) {
    const double limit = criticalStep(row.integrator, stiffMode);
    EXPECT_EQ(std::isfinite(limit), row.boundedStableStep) << row.name() << " limit " << limit;
    if (row.boundedStableStep) bounded.push_back(row.integrator);
    std::vector<double> y{1, 0};
    Stepper stepper(row.integrator);
    if (row.needsJacobian) {
      EXPECT_THROW(stepper.step(withoutJacobian, y, 0.01), std::logic_error) << row.name();
    } else {
      EXPECT_NO_THROW(stepper.step(withoutJacobian, y, 0.01)) << row.name();
      EXPECT_EQ(stepper.stats().jacobians, 0) << row.name();
    }
  }
  EXPECT_EQ(kExplicitIntegrators, bounded);
  EXPECT_EQ(integratorsWithStepLimit(), bounded);
}

// --help lists every integrator with its order and description, from the table.
TEST(IntegratorTable, HelpListsEveryIntegratorWithItsOrderAndDescription) {
  test::CommandResult help = test::runJello("--help");
  ASSERT_EQ(help.status, 0) << help.err;
  for (const IntegratorInfo& row : integratorTable()) {
    const std::size_t at = help.out.find("  " + std::string(row.name()) + " ");
    ASSERT_NE(at, std::string::npos) << row.name() << "\n" << help.out;
    const std::string rest = help.out.substr(at, help.out.find('\n', at) - at);
    EXPECT_NE(rest.find("order " + std::to_string(row.order)), std::string::npos) << rest;
    EXPECT_NE(rest.find(row.description), std::string::npos) << rest;
  }
}

// The README's list of integrators (a table "| `NAME` | what | order | evaluations |") names
// only integrators of the table, each with the table's order.
TEST(IntegratorTable, TheReadmesListAgreesWithIt) {
  std::istringstream readme(test::readText(std::string(JELLO_SOURCE_DIR) + "/README.md"));
  bool inSection = false;
  int rows = 0;
  for (std::string line; std::getline(readme, line);) {
    if (line.rfind("## ", 0) == 0) inSection = line == "## Integrators";
    if (!inSection || line.rfind("| `", 0) != 0) continue;
    std::vector<std::string> cells;
    std::istringstream cellText(line.substr(1));
    for (std::string cell; std::getline(cellText, cell, '|');) cells.push_back(cell);
    ASSERT_GE(cells.size(), 3u) << line;
    const std::string name =
        cells[0].substr(cells[0].find('`') + 1, cells[0].rfind('`') - cells[0].find('`') - 1);
    Integrator integrator;
    ASSERT_TRUE(parseIntegratorName(name, &integrator)) << "the README lists " << name;
    EXPECT_EQ(std::stoi(cells[2]), orderOf(integrator)) << name;
    ++rows;
  }
  EXPECT_GT(rows, 0) << "no integrator list found under '## Integrators'";
}

}  // namespace
}  // namespace jello
