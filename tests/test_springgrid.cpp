// The grid kernel of every body (model/springgrid.h) against the spring list, bit for bit; on
// every range of points and on any number of threads (core/threadpool.h), bit for bit; the pool
// itself; and how a run is split between threads (solver/physics.h workersFor).
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstring>
#include <memory>
#include <random>
#include <thread>

#include "core/threadpool.h"
#include "solver/physics.h"
#include "solver/simulation.h"
#include "test_support.h"

namespace jello {
namespace {

// The body at rest moved and deformed pseudo-randomly, with velocities; two neighbours share a
// position (a spring of zero length).
State shakenBody(const Body& body, std::mt19937_64& random, double amount) {
  std::uniform_real_distribution<double> u(-amount, amount);
  State s(body.count());
  const std::vector<double> rest = restPositionsOf(body);
  std::copy(rest.begin(), rest.end(), s.p());
  for (double& y : s.y) y += u(random);
  if (body.count() > 1) store(s.p(), 1, body.count(), load(s.p(), 0, body.count()));
  return s;
}

// A ball of voxels: the voxels of an r-voxel-radius ball in a (2r)^3 grid.
VoxelMask voxelBall(int r) {
  VoxelMask mask{2 * r, 2 * r, 2 * r, std::vector<char>(8 * r * r * r, 0)};
  for (int i = 0; i < 2 * r; ++i)
    for (int j = 0; j < 2 * r; ++j)
      for (int k = 0; k < 2 * r; ++k) {
        const double x = i + 0.5 - r, y = j + 0.5 - r, z = k + 0.5 - r;
        mask.filled[mask.cell(i, j, k)] = x * x + y * y + z * z <= r * r;
      }
  return mask;
}

// A mask with about `fill` of its voxels filled, at random.
VoxelMask randomVoxels(int nx, int ny, int nz, double fill, std::mt19937_64& random) {
  VoxelMask mask{nx, ny, nz, std::vector<char>(std::size_t(nx) * ny * nz, 0)};
  std::bernoulli_distribution filled(fill);
  for (char& f : mask.filled) f = filled(random);
  mask.filled[0] = 1;
  return mask;
}

// Lattices of every shape the kernel treats apart (rows shorter and longer than a unit, rows
// that do not fill whole units, sheets in each plane, a body of 2 points a side), balls and
// random voxels (rows with gaps, isolated points).
std::vector<Body> gridBodies() {
  std::mt19937_64 random(30);
  std::vector<Body> out = {
      latticeBody(2, 2, 2, 0.3),   latticeBody(3, 5, 7, 0.1),         latticeBody(9, 9, 9, 0.05),
      latticeBody(6, 4, 17, 0.07), latticeBody(12, 1, 10, 0.1),       latticeBody(1, 6, 6, 0.1),
      latticeBody(7, 7, 1, 0.1),   latticeBody(16, 16, 16, 1.0 / 15), latticeBody(3, 3, 40, 0.02)};
  out.push_back(voxelBody(voxelBall(4), 0.1, "a ball"));
  out.push_back(voxelBody(randomVoxels(5, 6, 7, 0.5, random), 0.1, "random voxels"));
  out.push_back(voxelBody(randomVoxels(9, 3, 11, 0.3, random), 0.1, "sparse random voxels"));
  return out;
}

const SpringConstants kGridSprings{{600, 250, 90}, {0.4, 0.15, 0.05}};

// Every body through its grid (not the row kernel, not the list) against the same springs
// through their list, with and without dampers, from forces that start nonzero: the same bits.
TEST(GridKernel, EveryBodySumsAsTheSpringListBitForBit) {
  std::mt19937_64 random(31);
  for (const Body& body : gridBodies()) {
    const int n = body.count();
    const State s = shakenBody(body, random, 0.02);
    std::vector<double> start(3 * n);
    for (double& f : start) f = std::uniform_real_distribution<double>(-3, 3)(random);
    for (bool dampers : {true, false}) {
      const SpringTerm grid(body, kGridSprings, dampers),
          list(body, kGridSprings, dampers, SpringKernel::List);
      ASSERT_FALSE(grid.rowKernel() || grid.listKernel()) << body.what;
      ASSERT_TRUE(list.listKernel());
      std::vector<double> a = start, b = start;
      grid.addForces(s.p(), s.v(), nullptr, a.data());
      list.addForces(s.p(), s.v(), nullptr, b.data());
      EXPECT_EQ(std::memcmp(a.data(), b.data(), sizeof(double) * 3 * n), 0)
          << body.what << (dampers ? " with" : " without") << " dampers";
      EXPECT_NE(std::memcmp(a.data(), start.data(), sizeof(double) * 3 * n), 0) << body.what;
    }
  }
}

// On every range of points (from every multiple of kRangeAlignment to the end, and from the start
// to it, and a range in the middle), the grid kernel adds what the whole pass adds there and
// touches nothing else, bit for bit. Each range follows a pass over another body and another
// state, so that this thread's scratch (rings, window) holds other values.
TEST(GridKernel, EveryRangeGivesTheWholePassBitForBit) {
  std::mt19937_64 random(32);
  const std::vector<Body> all = gridBodies();
  const Body& other = all[7];
  const State otherState = shakenBody(other, random, 0.05);
  const SpringTerm otherTerm(other, kGridSprings, true);
  std::vector<double> junk(3 * other.count());
  int compared = 0;
  for (const Body& body : all) {
    const int n = body.count();
    const State s = shakenBody(body, random, 0.02);
    const SpringTerm term(body, kGridSprings, true);
    std::vector<double> whole(3 * n, 0.0);
    term.addForces(s.p(), s.v(), nullptr, whole.data());
    for (int split = 0; split <= n; split += kRangeAlignment) {
      const int middle = std::min(n, split + 3 * kRangeAlignment);
      for (const PointRange range :
           {PointRange{0, split}, PointRange{split, n}, PointRange{split, middle}}) {
        std::vector<double> part(3 * n, 7.0);  // outside the range: untouched
        for (int a = 0; a < 3; ++a)
          std::fill(part.begin() + a * n + range.begin, part.begin() + a * n + range.end, 0.0);
        otherTerm.addForces(otherState.p(), otherState.v(), nullptr, junk.data());
        term.addForcesOn(range, s.p(), s.v(), nullptr, part.data());
        for (int a = 0; a < 3; ++a)
          for (int q = 0; q < n; ++q) {
            const bool in = q >= range.begin && q < range.end;
            const double expected = in ? whole[a * n + q] : 7.0;
            ASSERT_EQ(std::memcmp(&part[a * n + q], &expected, sizeof(double)), 0)
                << body.what << " range [" << range.begin << ", " << range.end << ") point " << q;
          }
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 1000);
}

// A scene's several jellies joined into one body: each part through its own grid with its own
// constants, as the list sums them.
TEST(GridKernel, AJoinedBodySumsEachPartAsTheListDoes) {
  std::mt19937_64 random(33);
  const Body joined = joinBodies({std::make_shared<Body>(latticeBody(5, 6, 7, 0.1)),
                                  std::make_shared<Body>(voxelBody(voxelBall(3), 0.08, "a ball")),
                                  std::make_shared<Body>(latticeBody(4, 4, 1, 0.2))});
  const std::vector<SpringConstants> byPart = {kGridSprings, SpringConstants::same(900, 0.7),
                                               SpringConstants{{50, 40, 30}, {0, 0.01, 0}}};
  const int n = joined.count();
  const State s = shakenBody(joined, random, 0.02);
  const SpringTerm grid(joined, byPart, true), list(joined, byPart, true, SpringKernel::List);
  ASSERT_FALSE(grid.listKernel());
  std::vector<double> a(3 * n, 0.0), b(3 * n, 0.0);
  grid.addForces(s.p(), s.v(), nullptr, a.data());
  list.addForces(s.p(), s.v(), nullptr, b.data());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), sizeof(double) * 3 * n), 0);
  for (int split = 0; split <= n; split += kRangeAlignment) {
    std::vector<double> parts(3 * n, 0.0);
    grid.addForcesOn({0, split}, s.p(), s.v(), nullptr, parts.data());
    grid.addForcesOn({split, n}, s.p(), s.v(), nullptr, parts.data());
    ASSERT_EQ(std::memcmp(parts.data(), b.data(), sizeof(double) * 3 * n), 0) << split;
  }
}

// A body whose springs are not in the grid's order (or not of its offsets' rest lengths) is left
// to the list, which sums them as they are.
TEST(GridKernel, SpringsOutOfTheGridsOrderGoThroughTheList) {
  Body body = latticeBody(4, 4, 4, 0.1);
  std::swap(body.springs[3], body.springs[5]);
  EXPECT_FALSE(SpringGrid(body).represents());
  EXPECT_TRUE(SpringTerm(body, kGridSprings, true).listKernel());
  Body longer = latticeBody(4, 4, 4, 0.1);
  longer.springs[0].rest *= 1.5;
  EXPECT_TRUE(SpringTerm(longer, kGridSprings, true).listKernel());
  EXPECT_FALSE(SpringTerm(latticeBody(4, 4, 4, 0.1), kGridSprings, true).listKernel());
}

World gridSceneWorld(const Body& body, double mass) {
  World w = test::springsOnlyWorld();
  w.mass = mass;
  auto spec = std::make_shared<SceneSpec>();
  spec->body = std::make_shared<Body>(body);
  spec->springs = kGridSprings;
  spec->gravity = {0, 0, -9.81};
  w.scene = spec;
  return w;
}

// The bounds of a state's ranges, put together, are the bounds of the whole state, whatever the
// ranges (the threads' culling box), to the bit.
TEST(Threads, TheBoundsOfRangesAreTheBoundsOfTheWhole) {
  std::mt19937_64 random(35);
  const Body body = latticeBody(7, 5, 9, 0.1);
  const int n = body.count();
  const State s = shakenBody(body, random, 0.3);
  const Bounds whole = boundsOf(s.p(), n);
  for (int split = kRangeAlignment; split < n; split += kRangeAlignment) {
    const Bounds a = boundsOf(s.p(), n, {0, split}), b = boundsOf(s.p(), n, {split, n});
    const Vec3 lower{std::min(a.lower.x, b.lower.x), std::min(a.lower.y, b.lower.y),
                     std::min(a.lower.z, b.lower.z)};
    const Vec3 upper{std::max(a.upper.x, b.upper.x), std::max(a.upper.y, b.upper.y),
                     std::max(a.upper.z, b.upper.z)};
    ASSERT_TRUE(lower.x == whole.lower.x && lower.y == whole.lower.y && lower.z == whole.lower.z)
        << split;
    ASSERT_TRUE(upper.x == whole.upper.x && upper.y == whole.upper.y && upper.z == whole.upper.z)
        << split;
  }
  const Bounds one = boundsOf(s.p(), n, {8, 9});
  EXPECT_EQ(one.lower.x, s.p()[8]);
  EXPECT_EQ(one.upper.z, s.p()[2 * n + 8]);
}

// A run on 1, 2, 3 and 8 threads (the ranges by cost, whatever the body's size) takes the same
// steps, bit for bit: RK4 steps of a lattice that does not fill whole units and of a ball of
// voxels, and of a body of a thousand points given a part each of more threads than it has ranges.
TEST(Threads, AnyNumberOfThreadsStepsAsOneBitForBit) {
  std::mt19937_64 random(34);
  ThreadPool pools[] = {ThreadPool(2), ThreadPool(3), ThreadPool(8)};
  for (const Body& body : {latticeBody(13, 11, 9, 0.05), voxelBody(voxelBall(6), 0.04, "a ball"),
                           latticeBody(10, 10, 10, 0.05)}) {
    const State start = shakenBody(body, random, 0.004);
    const World world = gridSceneWorld(body, 0.002);
    const Model model = makeModel(world, start);
    Simulation one(model, start, Integrator::RK4, 2e-4);
    ASSERT_TRUE(one.advance(60).ran()) << body.what;
    for (ThreadPool& pool : pools) {
      Simulation many(model, start, Integrator::RK4, 2e-4);
      many.setPool(&pool, false);
      EXPECT_EQ(many.threads(), pool.threads()) << body.what;
      ASSERT_TRUE(many.advance(60).ran()) << body.what;
      EXPECT_EQ(std::memcmp(one.state().y.data(), many.state().y.data(),
                            sizeof(double) * one.state().y.size()),
                0)
          << body.what << " on " << pool.threads() << " threads";
    }
  }
}

// The ranges of a run: in order, covering every point once, each beginning on a multiple of
// kRangeAlignment, of about equal cost (a range after the first computing again the slots before
// it); and a body gets one thread below kFewestPointsShared points, else one for each
// kPointsPerThread points, two at least.
TEST(Threads, ARunIsSplitIntoRangesOfEqualCostAndThreadsBySize) {
  ThreadPool pool(4);
  const Body big = latticeBody(30, 30, 30, 0.01), ball = voxelBody(voxelBall(14), 0.01, "a ball");
  for (const Body* body : {&big, &ball}) {
    const State rest(body->count());
    const Model model = makeModel(gridSceneWorld(*body, 0.001), rest);
    const Workers workers = workersFor(model, &pool, false);
    ASSERT_EQ(workers.threads(), 4);
    int next = 0;
    long long least = -1, most = 0;
    for (const PointRange& r : workers.parts) {
      EXPECT_EQ(r.begin, next);
      EXPECT_EQ(r.begin % kRangeAlignment, 0);
      EXPECT_GT(r.end, r.begin);
      next = r.end;
      const long long cost = model.forces.springs->costOf(r) + (r.end - r.begin) +
                             (r.begin > 0 ? model.forces.springs->warmUpCost() : 0);
      least = least < 0 ? cost : std::min(least, cost);
      most = std::max(most, cost);
    }
    EXPECT_EQ(next, model.points());
    EXPECT_LT(double(most - least) / most, 0.05) << body->what;
  }
  const Model cube = makeModel(test::springsOnlyWorld(), test::restLattice());
  EXPECT_EQ(workersFor(cube, &pool).threads(), 1);
  EXPECT_EQ(threadsFor(cube, 16), 1);
  const Model large = makeModel(gridSceneWorld(big, 0.001), State(big.count()));
  EXPECT_EQ(threadsFor(large, 16), 27000 / kPointsPerThread);
  EXPECT_EQ(threadsFor(large, 2), 2);
  EXPECT_EQ(threadsFor(large, 1), 1);
  EXPECT_EQ(workersFor(large, &pool).threads(), std::min(4, 27000 / kPointsPerThread));
  for (int edge : {11, 12, 16}) {  // 1,331, 1,728 and 4,096 points
    const Body lattice = latticeBody(edge, edge, edge, 0.05);
    const Model m = makeModel(gridSceneWorld(lattice, 0.001), State(lattice.count()));
    EXPECT_EQ(threadsFor(m, 8), lattice.count() < kFewestPointsShared ? 1 : 2) << edge;
  }
}

// The pool runs each part of each job exactly once, whichever thread takes it: jobs of 1 to 40
// parts on 4 threads, some parts slow; jobs after the workers have gone to sleep; a job whose
// part 0 waits until part 1 has begun, which another thread must then take (every thousandth,
// and one just after the workers slept), however busy the machine.
TEST(Threads, ThePoolRunsEachPartOfEachJobExactlyOnce) {
  ThreadPool pool(4);
  EXPECT_EQ(pool.threads(), 4);
  std::atomic<long long> total{0};
  long long expected = 0;
  for (int job = 0; job < 20000; ++job) {
    const int parts = 1 + job % 40;
    const bool wait = job % 1000 == 1 || job == 10001;
    std::vector<std::atomic<int>> seen(parts);
    std::atomic<bool> partOneBegun{false};
    pool.run(wait ? 2 : parts, [&](int part) {
      if (part == 1) partOneBegun = true;
      if (part == 0 && wait) {
        const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(5);
        while (!partOneBegun && std::chrono::steady_clock::now() < until) std::this_thread::yield();
      } else if (part % 3 == 0) {
        for (volatile int spin = 0; spin < 1000; ++spin) {
        }
      }
      ++seen[part];
      total += part + 1;
    });
    for (int part = 0; part < (wait ? 2 : parts); ++part) ASSERT_EQ(seen[part], 1) << job;
    expected += wait ? 3 : parts * (parts + 1) / 2;
    if (wait) {
      ASSERT_TRUE(partOneBegun) << "job " << job;
    }
    if (job == 10000) std::this_thread::sleep_for(4 * ThreadPool::kSpinFor);  // the workers sleep
  }
  EXPECT_EQ(total, expected);
  EXPECT_GE(availableCores(), 1);
}

}  // namespace
}  // namespace jello
