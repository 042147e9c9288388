// Scene files (docs/scenes.md): the reader and its refusals, the obstacles' forces against hand-
// computed values and finite differences, pinned points, friction on a slope, and a jelly
// dropped on a sphere.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstring>
#include <random>
#include <string>

#include "analysis/contacts.h"
#include "analysis/stability.h"
#include "io/scenereader.h"
#include "model/field.h"
#include "model/obstacle.h"
#include "model/scenespec.h"
#include "solver/integrators.h"
#include "solver/jacobian.h"
#include "solver/physics.h"
#include "solver/simulation.h"
#include "test_support.h"

namespace jello {
namespace {

using test::centroid;

WorldFile scene(const std::string& text) {
  return parseScene(text, "test.toml", std::string(JELLO_SOURCE_DIR));
}

TEST(SceneFile, ACourseWorldThroughASceneIsTheCourseWorldBitForBit) {
  for (const char* name : {"rotate.w", "jello.w", "skewedCorner.w"}) {
    const WorldFile course = readWorldFile(std::string(JELLO_SOURCE_DIR) + "/world/" + name);
    const WorldFile through = scene(std::string("world = \"world/") + name + "\"\n");
    const Model a = makeModel(course.world, course.state),
                b = makeModel(through.world, through.state);
    Simulation one(a, course.state, course.run.integrator, course.run.dt);
    Simulation two(b, through.state, through.run.integrator, through.run.dt);
    ASSERT_TRUE(one.advance(1000).ran() && two.advance(1000).ran()) << name;
    EXPECT_EQ(
        std::memcmp(one.state().y.data(), two.state().y.data(), sizeof(double) * 2 * kNumCoords), 0)
        << name;
  }
}

// [field] replaces the course world's field: expressions evaluated at the nodes (node (i, j, k) of
// R^3 at -2 + 4 i / (R - 1), docs/world-format.md), one uniform force, or none at all, in which
// the jelly moves as the course world's springs and walls alone move it.
TEST(SceneFile, AFieldFromExpressionsUniformOrNone) {
  const WorldFile swirl = scene(
      "world = \"world/rotate.w\"\n[field]\nexpression = \"-2 * y; x + z^2; 0.5\"\nresolution "
      "= 5\n");
  ASSERT_EQ(swirl.world.field.resolution, 5);
  for (int n : {0, 7, 62, 124}) {
    const int i = n / 25, j = n / 5 % 5, k = n % 5;
    const double x = -2.0 + i, y = -2.0 + j, z = -2.0 + k;
    const Vec3 f = swirl.world.field.node(static_cast<std::size_t>(n));
    EXPECT_EQ(f.x, -2 * y) << n;
    EXPECT_EQ(f.y, x + z * z) << n;
    EXPECT_EQ(f.z, 0.5) << n;
  }
  // The expressions are evaluated at every node as the scene is read: their length is capped.
  std::string longest = "1";  // "1+1+...+1 ": kMostFieldExpressionBytes - 6 characters
  while (longest.size() + 2 <= kMostFieldExpressionBytes - 6) longest += "+1";
  longest.resize(kMostFieldExpressionBytes - 6, ' ');
  EXPECT_EQ(scene("[field]\nexpression = \"" + longest + "; 0; 0\"\nresolution = 2\n")
                .world.field.resolution,
            2);
  try {
    scene("[field]\nexpression = \"" + longest + "1; 0; 0\"\n");
    ADD_FAILURE() << "an expression of 1001 characters was accepted";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "test.toml:2: longer than 1000 characters (field.expression)");
  }
  const WorldFile uniform = scene("[field]\nuniform = [0, 0, -0.02]\n");
  EXPECT_EQ(uniform.world.field.resolution, 30);
  EXPECT_EQ(uniform.world.field.node(1234).z, -0.02);

