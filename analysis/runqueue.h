// runqueue.h: independent jobs worked by one thread a core, the dearest first (jello --report's
// runs). A job may add jobs; every job runs exactly once; a job writes its results to a place
// fixed before it runs, so that what the jobs make does not depend on which thread ran what, nor
// in which order.
#pragma once

#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <queue>
#include <vector>

namespace jello {

class RunQueue {
 public:
  // Queues a job of `cost` (any unit: only the order matters). May be called from a running job.
  void add(double cost, std::function<void()> job);
  // Runs every job, the ones they add included, on `threads` threads (this one among them, and
  // only this one when no other can be had): the dearest queued job first, among equal costs the
  // first added. Returns when none is queued or running. Rethrows the first exception a job
  // threw; the jobs not yet begun then are not run.
  void run(unsigned threads);

 private:
  struct Job {
    double cost;
    long long order;  // among equal costs, the first added first
    std::function<void()> run;
    bool operator<(const Job& o) const { return cost != o.cost ? cost < o.cost : order > o.order; }
  };
  void work();

  std::mutex mutex_;
  std::condition_variable changed_;
  std::priority_queue<Job> jobs_;
  long long added_ = 0;
  int running_ = 0;
  std::exception_ptr failure_;
};

}  // namespace jello
