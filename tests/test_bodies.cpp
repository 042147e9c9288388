// Bodies of any size and shape (body.h, docs/scenes.md): their points, springs and surfaces
// against counts by hand and by an independent count, the spring list's forces against the course
// kernel, finite differences and themselves on ranges and two threads, the 8x8x8 lattice of a
// scene against the course cube, a bent bar's equilibrium, and the integrators' orders.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <set>
#include <string>
#include <tuple>

#include "analysis/stability.h"
#include "core/threadpool.h"
#include "io/scenereader.h"
#include "model/body.h"
#include "model/scenespec.h"
#include "model/springs.h"
#include "solver/integrators.h"
#include "solver/jacobian.h"
#include "solver/physics.h"
#include "solver/simulation.h"
#include "test_support.h"

namespace jello {
namespace {

WorldFile bodyScene(const std::string& text) {
  return parseScene(text, "test.toml", std::string(JELLO_SOURCE_DIR));
}

// The springs a lattice of nx x ny x nz points has, kind by kind, counted by hand: structural
// along each axis, two diagonals on each face square, four through each cube, bends two apart.
std::size_t latticeSprings(int x, int y, int z) {
  const int structural = (x - 1) * y * z + x * (y - 1) * z + x * y * (z - 1);
  const int face = 2 * ((x - 1) * (y - 1) * z + (x - 1) * y * (z - 1) + x * (y - 1) * (z - 1));
  const int body = 4 * (x - 1) * (y - 1) * (z - 1);
  const int bend = (x - 2) * y * z + x * (y - 2) * z + x * y * (z - 2);
  return static_cast<std::size_t>(structural + face + body + bend);
}

// The springs of a voxel body counted apart from body.cpp: the set of corner nodes of the filled
// voxels, and for every offset the nodes whose neighbour at the offset is in the set.
std::size_t springsImpliedBy(const VoxelMask& mask) {
  std::set<std::tuple<int, int, int>> nodes;
  for (int i = 0; i < mask.nx; ++i)
    for (int j = 0; j < mask.ny; ++j)
      for (int k = 0; k < mask.nz; ++k)
        if (mask.at(i, j, k))
          for (int c = 0; c < 8; ++c)
            nodes.insert({i + (c >> 2 & 1), j + (c >> 1 & 1), k + (c & 1)});
  std::size_t springs = 0;
  for (const SpringOffset& o : kSpringOffsets)
    for (const auto& [i, j, k] : nodes) springs += nodes.count({i + o.di, j + o.dj, k + o.dk});
  return springs;
}

// V - E + F of the surface: 2 for a closed surface of a body without holes.
int eulerCharacteristic(const Body& body) {
  std::set<std::pair<int, int>> edges;
  for (const Triangle& t : body.surface)
    for (int e = 0; e < 3; ++e) edges.insert(std::minmax(t[e], t[(e + 1) % 3]));
  return static_cast<int>(body.surfacePoints.size()) - static_cast<int>(edges.size()) +
         static_cast<int>(body.surface.size());
}

// Twice the enclosed volume by the divergence theorem over the surface's triangles (m^3).
double enclosedVolume(const Body& body, const State& rest) {
  double volume = 0;
  const int n = body.count();
  for (const Triangle& t : body.surface)
    volume +=
        dot(load(rest.p(), t[0], n), cross(load(rest.p(), t[1], n), load(rest.p(), t[2], n))) / 6;
  return volume;
}

TEST(Bodies, TheCourseLatticeIsTheCourseCubeItsNumberingSpringsAndSurface) {
  const Body& course = courseBody();
  ASSERT_EQ(course.count(), kNumPoints);
  EXPECT_TRUE(course.courseLattice);
  for (int q = 0; q < kNumPoints; ++q) {
    const std::array<int, 3> i = course.index(q);
    ASSERT_EQ(pointIndex(i[0], i[1], i[2]), q);
    ASSERT_EQ(course.label(q), latticeLabel(q));
  }
  // The course's spring list, as the kernel's slots give it (springs.h): offset by offset, each
  // in the order of its point a.
  std::size_t s = 0;
  for (const SpringOffset& o : kSpringOffsets)
    for (int q = 0; q < kNumPoints; ++q)
      if (rowHasSprings(o, q / kLatticeSize) && slotKept(o, q % kLatticeSize)) {
        ASSERT_LT(s, course.springs.size());
        const Spring& spring = course.springs[s++];
        EXPECT_EQ(spring.a, q);
        EXPECT_EQ(spring.b, q + springDelta(o));
        EXPECT_EQ(spring.rest, restLength(o));
        EXPECT_EQ(spring.kind, o.kind);
      }
  EXPECT_EQ(s, course.springs.size());
  EXPECT_EQ(course.springs.size(), latticeSprings(8, 8, 8));
  EXPECT_EQ(course.springs.size(), 6220u);
  EXPECT_EQ(course.surface.size(), 588u);
}

TEST(Bodies, ALatticeOfAnySizeHasTheSpringsAndClosedSurfaceItsSizeImplies) {
  for (auto [x, y, z] : {std::tuple{16, 4, 4}, {2, 2, 2}, {3, 5, 2}, {48, 2, 3}, {16, 16, 16}}) {
    const Body body = latticeBody(x, y, z, 0.1);
    EXPECT_EQ(body.count(), x * y * z);
    EXPECT_EQ(body.springs.size(), latticeSprings(x, y, z)) << x << "x" << y << "x" << z;
    const std::size_t quads = 2 * ((x - 1) * (y - 1) + (x - 1) * (z - 1) + (y - 1) * (z - 1));
    EXPECT_EQ(body.surface.size(), 2 * quads);
    EXPECT_EQ(eulerCharacteristic(body), 2);
    // Outward winding: the enclosed volume is the box's, positive.
    EXPECT_NEAR(enclosedVolume(body, restState(body)), 1e-3 * (x - 1) * (y - 1) * (z - 1), 1e-12);
    EXPECT_FALSE(body.courseLattice);
  }
}

TEST(Bodies, VoxelsMakeTheBodyTheirCornersAndSpringsImply) {
  // One voxel: 8 corners, 12 edges, 12 face diagonals, 4 body diagonals, no bend.
  VoxelMask one{1, 1, 1, {1}};
  const Body cube = voxelBody(one, 0.5, "one voxel");
  EXPECT_EQ(cube.count(), 8);
  EXPECT_EQ(cube.springs.size(), 28u);
  EXPECT_EQ(cube.surface.size(), 12u);
  // Two voxels meeting along an edge only (diagonal neighbours): 14 points, two cubes' springs
  // and the face diagonals across the shared edge's two squares' planes where both ends exist.
  VoxelMask edge{2, 2, 1, {1, 0, 0, 1}};
  const Body two = voxelBody(edge, 0.5, "two voxels on an edge");
  EXPECT_EQ(two.count(), 14);
  EXPECT_EQ(two.springs.size(), springsImpliedBy(edge));
  // An L of three voxels and a hollow ring of eight: their surfaces close (the ring is a torus,
  // V - E + F = 0) and the springs are what their corners imply.
  VoxelMask ell{2, 2, 1, {1, 1, 1, 0}};
  const Body l = voxelBody(ell, 0.5, "an L");
  EXPECT_EQ(l.springs.size(), springsImpliedBy(ell));
  EXPECT_EQ(eulerCharacteristic(l), 2);
  EXPECT_NEAR(enclosedVolume(l, restState(l)), 3 * 0.125, 1e-15);
  VoxelMask ring{3, 3, 1, {1, 1, 1, 1, 0, 1, 1, 1, 1}};
  const Body torus = voxelBody(ring, 0.5, "a ring");
  EXPECT_EQ(torus.springs.size(), springsImpliedBy(ring));
  EXPECT_EQ(eulerCharacteristic(torus), 0);
  EXPECT_NEAR(enclosedVolume(torus, restState(torus)), 8 * 0.125, 1e-15);
}

// A body's state: its rest lattice moved and deformed pseudo-randomly, with velocities.
State jostled(const Body& body, std::mt19937_64& random, double amount) {
  std::uniform_real_distribution<double> u(-amount, amount);
  State s = restState(body);
  for (double& y : s.y) y += u(random);
  return s;
}

World springWorld(std::shared_ptr<SceneSpec> spec) {
  World w = test::springsOnlyWorld();
  w.mass = 0.01;
  w.scene = std::move(spec);
  return w;
}

std::shared_ptr<SceneSpec> bodySpec(Body body, std::optional<SpringConstants> springs = {}) {
  auto spec = std::make_shared<SceneSpec>();
  spec->body = std::make_shared<Body>(std::move(body));
  spec->springs = springs;
  spec->boundsPresent = false;
  return spec;
}

TEST(SpringList, SumsTheCourseCubeAsTheRowKernelDoesBitForBit) {
  std::mt19937_64 random(41);
  const State s = jostled(courseBody(), random, 0.05);
  for (bool dampers : {true, false}) {
    const SpringConstants c = SpringConstants::same(437.5, dampers ? 0.3 : 0);
    // A body with the course's points and springs that is not marked as the course's cube goes
    // through the grid kernel; the reference through the spring list.
    Body listed = courseBody();
    listed.courseLattice = false;
    const SpringTerm row(courseBody(), c, dampers), grid(listed, c, dampers),
        list(courseBody(), c, dampers, SpringKernel::List);
    ASSERT_TRUE(row.rowKernel());
    ASSERT_FALSE(grid.rowKernel() || grid.listKernel());
    ASSERT_TRUE(list.listKernel());
    std::vector<double> a(kNumCoords, 0.0), b(kNumCoords, 0.0), l(kNumCoords, 0.0);
    row.addForces(s.p(), s.v(), nullptr, a.data());
    grid.addForces(s.p(), s.v(), nullptr, b.data());
    list.addForces(s.p(), s.v(), nullptr, l.data());
    EXPECT_EQ(std::memcmp(a.data(), b.data(), sizeof(double) * kNumCoords), 0) << dampers;
    EXPECT_EQ(std::memcmp(a.data(), l.data(), sizeof(double) * kNumCoords), 0) << dampers;
  }
}

TEST(SpringList, OnEveryRangeAndOnTwoThreadsGivesTheWholePassBitForBit) {
  std::mt19937_64 random(42);
  VoxelMask ell{5, 3, 2, std::vector<char>(30, 1)};
  ell.filled[7] = ell.filled[20] = 0;
  for (const Body& body : {latticeBody(16, 4, 4, 0.1), voxelBody(ell, 0.1, "an odd count")}) {
    const int n = body.count();
    const SpringTerm term(body, SpringConstants{{300, 200, 100}, {0.2, 0.1, 0.05}}, true);
    const State s = jostled(body, random, 0.02);
    std::vector<double> whole(3 * n, 0.0);
    term.addForces(s.p(), s.v(), nullptr, whole.data());
    for (int split = 0; split <= n; split += kRangeAlignment) {
      std::vector<double> parts(3 * n, 0.0);
      term.addForcesOn({0, split}, s.p(), s.v(), nullptr, parts.data());
      term.addForcesOn({split, n}, s.p(), s.v(), nullptr, parts.data());
      ASSERT_EQ(std::memcmp(whole.data(), parts.data(), sizeof(double) * 3 * n), 0)
          << body.what << " split at " << split;
    }
    // The whole model on two threads, its derivative over RK4 steps.
    const Model model = makeModel(springWorld(bodySpec(body)), s);
    ThreadPool pool(2);
    Simulation one(model, s, Integrator::RK4, 1e-3), two(model, s, Integrator::RK4, 1e-3);
    two.setPool(&pool, false);
    ASSERT_TRUE(one.advance(200).ran() && two.advance(200).ran());
    EXPECT_EQ(std::memcmp(one.state().y.data(), two.state().y.data(), sizeof(double) * 6 * n), 0)
        << body.what;
  }
}

TEST(SpringList, ForcesAreMinusTheEnergysGradientAndTheJacobianTheForcesDerivative) {
  std::mt19937_64 random(43);
  const Body body = latticeBody(3, 4, 2, 0.2);
  const int n = body.count();
  const SpringConstants c{{400, 150, 60}, {0.3, 0.2, 0.1}};
  const SpringTerm term(body, c, true);
  const State s = jostled(body, random, 0.03);
  std::vector<double> force(3 * n, 0.0);
  term.addForces(s.p(), s.v(), nullptr, force.data());
  // Without damping the force is -dE/dp: central differences of the energy.
  const SpringTerm undamped(body, SpringConstants{c.k, {0, 0, 0}}, false);
  std::vector<double> still(3 * n, 0.0);
  undamped.addForces(s.p(), s.v(), nullptr, still.data());
  constexpr double h = 1e-6;
  double worst = 0;
  for (int i = 0; i < 3 * n; ++i) {
    State plus = s, minus = s;
    plus.p()[i] += h;
    minus.p()[i] -= h;
    double ePlus = 0, eMinus = 0;
    undamped.addEnergy(plus.p(), &ePlus);
    undamped.addEnergy(minus.p(), &eMinus);
    worst = std::max(worst, std::fabs(-(ePlus - eMinus) / (2 * h) - still[i]));
  }
  EXPECT_LT(worst, 1e-6);
  // The Jacobian by position against central differences of the (damped) force.
  World w = springWorld(bodySpec(body, c));
  const Model model = makeModel(w, s);
  AccelerationJacobian jacobian;
  accelerationJacobian(model, s.p(), s.v(), nullptr, &jacobian);
  const Eigen::MatrixXd dAdp(jacobian.dAdp);
  double worstJ = 0, largest = 0;
  for (int column = 0; column < 3 * n; ++column) {
    State plus = s, minus = s;
    plus.p()[column] += h;
    minus.p()[column] -= h;
    std::vector<double> fp(3 * n), fm(3 * n);
    computeForces(model, plus.p(), plus.v(), fp.data());
    computeForces(model, minus.p(), minus.v(), fm.data());
    for (int row = 0; row < 3 * n; ++row) {
      const double fd = (fp[row] - fm[row]) / (2 * h) / w.mass;
      worstJ = std::max(worstJ, std::fabs(fd - dAdp(row, column)));
      largest = std::max(largest, std::fabs(fd));
    }
  }
  EXPECT_LT(worstJ, 1e-6 * largest);
}

TEST(SceneBodies, TheEightByEightLatticeOfASceneIsTheCourseCubeBitForBit) {
  // The default scene (rotate.w's parameters, the cube centred on the origin) and the same cube
  // given as a lattice of 8 points of 1/7 m, over 1000 steps of a spinning start.
  const std::string rest =
      "gravity = [0, 0, -9.81]\n[[sphere]]\ncentre = [0, 0, -1.2]\nradius = 0.6\n";
  const WorldFile given = bodyScene(rest + "[jelly]\nvelocity = [0.5, 0, 1]\n");
  const WorldFile lattice = bodyScene(rest +
                                      "[jelly]\nshape = \"lattice\"\nsize = [8, 8, 8]\n"
                                      "velocity = [0.5, 0, 1]\n");
  ASSERT_TRUE(lattice.world.scene->body && lattice.world.scene->body->courseLattice);
  const Model a = makeModel(given.world, given.state), b = makeModel(lattice.world, lattice.state);
  EXPECT_TRUE(b.forces.springs->rowKernel());
  double moved = 0;
  for (int c = 0; c < kNumCoords; ++c)
    moved = std::max(moved, std::fabs(given.state.p()[c] - lattice.state.p()[c]));
  EXPECT_LT(moved, 1e-15) << "the same placement";
  Simulation one(a, lattice.state, Integrator::RK4, 5e-4),
      two(b, lattice.state, Integrator::RK4, 5e-4);
  ASSERT_TRUE(one.advance(1000).ran() && two.advance(1000).ran());
  EXPECT_EQ(
      std::memcmp(one.state().y.data(), two.state().y.data(), sizeof(double) * 2 * kNumCoords), 0);
}

// A 16x4x4 bar (0.1 m apart) held at one end by its first layer of pins, under gravity, settles
// bent: the pins then hold the whole bar's weight (the springs' forces cancel pairwise), and in
// the small deflections of linear elasticity the tip sags in inverse proportion to the stiffness.
// (IMPLICIT with heavy damping: at rest within 3 s.)
TEST(SceneBodies, ABarHeldAtOneEndCarriesItsWeightOnThePinsAndSagsAsOneOverK) {
  auto settle = [](double k, Vec3* pinForce, double* weight) {
    const WorldFile f = bodyScene(
        "gravity = [0, 0, -9.81]\ndt = 5e-4\n[bounds]\npresent = false\n"
        "[jelly]\nshape = \"lattice\"\nsize = [16, 4, 4]\nspacing = 0.1\ntotal_mass = 1\n"
        "damping = 2\nstiffness = " +
        std::to_string(k) + "\n[[pin]]\ni = [0, 0]\n");
    const Model model = makeModel(f.world, f.state);
    Simulation s(model, f.state, Integrator::Implicit, 2e-3);
    EXPECT_TRUE(s.advanceTo(3).ran());
    const int n = model.points();
    std::vector<double> force(3 * n);
    computeForces(model, s.state().p(), s.state().v(), force.data());
    *pinForce = {};
    for (int q : model.pinned) *pinForce += load(force.data(), q, n);
    *weight = 9.81 * model.world.mass * n;
    const Body& body = model.body();
    double tip = 0;
    for (int q = 0; q < n; ++q)
      if (body.index(q)[0] == 15) tip += load(s.state().p(), q, n).z - load(f.state.p(), q, n).z;
    return tip / 16;
  };
  Vec3 held1, held2;
  double weight = 0;
  const double sag1 = settle(20000, &held1, &weight), sag2 = settle(40000, &held2, &weight);
  std::printf(
      "tip sag %.4g m at k, %.4g m at 2k; pins' net force (%.3g, %.3g, %.3g) N, weight "
      "%.4g N\n",
      sag1, sag2, held1.x, held1.y, held1.z, weight);
  EXPECT_LT(sag1, -1e-3) << "it bends down";
  // The forces on the pinned points (their springs' and their own weight) sum to minus the whole
  // bar's weight: what the pins hold it up with, once every free point is at rest.
  EXPECT_NEAR(held1.z, -weight, 1e-3 * weight);
  EXPECT_NEAR(held1.x, 0, 1e-3 * weight);
  EXPECT_NEAR(sag1 / sag2, 2, 0.05);
}

// A lattice or sheet is bounded by the scene's total, not along an axis: an 81x9x9 beam, a
// 300x300 cloth and a 2000x2x2 rod have their springs counted by hand, no force at rest, and
// stretched along their length pull back at both ends alike (the net force zero).
TEST(SceneBodies, ALatticeOrSheetMayBeLongAlongAnAxisWithinTheScenesTotal) {
  struct Case {
    const char* size;
    int n[3];
    double spacing;
  };
  for (const Case& c :
       {Case{"[81, 9, 9]", {81, 9, 9}, 0.04}, Case{"[300, 300, 1]", {300, 300, 1}, 0.01},
        Case{"[2000, 2, 2]", {2000, 2, 2}, 0.001}}) {
    const WorldFile f = bodyScene(std::string("[bounds]\npresent = false\n[jelly]\nshape = "
                                              "\"lattice\"\nsize = ") +
                                  c.size + "\nspacing = " + std::to_string(c.spacing) + "\n");
    const Model model = makeModel(f.world, f.state);
    const int n = model.points();
    ASSERT_EQ(n, c.n[0] * c.n[1] * c.n[2]) << c.size;
    if (c.n[2] > 1) {
      EXPECT_EQ(model.body().springs.size(), latticeSprings(c.n[0], c.n[1], c.n[2]));
    }
    std::vector<double> force(3 * n), stretched(f.state.p(), f.state.p() + 3 * n);
    computeForces(model, f.state.p(), f.state.v(), force.data());
    double largest = 0;
    for (double x : force) largest = std::max(largest, std::fabs(x));
    EXPECT_LT(largest, 1e-9) << c.size << ": at rest";
    for (int q = 0; q < n; ++q) stretched[q] *= 1.01;  // x, the long axis, 1% longer
    computeForces(model, stretched.data(), f.state.v(), force.data());
    Vec3 net{}, first{};
    for (int q = 0; q < n; ++q) {
      net += load(force.data(), q, n);
      if (model.body().index(q)[0] == 0) first += load(force.data(), q, n);
    }
    EXPECT_GT(first.x, 0) << c.size << ": its first face pulled towards the rest";
    EXPECT_LT(std::fabs(net.x), 1e-9 * std::fabs(first.x)) << c.size;
  }
}

// A point that is not finite is named by its place in its own body's grid, whatever the body's
// count (a 512-point ball is not the course's lattice).
TEST(SceneBodies, APointThatIsNotFiniteIsNamedByItsOwnGridIndex) {
  for (const char* jelly : {"shape = \"sphere\"\nradius = 0.4\nspacing = 0.2\n",
                            "shape = \"lattice\"\nsize = [4, 4, 32]\n"}) {
    WorldFile f = bodyScene(std::string("[jelly]\n") + jelly);
    const Body& body = *f.world.scene->body;
    const int q = body.count() - 1;
    f.state.v()[coordIndex(q, 1, body.count())] = NAN;
    const std::optional<WorldProblem> problem = findWorldProblem(f);
    ASSERT_TRUE(problem) << jelly;
    const std::array<int, 3> i = body.index(q);
    const std::string label = "[" + std::to_string(i[0]) + "][" + std::to_string(i[1]) + "][" +
                              std::to_string(i[2]) + "]";
    EXPECT_NE(problem->what.find("the velocity of point " + label + " is"), std::string::npos)
        << problem->what;
  }
}

TEST(SceneBodies, EveryIntegratorKeepsItsOrderOnAPinnedSphereJelly) {
  const WorldFile f = bodyScene(
      "gravity = [0, 0, -9.81]\n[bounds]\npresent = false\n[jelly]\nshape = \"sphere\"\n"
      "radius = 0.4\nspacing = 0.2\nstiffness = {structural = 600, shear = 300, bend = 100}\n"
      "[[pin]]\nk = [0, 0]\n");
  const Model model = makeModel(f.world, f.state);
  ASSERT_FALSE(model.pinned.empty());
  ASSERT_NE(model.points() % 8, 0) << "the count's tail goes through the point terms too";
  const State reference = test::expectEveryIntegratorsOrder(model, f.state, 0.02);
  const int n = model.points();
  // The pins did not move.
  for (int q : model.pinned)
    for (int axis = 0; axis < 3; ++axis)
      EXPECT_EQ(reference.p()[coordIndex(q, axis, n)], f.state.p()[coordIndex(q, axis, n)]);
}

// A body larger than the course cube is not analysed when its run diverges (minutes at 32^3):
// the message gives a step from the row sums of its stiffness and damping instead, which must be
// below the analysis's limit (else it promises a stability that is not there) and not far below
// it (else it is no help). A 9x9x9 lattice, free and with a pinned face, its initial state
// stretched by 10% along x so that springs carry tension.
TEST(SceneBodies, ALargeBodysDivergenceSuggestsAStepBelowTheAnalysedLimitWithoutAnalysing) {
  for (const char* pin : {"", "[[pin]]\ni = [0, 0]\n"}) {
    SCOPED_TRACE(*pin ? "pinned face" : "free");
    WorldFile f =
        bodyScene(std::string("dt = 0.01\n[jelly]\nshape = \"lattice\"\nsize = [9, 9, 9]\n"
                              "spacing = 0.125\nstiffness = 1000\ndamping = 1\n") +
                  pin);
    const int n = f.state.points();
    ASSERT_GT(n, kNumPoints);
    for (int q = 0; q < n; ++q) f.state.p()[coordIndex(q, 0, n)] *= 1.1;
    const Linearisation analysed = linearise(makeModel(f.world, f.state), f.state);
    for (Integrator integrator : {Integrator::Symplectic, Integrator::Midpoint, Integrator::Verlet,
                                  Integrator::RK4, Integrator::RK45}) {
      SCOPED_TRACE(integratorName(integrator));
      f.run.integrator = integrator;
      const std::string message =
          divergenceMessage(f.world, f.state, f.run.integrator, f.run.dt, 3, 0.03, "a test");
      const std::size_t at = message.find("stable below ");
      ASSERT_NE(at, std::string::npos) << message;
      const double bound = std::stod(message.substr(at + 13));
      const double limit = criticalStep(integrator, analysed.modes);
      EXPECT_LE(bound, limit) << message;
      EXPECT_GT(bound, limit / 25) << message;
    }
    f.run.integrator = Integrator::Euler;
    EXPECT_NE(divergenceMessage(f.world, f.state, f.run.integrator, f.run.dt, 3, 0.03, "a test")
                  .find("row sums cannot bound"),
              std::string::npos);
  }
}

}  // namespace
}  // namespace jello
