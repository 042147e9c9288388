// core/threadpool.h: worker threads that share the parts of one job with the thread that posts it,
// for the force evaluations of a large body (a job every few hundred microseconds while a run is
// stepping, each part a range of points).
//
// A job is `parts` calls job(0) .. job(parts - 1). The posting thread takes parts too, and any
// thread takes the next part not yet taken: a worker the system has not scheduled (the machine
// busy with other programs) never holds a job up, its parts are taken by the others. Between jobs
// a worker spins for kSpinFor (the next evaluation of a stepping run follows within that), then
// sleeps until the next job: a paused window, a finished run or a machine whose cores are taken
// costs no core. Which thread computes a part changes nothing in its results.
//
// Lifetime: the workers start with the pool and are joined by its destructor. One thread at a
// time posts jobs (run); a job must not post another, nor throw.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

namespace jello {

// The cores this process may run on (its affinity mask), at least 1.
int availableCores();

class ThreadPool {
 public:
  // How long a worker spins for the next job before it sleeps.
  static constexpr std::chrono::microseconds kSpinFor{2000};
  // The most parts a job may have.
  static constexpr int kMostParts = 0xffff;

  // `threads` threads in all (at least 1): this one and threads - 1 workers (fewer when the
  // system starts no more: threads() says how many).
  explicit ThreadPool(int threads);
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;
  int threads() const { return static_cast<int>(workers_.size()) + 1; }

  // Calls job(part) for every part in [0, parts), each exactly once, on this thread and the
  // workers; returns when all have returned. 1 <= parts <= kMostParts.
  template <class Job>
  void run(int parts, const Job& job) {
    runParts(
        parts, [](const void* context, int part) { (*static_cast<const Job*>(context))(part); },
        &job);
  }

 private:
  using Call = void (*)(const void* context, int part);
  // The job word: generation (32 bits), parts (16), next part to take (16).
  static std::uint64_t word(std::uint32_t generation, int parts, int next) {
    return std::uint64_t(generation) << 32 | std::uint64_t(parts) << 16 | std::uint64_t(next);
  }
  static std::uint32_t generationOf(std::uint64_t w) { return std::uint32_t(w >> 32); }
  void runParts(int parts, Call call, const void* context);
  void takeParts(std::uint32_t generation);  // until the job has no part left to take
  void workerLoop();
  bool awaitJob(std::uint32_t seen);  // false: stop

  std::atomic<std::uint64_t> job_{0};
  std::atomic<Call> call_{nullptr};
  std::atomic<const void*> context_{nullptr};
  alignas(64) std::atomic<int> finished_{0};  // parts of the current job that have returned,
                                              // on a cache line apart from job_ (taken by CAS)
  std::atomic<int> sleeping_{0};
  std::atomic<bool> stopping_{false};
  std::mutex mutex_;
  std::condition_variable wake_;
  std::vector<std::thread> workers_;
};

}  // namespace jello
