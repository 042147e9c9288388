// The force kernel specialised for a scene against the general one (every term at every point),
// and the scene analysis that chooses between them.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <random>
#include <thread>

#include "core/threadpool.h"
#include "solver/integrators.h"
#include "solver/physics.h"
#include "solver/simulation.h"
#include "test_support.h"

namespace jello {
namespace {

// max |a - b| over max |b|: the difference relative to the largest coordinate.
double relativeDifference(const std::vector<double>& a, const std::vector<double>& b) {
  double difference = 0, largest = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    difference = std::max(difference, std::fabs(a[i] - b[i]));
    largest = std::max(largest, std::fabs(b[i]));
  }
  return difference / largest;
}

// 1000 steps with each kernel from the same state; the largest relative difference of the
// states along the way (a NaN counts as a failure).
double kernelsDisagreeBy(const World& world, const State& start, double dt,
                         Integrator integrator = Integrator::RK4) {
  Model specialised = makeModel(world, start, KernelChoice::Specialised);
  Model general = makeModel(world, start, KernelChoice::General);
  EXPECT_TRUE(specialised.forces.culling && !general.forces.culling);
  State a = start, b = start;
  Stepper sa(integrator), sb(integrator);
  double worst = 0;
  for (int s = 0; s < 1000; ++s) {
    sa.step(specialised, a, dt);
    sb.step(general, b, dt);
    double d = relativeDifference(a.y, b.y);
    if (!(d <= worst)) worst = d;  // keeps a NaN
  }
  EXPECT_EQ(findDivergedPoint(b), -1)
      << "the general run diverged: the comparison would mean little";
  return worst;
}

// The kernel's slots against the lattice itself: a slot is kept exactly when its neighbour
// (i+di, j+dj, k+dk) exists, every such pair has a slot, a kept slot's far end is that
// neighbour (never past the last point), and the rest length is |offset|/7.
TEST(SpringSlots, KeptSlotsAreExactlyTheLatticeNeighbours) {
  auto inside = [](int c) { return c >= 0 && c < kLatticeSize; };
  std::size_t kept = 0, slots = 0;
  for (const SpringOffset& offset : kSpringOffsets) {
    EXPECT_DOUBLE_EQ(
        restLength(offset),
        std::sqrt(double(offset.di * offset.di + offset.dj * offset.dj + offset.dk * offset.dk)) /
            7);
    for (int i = 0; i < kLatticeSize; ++i)
      for (int j = 0; j < kLatticeSize; ++j)
        for (int k = 0; k < kLatticeSize; ++k) {
          const int q = pointIndex(i, j, k);
          const bool neighbour =
              inside(i + offset.di) && inside(j + offset.dj) && inside(k + offset.dk);
          const bool computed = rowHasSprings(offset, q / kLatticeSize);
          const bool keep = computed && slotKept(offset, k);
          EXPECT_EQ(keep, neighbour) << offset.di << offset.dj << offset.dk << " point " << q;
          if (keep) {
            EXPECT_EQ(q + springDelta(offset),
                      pointIndex(i + offset.di, j + offset.dj, k + offset.dk));
          }
          kept += keep;
          slots += computed;
        }
  }
  EXPECT_EQ(kept, 6220u);
  EXPECT_EQ(buildSprings().size(), kept);
  std::printf("%zu slots for %zu springs\n", slots, kept);
}

// The kernel against a loop over single springs in docs/physics.md's order (for each offset in
// table order, each point q: F_q = (F_q - f_in) + f_out, a missing spring giving 0), with and
// without dampers: the same bits. The state is jittered and moving, a pair of neighbours shares a
// position (a spring of zero length) and the forces start nonzero (the term adds to them).
TEST(SpringKernel, AddsEachSpringInTheDocumentedOrderBitForBit) {
  std::mt19937 random(16);
  std::uniform_real_distribution<double> jitter(-0.02, 0.02), speed(-3, 3), start(-5, 5);
  State s = test::restLattice();
  for (int c = 0; c < kNumCoords; ++c) {
    s.p()[c] += jitter(random);
    s.v()[c] = speed(random);
  }
  store(s.p(), pointIndex(3, 4, 5), load(s.p(), pointIndex(3, 4, 6)));
  std::vector<double> initial(kNumCoords);
  for (double& f : initial) f = start(random);
  const double k = 734.5, d = 0.8125;
  const std::vector<Spring> springs = buildSprings();  // by offset, in table order
  for (bool dampers : {true, false}) {
    std::vector<double> expected = initial, got = initial;
    int offsets = 0;
    for (std::size_t first = 0, end = 0; first < springs.size(); first = end, ++offsets) {
      const int delta = springs[first].b - springs[first].a;  // one offset: a run of equal deltas
      std::vector<const Spring*> from(kNumPoints, nullptr);
      for (end = first; end < springs.size() && springs[end].b - springs[end].a == delta; ++end)
        from[springs[end].a] = &springs[end];
      auto force = [&](int a) {  // of the spring from a, or 0 when there is none
        if (a < 0 || !from[a]) return Vec3{};
        double len;
        const Vec3 u = direction(load(s.p(), a) - load(s.p(), a + delta), &len);
        double tension = springTension(len, k, from[a]->rest);
        if (dampers) tension += damperTension(load(s.v(), a) - load(s.v(), a + delta), u, d);
        return tension * u;
      };
      for (int q = 0; q < kNumPoints; ++q) {
        const Vec3 in = force(q - delta), out = force(q), total = load(expected.data(), q);
        store(expected.data(), q,
              {(total.x - in.x) + out.x, (total.y - in.y) + out.y, (total.z - in.z) + out.z});
      }
    }
    EXPECT_EQ(offsets, 16);
    SpringTerm(courseBody(), SpringConstants::same(k, d), dampers)
        .addForces(s.p(), s.v(), nullptr, got.data());
    EXPECT_EQ(std::memcmp(got.data(), expected.data(), sizeof(double) * kNumCoords), 0)
        << (dampers ? "with" : "without") << " dampers";
  }
}

class CourseKernels : public ::testing::TestWithParam<const char*> {};

TEST_P(CourseKernels, SpecialisedAgreesWithGeneralOverAThousandSteps) {
  WorldFile f = readWorldFile(test::dataPath(GetParam()));
  double d = kernelsDisagreeBy(f.world, f.state, f.run.dt);
  std::printf("%s: specialised and general kernels differ by %.3g relative\n", GetParam(), d);
  EXPECT_LE(d, 1e-14);
}

INSTANTIATE_TEST_SUITE_P(Worlds, CourseKernels,
                         ::testing::Values("jello.w", "rotate.w", "moveLeft.w", "skewedCorner.w",
                                           "gravity.w"),
                         [](const auto& testInfo) {
                           std::string name = testInfo.param;
                           return name.substr(0, name.find('.'));
                         });

// Random worlds that exercise every branch: with and without dampers, plane and field (absent,
// zero, uniform, trilinear), thrown so that the cube meets walls and the plane within the run.
// Random worlds are run with RK4 at this step, s.
constexpr double kRandomWorldDt = 2e-4;
World randomWorld(std::mt19937& random, State* start) {
  std::uniform_real_distribution<double> unit(0, 1), centred(-1, 1);
  World w;
  w.kElastic = 200 + 800 * unit(random);
  w.dElastic = random() % 3 == 0 ? 0 : unit(random);
  w.kCollision = 500 + 1500 * unit(random);
  w.dCollision = random() % 3 == 0 ? 0 : unit(random);
  w.hasPlane = random() % 2 == 0;
  if (w.hasPlane)
    w.plane = {centred(random), centred(random), 1 + unit(random), 0.8 + unit(random)};
  const int kind = static_cast<int>(random() % 4);  // absent, zero, uniform, trilinear
  if (kind > 0) {
    w.field.resolution = 2 + static_cast<int>(random() % 5);
    std::size_t nodes =
        static_cast<std::size_t>(w.field.resolution) * w.field.resolution * w.field.resolution;
    w.field.forces.assign(3 * nodes, 0.0);
    Vec3 constant{centred(random), centred(random), centred(random)};
    for (std::size_t n = 0; n < nodes; ++n) {
      if (kind == 2) w.field.setNode(n, constant);
      if (kind == 3) w.field.setNode(n, Vec3{centred(random), centred(random), centred(random)});
    }
  }
  *start = test::restLattice();
  Vec3 shift{centred(random), centred(random), centred(random)};
  Vec3 velocity = 6.0 * Vec3{centred(random), centred(random), centred(random)};
  for (int q = 0; q < kNumPoints; ++q) {
    store(start->p(), q, load(start->p(), q) + shift);
    store(start->v(), q, velocity + 0.3 * Vec3{centred(random), centred(random), centred(random)});
  }
  return w;
}

TEST(RandomKernels, SpecialisedAgreesWithGeneralOverAThousandSteps) {
  std::mt19937 random(20261122);
  for (int world = 0; world < 12; ++world) {
    State start;
    World w = randomWorld(random, &start);
    double d = kernelsDisagreeBy(w, start, kRandomWorldDt);
    std::printf("random world %d (%s): %.3g\n", world,
                termsLine(makeModel(w, start).forces).c_str(), d);
    EXPECT_LE(d, 1e-14) << "random world " << world;
  }
}

// The kernel a range of rows at a time (what each of two threads computes) against the whole
// pass, bit for bit: every split of the rows in two, on states where every term acts (random
// worlds thrown against the walls and the plane, 300 steps on), a pulled point in either range.
// Each range follows a whole pass on another state, so that the kernel's scratch on the stack
// (the spring rings) holds that state's values wherever the range reads a slot it has not
// written.
TEST(KernelRanges, EverySplitIntoTwoRangesGivesTheWholePassBitForBit) {
  std::mt19937 random(20261123);
  int compared = 0;
  for (int world = 0; world < 6; ++world) {
    State state;
    const World w = randomWorld(random, &state);
    for (KernelChoice choice : {KernelChoice::Specialised, KernelChoice::General}) {
      const Model model = makeModel(w, state, choice);
      State s = state;
      Stepper stepper(Integrator::RK4);
      for (int step = 0; step < 300; ++step) stepper.step(model, s, kRandomWorldDt);
      const Bounds box = boundsOf(s.p(), kNumPoints);
      const Bounds* reach = model.forces.culling ? &box : nullptr;
      State other = s;
      for (int c = 0; c < kNumCoords; ++c) other.p()[c] += 0.01 * std::sin(c);
      std::vector<double> junk(kNumCoords);
      for (int pulled : {-1, 37, 400}) {
        const Pull pull{pulled, {0.1, 0.2, 0.3}, 50};
        std::vector<double> whole(kNumCoords), parts(kNumCoords, 1.0);
        computeForces(model, s.p(), s.v(), whole.data(), &pull);
        for (int split = kLatticeSize; split < kNumPoints; split += kLatticeSize) {
          for (PointRange range : {PointRange{split, kNumPoints}, PointRange{0, split}}) {
            computeForcesOn(model, {0, kNumPoints}, other.p(), s.v(), reach, junk.data(), &pull);
            computeForcesOn(model, range, s.p(), s.v(), reach, parts.data(), &pull);
          }
          ASSERT_EQ(std::memcmp(parts.data(), whole.data(), sizeof(double) * kNumCoords), 0)
              << "random world " << world << ", split at point " << split;
          ++compared;
        }
      }
    }
  }
  EXPECT_EQ(compared, 6 * 2 * 3 * 63);
}

// Two threads (core/threadpool.h; a course cube is given one by its size, here two whatever the
// size) step exactly as one: 1000 RK4 steps of each course world, compared bit for bit along the
// way.
TEST(KernelRanges, ATwoThreadRunIsTheOneThreadRunBitForBit) {
  ThreadPool pool(2);
  for (const char* name : {"jello.w", "rotate.w", "moveLeft.w", "skewedCorner.w", "gravity.w"}) {
    const WorldFile f = readWorldFile(test::dataPath(name));
    const Model model = makeModel(f.world, f.state);
    Simulation one(model, f.state, Integrator::RK4, f.run.dt);
    Simulation two(model, f.state, Integrator::RK4, f.run.dt);
    two.setPool(&pool, false);
    ASSERT_EQ(two.threads(), 2);
    for (int step = 0; step < 1000; ++step) {
      ASSERT_TRUE(one.advance(1).ran() && two.advance(1).ran()) << name;
      ASSERT_EQ(std::memcmp(one.state().y.data(), two.state().y.data(),
                            sizeof(double) * one.state().y.size()),
                0)
          << name << " at step " << step + 1;
    }
  }
}

// The field as the specialised kernel interpolates it (8 points at a time, on padded nodes)
// against the reference point by point, bit for bit: points inside the box, on its walls and
// corners, on nodes, outside it and not a number, for several resolutions, with and without the
// positions' bounds (which let the kernel skip the inside test).
TEST(FieldKernel, PaddedInterpolationIsTheReferenceBitForBit) {
  std::mt19937 random(2016);
  std::uniform_real_distribution<double> inBox(-2, 2), around(-2.5, 2.5), force(-3, 3);
  for (int r : {2, 3, 5, 30}) {
    World w;
    w.field.resolution = r;
    w.field.forces.resize(3 * std::size_t(r) * r * r);
    for (double& f : w.field.forces) f = force(random);
    State s = test::restLattice();
    for (int c = 0; c < kNumCoords; ++c) s.p()[c] = around(random);
    const double node = fieldNodeCoordinate(1, r);
    const Vec3 special[] = {{2, 2, 2},   {-2, -2, -2}, {2, -2, 0.5}, {node, node, node},
                            {NAN, 0, 0}, {0, 0, NAN},  {2.5, 0, 0},  {0, -2.0000001, 1}};
    for (int q = 0; q < 8; ++q) store(s.p(), 17 * q, special[q]);
    State inside = s;
    for (int c = 0; c < kNumCoords; ++c) inside.p()[c] = inBox(random);
    const FieldTerm padded(kNumPoints, w.field, w.mass, FieldTerm::Method::Padded),
        reference(kNumPoints, w.field, w.mass, FieldTerm::Method::Reference);
    for (const State* state : {&s, &inside}) {
      const Bounds box = boundsOf(state->p(), kNumPoints);
      std::vector<double> expected(kNumCoords, 1.0), got(kNumCoords, 1.0), bounded(kNumCoords, 1.0);
      reference.addForces(state->p(), state->v(), nullptr, expected.data());
      padded.addForces(state->p(), state->v(), nullptr, got.data());
      padded.addForces(state->p(), state->v(), &box, bounded.data());
      EXPECT_EQ(std::memcmp(got.data(), expected.data(), sizeof(double) * kNumCoords), 0) << r;
      EXPECT_EQ(std::memcmp(bounded.data(), expected.data(), sizeof(double) * kNumCoords), 0) << r;
    }
  }
}

// The culls are exact: a point a hair past a wall or across the plane gets the same force
// from both kernels, and a force it would not get without the contact.
TEST(Culling, APointJustPastAWallOrThePlaneIsNotMissed) {
  World w = test::springsOnlyWorld();
  w.kCollision = 1000;
  w.dCollision = 0.5;
  w.hasPlane = true;
  w.plane = {0, 0, 1, 1};  // z = -1; the cube is above it
  State s = test::restLattice();
  Model specialised = makeModel(w, s, KernelChoice::Specialised),
        general = makeModel(w, s, KernelChoice::General);
  for (Vec3 p :
       {Vec3{0.5, 0.5, -1 - 1e-12}, Vec3{2 + 1e-12, 0.5, 0.5}, Vec3{0.5, -2 - 1e-15, 0.5}}) {
    State t = s;
    store(t.p(), pointIndex(3, 3, 3), p);
    store(t.v(), pointIndex(3, 3, 3), {1, 1, 1});  // so that the contact's damper adds 0.5 N
    std::vector<double> a(kNumCoords), b(kNumCoords), none(kNumCoords);
    computeForces(specialised, t.p(), t.v(), a.data());
    computeForces(general, t.p(), t.v(), b.data());
    EXPECT_EQ(a, b) << p.x << " " << p.y << " " << p.z;
    World without = w;
    without.kCollision = without.dCollision = 0;
    Model free = makeModel(without, s);
    computeForces(free, t.p(), t.v(), none.data());
    EXPECT_NE(load(a.data(), pointIndex(3, 3, 3)).x + load(a.data(), pointIndex(3, 3, 3)).y +
                  load(a.data(), pointIndex(3, 3, 3)).z,
              load(none.data(), pointIndex(3, 3, 3)).x + load(none.data(), pointIndex(3, 3, 3)).y +
                  load(none.data(), pointIndex(3, 3, 3)).z)
        << "no contact force";
  }
}

// What a specialised scene keeps and what it leaves out, for a world at rest.
std::string sceneOf(const World& w) { return termsLine(makeModel(w, test::restLattice()).forces); }

TEST(Scene, FieldAndPlaneAnalysis) {
  World w;
  w.dElastic = 0.25;
  EXPECT_EQ(fieldUse(w.field), FieldUse::Absent);
  EXPECT_NE(sceneOf(w).find("left out: plane (none in the file), field (none in the file)"),
            std::string::npos)
      << sceneOf(w);
  w.field.resolution = 2;
  w.field.forces.assign(24, 0.0);
  EXPECT_EQ(fieldUse(w.field), FieldUse::Zero);
  EXPECT_NE(sceneOf(w).find("field (all zero)"), std::string::npos) << sceneOf(w);
  for (std::size_t n = 0; n < 8; ++n) w.field.setNode(n, {0, 0, -9.8});
  EXPECT_EQ(fieldUse(w.field), FieldUse::Uniform);
  EXPECT_NE(sceneOf(w).find(
                "kept: springs, dampers, walls (when the cube's bounding box reaches them), field "
                "(uniform: a constant, no interpolation)"),
            std::string::npos)
      << sceneOf(w);
  w.field.setNode(7, {0, 0, std::nextafter(-9.8, 0.0)});
  EXPECT_EQ(fieldUse(w.field), FieldUse::Trilinear);
  EXPECT_NE(sceneOf(w).find("field (trilinear, 2^3 nodes)"), std::string::npos) << sceneOf(w);
  w.dElastic = 0;
  EXPECT_NE(sceneOf(w).find("left out: dampers (zero damping), plane"), std::string::npos)
      << sceneOf(w);
  w.dElastic = 0.1;
  w.hasPlane = true;
  w.plane = {0, 0, 1, 1};
  EXPECT_NE(
      sceneOf(w).find(
          "kept: springs, dampers, walls (when the cube's bounding box reaches them), plane (when "
          "the bounding box reaches it), field (trilinear"),
      std::string::npos)
      << sceneOf(w);
  EXPECT_NE(sceneOf(w).find("left out: nothing"), std::string::npos) << sceneOf(w);
}

// The scene line of a headless run (issue 7's examples).
std::string sceneLineOf(const std::string& world) {
  test::CommandResult r = test::runJello("--headless --steps 1 '" + test::dataPath(world) + "'");
  EXPECT_EQ(r.status, 0) << r.err;
  std::string line = r.out.substr(0, r.out.find('\n'));
  EXPECT_EQ(line.rfind("scene: kept: ", 0), 0u) << r.out;
  return line;
}

TEST(Scene, MoveLeftLeavesOutFieldAndPlane) {
  std::string line = sceneLineOf("moveLeft.w");
  std::string left = line.substr(line.find("; left out: "));
  EXPECT_NE(left.find("field (all zero)"), std::string::npos) << line;
  EXPECT_NE(left.find("plane (none in the file)"), std::string::npos) << line;
}

TEST(Scene, RotateKeepsItsField) {
  std::string line = sceneLineOf("rotate.w");
  std::string kept = line.substr(0, line.find("; left out: "));
  EXPECT_NE(kept.find("field (trilinear, 30^3 nodes)"), std::string::npos) << line;
  EXPECT_NE(kept.find("plane"), std::string::npos) << line;
}

// The same run through the command line with either kernel ends in the same state, bit for bit.
TEST(Scene, TheGeneralKernelFromTheCommandLineGivesTheSameResult) {
  std::string dir = test::makeTempDir();
  for (const char* kernel : {"specialised", "general"}) {
    test::CommandResult r =
        test::runJello("--headless --steps 300 --kernel " + std::string(kernel) + " --dump '" +
                       dir + "/" + kernel + ".w' '" + test::dataPath("moveLeft.w") + "'");
    EXPECT_EQ(r.status, 0) << r.err;
  }
  EXPECT_EQ(test::readText(dir + "/specialised.w"), test::readText(dir + "/general.w"));
  test::removeTree(dir);
}

TEST(Scene, GravityIsAConstant) {
  std::string line = sceneLineOf("gravity.w");
  EXPECT_NE(line.find("field (uniform"), std::string::npos) << line;
}

}  // namespace
}  // namespace jello
