// The job queue of jello --report: dearest first, jobs that add jobs, results in fixed slots,
// every job run exactly once, the first failure rethrown.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <functional>
#include <mutex>
#include <random>
#include <stdexcept>
#include <vector>

#include "analysis/runqueue.h"

namespace jello {
namespace {

// On one thread the jobs run in the queue's order: the dearest first, equal costs in the order
// they were added, and a job added by a running one takes its place by its cost among those
// still queued.
TEST(RunQueue, RunsTheDearestJobFirstAndEqualCostsInTheOrderAdded) {
  RunQueue queue;
  std::vector<int> order;
  for (auto [cost, name] : {std::pair{3.0, 3}, {1.0, 1}, {5.0, 5}, {2.0, 2}, {5.0, 6}})
    queue.add(cost, [&order, name = name] { order.push_back(name); });
  queue.add(4, [&] {
    order.push_back(4);
    queue.add(2.5, [&order] { order.push_back(25); });  // between 3 and 2
    queue.add(10, [&order] { order.push_back(10); });   // dearer than all left: next
  });
  queue.run(1);
  EXPECT_EQ(order, (std::vector<int>{5, 6, 4, 10, 3, 25, 2, 1}));
}

// On several threads every job runs exactly once, those added by running jobs (three levels
// deep) included, and each result lands in the slot fixed for it, whichever thread ran it.
TEST(RunQueue, RunsEveryJobExactlyOnceOnEveryThreadWithResultsInTheirSlots) {
  constexpr int kRoots = 200, kChildren = 3, kDepth = 3;
  int total = 0;
  for (int level = 0, width = kRoots; level < kDepth; ++level, width *= kChildren) total += width;
  std::vector<std::atomic<int>> runs(total);
  std::vector<long long> results(total, -1);
  RunQueue queue;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> cost(0, 1);
  std::mutex costs;  // the generator, shared by the jobs that add jobs
  // Job `slot` at `level` writes slot * slot and adds its children, slots numbered level by level.
  std::function<void(int, int, int)> add = [&](int slot, int level, int levelStart) {
    double c;
    {
      std::lock_guard<std::mutex> lock(costs);
      c = cost(random);
    }
    queue.add(c, [&, slot, level, levelStart] {
      ++runs[slot];
      results[slot] = static_cast<long long>(slot) * slot;
      if (level + 1 == kDepth) return;
      const int width = kRoots * static_cast<int>(std::pow(kChildren, level));
      const int nextStart = levelStart + width;
      for (int child = 0; child < kChildren; ++child)
        add(nextStart + (slot - levelStart) * kChildren + child, level + 1, nextStart);
    });
  };
  for (int slot = 0; slot < kRoots; ++slot) add(slot, 0, 0);
  queue.run(4);
  for (int slot = 0; slot < total; ++slot) {
    EXPECT_EQ(runs[slot].load(), 1) << slot;
    EXPECT_EQ(results[slot], static_cast<long long>(slot) * slot) << slot;
  }
}

// A job that throws: run() rethrows its exception after the running jobs end, and the jobs not
// yet begun are not run.
TEST(RunQueue, RethrowsTheFirstFailureAndRunsNothingAfterIt) {
  RunQueue queue;
  int after = 0;
  queue.add(2, [] { throw std::runtime_error("the first failure"); });
  for (int i = 0; i < 5; ++i) queue.add(1, [&after] { ++after; });
  try {
    queue.run(1);
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "the first failure");
  }
  EXPECT_EQ(after, 0);
}

}  // namespace
}  // namespace jello