  const WorldFile course = readWorldFile(std::string(JELLO_SOURCE_DIR) + "/world/rotate.w");
  const WorldFile none = scene("world = \"world/rotate.w\"\n[field]\npresent = false\n");
  ASSERT_GT(course.world.field.resolution, 0);
  EXPECT_EQ(none.world.field.resolution, 0);
  EXPECT_TRUE(none.world.field.forces.empty());
  World withoutField = course.world;
  withoutField.field = ForceField{};
  const Model a = makeModel(withoutField, course.state), b = makeModel(none.world, none.state);
  Simulation one(a, course.state, Integrator::RK4, course.run.dt);
  Simulation two(b, none.state, Integrator::RK4, none.run.dt);
  ASSERT_TRUE(one.advance(500).ran() && two.advance(500).ran());
  EXPECT_EQ(one.state().y, two.state().y);
}

// A point 0.1 m inside a sphere of radius 1, moving in and sideways: the spring pushes k * 0.1
// out along the radius, the damper d * 0.5 more, and friction holds the sideways motion back by
// mu(s) N s / sqrt(s^2 + eps^2), N the push.
TEST(ObstacleForces, APointInsideASphereIsPushedOutAndHeldBackByHandComputedForces) {
  Obstacle sphere;
  sphere.shape = ObstacleShape::Sphere;
  sphere.radius = 1;
  sphere.spring = {1000, 2};
  const Vec3 p{0, 0, 0.9}, v{0.2, 0, -0.5};
  Vec3 f = obstacleForce(sphere, p, v);
  EXPECT_NEAR(f.x, 0, 1e-12);
  EXPECT_NEAR(f.z, 1000 * 0.1 + 2 * 0.5, 1e-9);  // 101 N
  sphere.friction = {0.5, 0.3, 0.01};
  f = obstacleForce(sphere, p, v);
  const double mu = 0.3 + 0.2 * std::exp(-0.2 / (20 * 0.01));  // 0.37358: Stribeck speed 20 eps
  EXPECT_NEAR(f.x, -mu * 101 * 0.2 / std::sqrt(0.04 + 0.0001), 1e-9);  // -37.7 N
  EXPECT_NEAR(f.y, 0, 1e-12);
  EXPECT_NEAR(f.z, 101, 1e-9);
  EXPECT_EQ(length(obstacleForce(sphere, {0, 0, 1.0001}, v)), 0) << "outside: no force";
}

// Inside a box, out through the nearest face: 0.1 m below y = 1 beats the other faces.
TEST(ObstacleForces, APointInsideABoxLeavesThroughItsNearestFace) {
  Obstacle box;
  box.shape = ObstacleShape::Box;
  box.lower = {-1, -1, -1};
  box.upper = {1, 1, 1};
  box.spring = {500, 0};
  const Vec3 f = obstacleForce(box, {0.2, 0.9, -0.3}, {});
  EXPECT_NEAR(f.x, 0, 1e-12);
  EXPECT_NEAR(f.y, 500 * 0.1, 1e-9);
  EXPECT_NEAR(f.z, 0, 1e-12);
  const Vec3 g = obstacleForce(box, {-0.95, 0, 0}, {});
  EXPECT_NEAR(g.x, -500 * 0.05, 1e-9);
}

// The Jacobian blocks against central differences of the force, for points in contact with
// each shape, friction on, sliding slowly and fast.
TEST(ObstacleJacobian, MatchesFiniteDifferencesOfTheForce) {
  std::mt19937 random(17);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Obstacle> obstacles(4);
  obstacles[0].shape = ObstacleShape::Sphere, obstacles[0].radius = 1;
  obstacles[1].shape = ObstacleShape::Box, obstacles[1].lower = {-1, -1, -1},
  obstacles[1].upper = {1, 1, 1};
  obstacles[2].shape = ObstacleShape::HalfSpace, obstacles[2].normal = {0.6, 0, 0.8};
  obstacles[3].shape = ObstacleShape::Container, obstacles[3].lower = {-1, -1, -1},
  obstacles[3].upper = {1, 1, 1};
  const Vec3 inside[4] = {{0.1, 0.2, 0.7}, {0.3, -0.2, 0.85}, {0.1, 0.3, -0.1}, {1.05, 0.2, -1.02}};
  int checked = 0;
  for (int o = 0; o < 4; ++o)
    for (double speed : {0.005, 0.05, 1.0}) {
      Obstacle obstacle = obstacles[o];
      obstacle.spring = {800, 1.5};
      obstacle.friction = {0.6, 0.4, 0.01};
      const Vec3 p = inside[o], v = speed * Vec3{u(random), u(random), u(random)};
      Block3 dFdp, dFdv;
      obstacleJacobian(obstacle, p, v, &dFdp, &dFdv);
      constexpr double h = 1e-7;
      for (int j = 0; j < 3; ++j) {
        Vec3 e;
        (j == 0 ? e.x : j == 1 ? e.y : e.z) = h;
        const Vec3 byP =
            (1 / (2 * h)) * (obstacleForce(obstacle, p + e, v) - obstacleForce(obstacle, p - e, v));
        const Vec3 byV =
            (1 / (2 * h)) * (obstacleForce(obstacle, p, v + e) - obstacleForce(obstacle, p, v - e));
        const double fp[3] = {byP.x, byP.y, byP.z}, fv[3] = {byV.x, byV.y, byV.z};
        for (int i = 0; i < 3; ++i) {
          // The damping's and friction's turn with a sphere's normal are left out (obstacle.h).
          const double slack =
              o == 0 ? 0.05 * (1 + std::fabs(fp[i])) : 1e-4 * (1 + std::fabs(fp[i]));
          EXPECT_NEAR(dFdp.m[3 * i + j], fp[i], slack) << "shape " << o << " dF/dp " << i << j;
          EXPECT_NEAR(dFdv.m[3 * i + j], fv[i], 1e-4 * (1 + std::fabs(fv[i])))
              << "shape " << o << " dF/dv " << i << j;
        }
      }
      ++checked;
    }
  EXPECT_EQ(checked, 12);
}

// Pinned points keep their positions to the last bit, with every integrator, under gravity.
TEST(Pins, APinnedPointDoesNotMoveByASingleUlp) {
  const WorldFile f = scene(
      "gravity = [0, 0, -9.81]\ndt = 0.0002\n[[pin]]\ni = [0, 0]\nk = [7, 7]\n[[pin]]\nlower = "
      "[0.4, "
      "-1, -1]\nupper = [1, 1, 1]\n");
  const std::vector<int>& pinned = f.world.scene->pinned;
  ASSERT_EQ(pinned.size(), 8u + 64u);
  for (const IntegratorInfo& row : integratorTable()) {
    const Model model = makeModel(f.world, f.state);
    Simulation run(model, f.state, row.integrator, f.run.dt);
    ASSERT_TRUE(run.advance(row.needsJacobian ? 20 : 300).ran()) << row.name();
    double moved = 0, free = 0;
    for (int q = 0; q < kNumPoints; ++q) {
      const double d = length(load(run.state().p(), q) - load(f.state.p(), q));
      (std::binary_search(pinned.begin(), pinned.end(), q) ? moved : free) += d;
    }
    EXPECT_EQ(moved, 0) << row.name();
    EXPECT_GT(free, 1e-4) << row.name() << ": the rest of the jelly falls";
  }
}

// --check on a jelly hanging from two pinned corners: its modes are those of the free coordinates
// (a dense solve of the stiffness with the pinned rows and columns removed, here): no growing
// mode, the same highest frequency, at rest and at the initial state.
TEST(Pins, TheStabilityAnalysisSeesOnlyTheFreeCoordinates) {
  const WorldFile f = scene(
      "gravity = [0, 0, -9.81]\n[jelly]\nstiffness = 60\ndamping = 0.2\n"
      "[[pin]]\ni = [0, 0]\nj = [0, 0]\nk = [7, 7]\n[[pin]]\ni = [0, 0]\nj = [7, 7]\nk = [7, 7]\n");
  const std::vector<int>& pinned = f.world.scene->pinned;
  ASSERT_EQ(pinned.size(), 2u);
  const Model model = makeModel(f.world, f.state);
  AccelerationJacobian jacobian;
  accelerationJacobian(model, f.state.p(), f.state.v(), nullptr, &jacobian);
  const Eigen::MatrixXd dAdp(jacobian.dAdp);
  std::vector<int> free;
  for (int c = 0; c < kNumCoords; ++c)
    if (!std::binary_search(pinned.begin(), pinned.end(), c % kNumPoints)) free.push_back(c);
  const Eigen::Index n = static_cast<Eigen::Index>(free.size());
  Eigen::MatrixXd stiffness(n, n);
  for (Eigen::Index r = 0; r < n; ++r)
    for (Eigen::Index c = 0; c < n; ++c)
      stiffness(r, c) = -0.5 * (dAdp(free[r], free[c]) + dAdp(free[c], free[r]));
  const Eigen::VectorXd values =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(stiffness, Eigen::EigenvaluesOnly)
          .eigenvalues();
  ASSERT_GT(values[0], -1e-9 * values[n - 1]) << "the pinned lattice at rest does not buckle";
  const double fastest = std::sqrt(values[n - 1]);

  const StabilityReport report = analyseStability(f.world, f.state);
  EXPECT_EQ(report.initial.growing, 0);
  EXPECT_EQ(report.rest.growing, 0);
  EXPECT_NEAR(report.initial.highestFrequency, fastest, 1e-9 * fastest);
  EXPECT_NEAR(report.rest.highestFrequency, fastest, 1e-9 * fastest);
  for (std::size_t i = 0; i < report.criticalRest.size(); ++i)
    EXPECT_NEAR(report.criticalRest[i], report.criticalInitial[i], 1e-9 * report.criticalRest[i]);
}

// --check's "face on a wall" column is the course's wall at x = -2: a scene without those walls
// (none, or a box of its own) has no such column, rather than a figure for a wall it lacks.
TEST(SceneFile, CheckHasAWallColumnOnlyWithTheCourseWalls) {
  const std::pair<const char*, bool> cases[] = {{"", true},
                                                {"[bounds]\npresent = false\n", false},
                                                {"[bounds]\nlower = [-3, -3, -3]\n", false}};
  for (const auto& c : cases) {
    const WorldFile f = scene(c.first);
    const StabilityReport report = analyseStability(f.world, f.state);
    EXPECT_EQ(report.courseWalls, c.second) << c.first;
    EXPECT_EQ(std::isnan(report.criticalFaceOnWall[0]), !c.second) << c.first;
    const std::string text = stabilityText("s.toml", f.run, report);
    EXPECT_EQ(text.find("(no course walls)") != std::string::npos, !c.second) << text;
  }
}

// Each integrator's error against a fine RK4 run at two steps, on a jelly hanging from a pinned
// edge under gravity (smooth: no contact): the fitted order is the integrator's.
TEST(Pins, EveryIntegratorKeepsItsOrderOnAScenWithPins) {
  const WorldFile f = scene(
      "gravity = [0, 0, -9.81]\n[bounds]\npresent = false\n[[pin]]\ni = [0, 0]\nk = [7, 7]\n");
  const Model model = makeModel(f.world, f.state);
  test::expectEveryIntegratorsOrder(model, f.state, 0.02);
}

// A jelly on a horizontal plane with friction, under gravity tilted by a (a slope of angle a):
// below the friction angle atan(mu_s) it creeps at most millimetres in a second (friction is
// regularised, obstacle.h); above it, it slides with the acceleration g (sin a - mu_d cos a).
TEST(Friction, ABlockOnASlopeStaysBelowTheFrictionAngleAndSlidesAboveIt) {
  constexpr double muS = 0.6, muD = 0.4, g = 9.81;
  auto slope = [&](double angle) {
    char text[600];
    std::snprintf(text, sizeof text,
                  "dt = 0.0001\ngravity = [%.17g, 0, %.17g]\n[jelly]\nstiffness = 2000\ndamping = "
                  "2\noffset = [0, 0, -0.5]\n[bounds]\npresent = false\n[[plane]]\npoint = [0, 0, "
                  "-1.0]\nnormal = [0, 0, 1]\nstiffness = 20000\ndamping = 5\nfriction_static = "
                  "%g\nfriction_dynamic = %g\nfriction_speed = 0.002\n",
                  g * std::sin(angle), -g * std::cos(angle), muS, muD);
    return scene(text);
  };
  const double friction = std::atan(muS);
  {
    // Settled on the level first: a jelly landing on a slope slides while its weight presses it
    // in, and once sliding, mu_d < tan a keeps it going, as Coulomb's law says.
    const WorldFile level = slope(0);
    const Model levelModel = makeModel(level.world, level.state);
    Simulation settle(levelModel, level.state, Integrator::RK4, level.run.dt);
    ASSERT_TRUE(settle.advanceTo(0.5).ran());
    const WorldFile f = slope(0.8 * friction);
    const Model model = makeModel(f.world, f.state);
    Simulation s(model, settle.state(), Integrator::RK4, f.run.dt);
    ASSERT_TRUE(s.advanceTo(1.0).ran());
    const double slid = centroid(s.state()).x - centroid(settle.state()).x;
    std::printf("at 0.8 of the friction angle: %.3g m in 1 s\n", slid);
    EXPECT_LT(std::fabs(slid), 0.01);
  }
  {
    const double angle = 1.2 * friction;
    const WorldFile f = slope(angle);
    const Model model = makeModel(f.world, f.state);
    Simulation s(model, f.state, Integrator::RK4, f.run.dt);
    auto speed = [&] {
      double sum = 0;
      for (int q = 0; q < kNumPoints; ++q) sum += s.state().v()[q];
      return sum / kNumPoints;
    };
    ASSERT_TRUE(s.advanceTo(0.4).ran());
    const double before = speed();
    ASSERT_TRUE(s.advanceTo(1.0).ran());
    const double measured = (speed() - before) / 0.6;
    const double expected = g * (std::sin(angle) - muD * std::cos(angle));
    std::printf("at 1.2 times the friction angle: %.4g m/s^2, expected %.4g\n", measured, expected);
    EXPECT_NEAR(measured / expected, 1, 0.03);
  }
}

// A point 1 mm into a frictional floor: at rest it sticks; slipping at 10 eps it slides; at
// half the sticking speed it still sticks; above the floor, or leaving it faster than the spring
// pushes, or on a floor without friction, it has no friction state.
TEST(FrictionState, APointRestingOnAFrictionalPlaneSticksOneSlippingAtTenEpsSlides) {
  Obstacle floor;
  floor.shape = ObstacleShape::HalfSpace;
  floor.point = {0, 0, -1};
  floor.normal = {0, 0, 1};
  floor.spring = {20000, 5};
  floor.friction = {0.6, 0.5, 0.002};
  const double eps = floor.friction.speed;
  const Vec3 in{0.3, -0.2, -1.001}, above{0.3, -0.2, -0.999};
  EXPECT_EQ(frictionState(floor, in, {0, 0, 0}), FrictionState::Sticking);
  EXPECT_EQ(frictionState(floor, in, {0.5 * kStickingSpeedRatio * eps, 0, 0}),
            FrictionState::Sticking);
  EXPECT_EQ(frictionState(floor, in, {6 * eps, -8 * eps, 0}), FrictionState::Sliding);  // 10 eps
  EXPECT_EQ(frictionState(floor, above, {0, 0, 0}), FrictionState::None);
  // k depth = 20 N; the damper takes it back at 4 m/s out of the floor (d = 5 N s/m).
  EXPECT_EQ(frictionState(floor, in, {10 * eps, 0, 3.9}), FrictionState::Sliding);
  EXPECT_EQ(frictionState(floor, in, {10 * eps, 0, 4.1}), FrictionState::None);
  floor.friction = {};
  EXPECT_EQ(frictionState(floor, in, {10 * eps, 0, 0}), FrictionState::None);
}

// The bottom layer of the jelly on the scenes' slope (25 degrees): with mu_s 0.6 it is held,
// creeping at 1.8 eps (3.7 mm/s); with mu_s 0.3 it slides (1.9 m/s at 1 s). The layers above
// touch nothing.
TEST(FrictionState, TheJellyOnTheSlopeSticksWithEnoughFrictionAndSlidesWithout) {
  auto states = [](const char* name, double time) {
    const WorldFile f = readSceneFile(std::string(JELLO_SOURCE_DIR) + "/scenes/" + name);
    const Model model = makeModel(f.world, f.state);
    Simulation run(model, f.state, f.run.integrator, f.run.dt);
    EXPECT_TRUE(run.advanceTo(time).ran());
    int count[2][3] = {};  // [bottom layer or not][state]
    double slip = 0;
    for (int q = 0; q < kNumPoints; ++q) {
      const bool bottom = q % kLatticeSize == 0;  // k = 0
      ++count[bottom][static_cast<int>(frictionStates(model, run.state())[q])];
      if (bottom)
        slip = std::max(slip, std::hypot(run.state().v()[q], run.state().v()[kNumPoints + q]));
    }
    std::printf("%s at %g s: bottom %d none, %d sticking, %d sliding; largest slip %.3g m/s\n",
                name, time, count[1][0], count[1][1], count[1][2], slip);
    EXPECT_EQ(count[0][0], kNumPoints - kLatticeSize * kLatticeSize) << name;
    return std::vector<int>{count[1][0], count[1][1], count[1][2]};
  };
  const std::vector<int> held = states("slope-friction.toml", 1.0);
  EXPECT_EQ(held[2], 0);
  EXPECT_GE(held[1], (kLatticeSize - 1) * kLatticeSize);  // the uphill edge may lift off
  const std::vector<int> sliding = states("slope-slides.toml", 1.0);
  EXPECT_EQ(sliding[2], kLatticeSize * kLatticeSize);
}

// Dropped from above onto a sphere's top, the jelly comes to rest on it, its centroid over the
// centre, none of it sunk far into the sphere. (The sphere is wider than the jelly is high, so
// that resting on its top is stable, as for a block on a ball: radius above half the height.)
TEST(Obstacles, AJellyDroppedOnASphereEndsRestingOnItCentred) {
  const WorldFile f = scene(
      "gravity = [0, 0, -9.81]\ndt = 0.0002\n[jelly]\noffset = [0, 0, 0.4]\ndamping = 1\n"
      "[[sphere]]\ncentre = [0, 0, -1.5]\nradius = 1\nstiffness = 5000\ndamping = 10\n"
      "friction_static = 0.8\nfriction_dynamic = 0.6\n");
  const Model model = makeModel(f.world, f.state);
  Simulation s(model, f.state, Integrator::RK4, f.run.dt);
  const RunOutcome outcome = s.advanceTo(4.0);
  ASSERT_TRUE(outcome.ran()) << "step " << outcome.step << ": " << outcome.reason;
  const Vec3 c = centroid(s.state());
  double fastest = 0, deepest = 0;
  Vec3 velocity;  // the centroid's
  for (int q = 0; q < kNumPoints; ++q) velocity += (1.0 / kNumPoints) * load(s.state().v(), q);
  for (int q = 0; q < kNumPoints; ++q) {
    fastest = std::max(fastest, length(load(s.state().v(), q)));
    deepest = std::max(deepest, 1 - length(load(s.state().p(), q) - Vec3{0, 0, -1.5}));
  }
  std::printf("centroid (%.3g, %.3g, %.3g), fastest point %.3g m/s, deepest %.3g m\n", c.x, c.y,
              c.z, fastest, deepest);
  EXPECT_NEAR(c.x, 0, 1e-3);
  EXPECT_NEAR(c.y, 0, 1e-3);
  EXPECT_GT(c.z, -0.5) << "above the sphere's top";
  EXPECT_LT(length(velocity), 0.005) << "at rest";
  EXPECT_LT(fastest, 0.1) << "quivering at most";
  EXPECT_LT(deepest, 0.01);
}

struct Malformed {
  const char* text;
  const char* message;  // what the error line must hold, "test.toml:LINE: ... (key)"
};

const Malformed kMalformed[] = {
    {"gravity = [0, 0]\n", "test.toml:1: expected 3 numbers [x, y, z] (gravity)"},
    {"gravity = [0, 0, \"down\"]\n", "test.toml:1: expected 3 numbers [x, y, z] (gravity)"},
    {"gravty = [0, 0, -9.8]\n", "test.toml:1: unknown key (gravty); did you mean gravity?"},
    {"dt = 0\n", "test.toml:1: must be above 0 (dt)"},
    {"dt = -1e-3\n", "test.toml:1: must be above 0 (dt)"},
    {"dt = \"fast\"\n", "test.toml:1: expected a number (dt)"},
    {"dt = inf\n", "test.toml:1: is not finite (dt)"},
    {"n = 0\n", "test.toml:1: expected a whole number from 1 to 2147483647 (n)"},
    {"n = 2.5\n", "test.toml:1: expected a whole number from 1 to 2147483647 (n)"},
    {"n = 2147483648\n", "test.toml:1: expected a whole number from 1 to 2147483647 (n)"},
    {"integrator = \"RK5\"\n", "test.toml:1: expected one of"},
    {"world = \"world/none.w\"\n", "world/none.w: cannot open: No such file or directory (world)"},
    {"world = 3\n", "test.toml:1: expected the path of a course world (.w) (world)"},
    {"[jelly]\nmass = 0\n", "test.toml:2: must be above 0 (jelly.mass)"},
    {"[jelly]\nmass = 1\ntotal_mass = 2\n",
     "test.toml:3: give mass (per point) or total_mass, not both (jelly.total_mass)"},
    {"[jelly]\nstiffness = -5\n", "test.toml:2: must be at least 0 (jelly.stiffness)"},
    {"[jelly]\ncolour = 1\n", "test.toml:2: unknown key (jelly.colour)"},
    {"jelly = 5\n", "test.toml:1: expected a [jelly] table or [[jelly]] tables (jelly)"},
    {"[[sphere]]\ncentre = [0, 0, 0]\n", "test.toml:1: missing (sphere[1].radius)"},
    {"[[sphere]]\ncentre = [0, 0, 0]\nradius = -1\n",
     "test.toml:3: must be above 0 (sphere[1].radius)"},
    {"[[sphere]]\ncentre = [0, 0, 0]\nradus = 1\n",
     "test.toml:3: unknown key (sphere[1].radus); did you mean sphere[1].radius?"},
    {"[[sphere]]\ncentre = [0,0,0]\nradius = 1\nfriction_static = 0.2\nfriction_dynamic = 0.5\n",
     "test.toml:5: must be from 0 to friction_static (dynamic friction is the weaker) "
     "(sphere[1].friction_dynamic)"},
    {"[[sphere]]\ncentre = [0,0,0]\nradius = 1\nfriction_speed = 0\n",
     "test.toml:4: must be above 0 (sphere[1].friction_speed)"},
    {"[[box]]\nlower = [0, 0, 0]\nupper = [1, 0, 1]\n",
     "test.toml:3: must be above lower on every axis (box[1].upper)"},
    {"[[plane]]\npoint = [0, 0, 0]\nnormal = [0, 0, 0]\n",
     "test.toml:3: must not be zero (plane[1].normal)"},
    {"sphere = 1\n", "test.toml:1: expected [[sphere]] tables (sphere)"},
    {"[[pin]]\ni = [0, 8]\n",
     "test.toml:2: expected [first, last], whole numbers with 0 <= first <= last <= 7 (pin[1].i)"},
    {"[[pin]]\ni = [3, 1]\n", "(pin[1].i)"},
    {"[[pin]]\nlower = [5, 5, 5]\n", "test.toml:1: pins no point (pin[1])"},
    {"[[pin]]\ni = [0, 0]\nlower = [0, 0, 0]\n",
     "give lattice ranges (i, j, k) or a region (lower, upper), not both"},
    {"[bounds]\npresent = 1\n", "test.toml:2: expected true or false (bounds.present)"},
    {"[bounds]\npresent = false\nfriction_static = 0.5\n",
     "test.toml:3: a bounding box that is not present takes no other key (bounds.friction_static)"},
    {"[bounds]\nfriction_dynamic = 0.5\n",
     "test.toml:2: must be from 0 to friction_static (dynamic friction is the weaker) "
     "(bounds.friction_dynamic)"},
    {"[bounds]\nlower = [0, 0, 0]\nupper = [-1, 1, 1]\n",
     "test.toml:3: must be above lower on every axis (bounds.upper)"},
    {"[bounds]\nlower = [3, 0, 0]\n",
     "test.toml:2: must be below upper on every axis (bounds.lower)"},
    {"[[sphere]]\ncentre = [0,0,0]\nradius = 1\nfriction_static = 8.1e307\n",
     "test.toml:4: is beyond 1e+12 in magnitude (sphere[1].friction_static)"},
    {"[[sphere]]\ncentre = [0,0,0]\nradius = 1\nfriction_static = 11\n",
     "test.toml:4: must be from 0 to 10 (sphere[1].friction_static)"},
    {"gravity = [0, 0, -1e13]\n", "test.toml:1: is beyond 1e+12 in magnitude (gravity)"},
    {"[field]\nexpression = \"x +; 0; 0\"\n", "test.toml:2: fx: Unexpected end of expression"},
    {"[field]\nexpression = \"x; 0\"\n",
     "test.toml:2: needs three expressions \"fx; fy; fz\", got 2 (field.expression)"},
    {"[field]\nexpression = \"1/0; 0; 0\"\nresolution = 2\n",
     "test.toml:2: fx is not finite at (-2, -2, -2) (field.expression)"},
    {"[field]\nuniform = [0, 0, 1]\npresent = false\n",
     "test.toml:1: give one of expression, uniform or present = false (field)"},
    {"[field]\npresent = true\n", "test.toml:2: expected false"},
    {"[field]\nuniform = [0, 0, 1]\nresolution = 1\n",
     "test.toml:3: expected a whole number from 2 to 64 (field.resolution)"},
    {"[field]\nexpression = 3\n", "test.toml:2: expected a string"},
    {"[field]\npresent = false\nresolution = 4\n",
     "test.toml:3: a field that is not present has no resolution (field.resolution)"},
    {"[field]\nuniform = [0, 0, 1]\nresolution = 65\n", "(field.resolution)"},
    {"[contact]\nstiffness = -1\n", "test.toml:2: must be at least 0 (contact.stiffness)"},
    {"dt = 1e-3\ndt = 2e-3\n", "test.toml:2:"},
    {"[jelly\n", "test.toml:1:"},
    // Not TOML: said in this program's words (toml++'s own text is not shown), naming the
    // character it stopped at, whatever it is; a quoted key may hold any character too
    {"n = n\n",
     "test.toml:1: not TOML: it cannot be read on from column 6, at '<newline>' (each line is "
     "key = value, [table] or [[list]]: docs/scenes.md)"},
    {"dt = \"1\u0001", "test.toml:1: not TOML: it cannot be read on from column"},
    // a key or table given twice, by its name
    {"dt = 1\ndt = 2\n", "test.toml:2: dt given twice (each key once in its table)"},
    {"[jelly]\nmass = 1\n[[jelly]]\nmass = 2\n",
     "test.toml:3: [jelly] given twice: [jelly] and [[jelly]] do not mix (one [jelly], or each as "
     "[[jelly]])"},
    {"[jelly]\nmass = 1\n[jelly]\n",
     "test.toml:3: [jelly] given twice (a table once; several as [[jelly]])"},
    {"\"a\\nb\" = 1\n", "test.toml:1: unknown key (a<newline>b)"},
    {"\"a\\u0001\" = 1\n", "test.toml:1: unknown key (a<U+0001>)"},
    // bodies
    {"[jelly]\nsize = [4, 4, 4]\n",
     "test.toml:2: give the jelly's shape (\"lattice\", \"sphere\" or \"mesh\") with it "
     "(jelly.size)"},
    {"[jelly]\nshape = \"cone\"\n",
     "test.toml:2: expected \"lattice\", \"sphere\" or \"mesh\" (jelly.shape)"},
    {"[jelly]\nshape = 3\n",
     "test.toml:2: expected \"lattice\", \"sphere\" or \"mesh\" (jelly.shape)"},
    {"[jelly]\nshape = \"lattice\"\n",
     "test.toml:2: a lattice needs its size = [nx, ny, nz] (jelly.size)"},
    {"[jelly]\nshape = \"lattice\"\nsize = [1, 4, 1]\n",
     "test.toml:3: at most one side may be 1 (a sheet); the others from 2 (jelly.size)"},
    {"[jelly]\nshape = \"lattice\"\nsize = [2000, 2000, 2]\n",
     "test.toml:3: 2000x2000x2 is 8000000 points; a scene holds at most 1048576 (jelly.size)"},
    {"[jelly]\nshape = \"lattice\"\nsize = [1048577, 2, 1]\n",
     "test.toml:3: expected a whole number from 1 to 1048576 (jelly.size)"},
    {"[jelly]\nshape = \"lattice\"\nsize = [4, 4]\n",
     "test.toml:3: expected [nx, ny, nz] (jelly.size)"},
    {"[jelly]\nshape = \"lattice\"\nsize = [4, 4, 4]\nradius = 1\n",
     "test.toml:4: belongs to shape = \"sphere\", not \"lattice\" (jelly.radius)"},
    {"[jelly]\nshape = \"lattice\"\nsize = [4, 4, 4]\nspacing = 0\n",
     "test.toml:4: must be at least 0.001 (jelly.spacing)"},
    {"[jelly]\nshape = \"sphere\"\n", "test.toml:2: a sphere needs its radius (m) (jelly.radius)"},
    {"[jelly]\nshape = \"sphere\"\nradius = 5\nspacing = 0.1\n",
     "test.toml:3: a ball of radius 5 m is 10 m across (along x): at voxel size 0.1 m that is 100 "
     "voxels, at most 47; use a voxel of at least 0.22 m (jelly.radius)"},
    {"[jelly]\nshape = \"mesh\"\n",
     "test.toml:2: a mesh jelly needs its mesh = \"FILE.obj\" (jelly.mesh)"},
    {"[jelly]\nshape = \"mesh\"\nmesh = \"none.obj\"\n",
     "none.obj: cannot open: No such file or directory (jelly.mesh)"},
    {"[jelly]\nshape = \"mesh\"\nmesh = \"scenes/models/jelly-mould.obj\"\nspacing = 0.001\n",
     "voxels, at most 47; use a voxel of at least"},
    {"[jelly]\nstiffness = {structural = 1, twist = 2}\n",
     "test.toml:2: unknown key (jelly.stiffness.twist)"},
    {"[jelly]\nstiffness = {shear = -1}\n",
     "test.toml:2: must be at least 0 (jelly.stiffness.shear)"},
    {"[jelly]\nshape = \"lattice\"\nsize = [4, 4, 4]\n[[pin]]\ni = [0, 4]\n",
     "test.toml:5: expected [first, last], whole numbers with 0 <= first <= last <= 3 (pin[1].i)"},
};

TEST(SceneFile, RefusesEveryMalformedSceneWithItsLineAndKey) {
  int refused = 0;
  for (const Malformed& m : kMalformed) {
    try {
      scene(m.text);
      ADD_FAILURE() << "accepted:\n" << m.text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(m.message), std::string::npos)
          << "for:\n"
          << m.text << "got: " << e.what() << "\nwanted: " << m.message;
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "one line";
      ++refused;
    }
  }
  EXPECT_GE(refused, 30);
}

TEST(SceneFile, TheCommandLineRefusesABadSceneWithExitStatusTwo) {
  const std::string dir = test::makeTempDir();
  test::writeText(dir + "/bad.toml", "[[sphere]]\ncentre = [0, 0, 0]\nradius = 0\n");
  const test::CommandResult r = test::runJelloArgs({"--headless", dir + "/bad.toml"});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("bad.toml:3: must be above 0 (sphere[1].radius)"), std::string::npos)
      << r.err;
}

}  // namespace
}  // namespace jello
