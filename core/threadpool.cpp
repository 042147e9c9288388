// core/threadpool.cpp: the pool of threadpool.h. Why the waiting is done this way: a condition
// variable alone costs a futex wake and a context switch (5 to 50 us here) at every evaluation of
// a stepping run; spinning alone would hold every core for as long as the pool lives, paused
// windows included. Spinning a while after each job, then sleeping, costs neither.

#include "core/threadpool.h"

#include <sched.h>

#include <system_error>

#include "core/assert.h"

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace jello {

namespace {
// A spin-wait's pause: it frees the core's resources for a moment and saves power.
inline void relax() {
#if defined(__x86_64__) || defined(__i386__)
  _mm_pause();
#endif
}
}  // namespace

int availableCores() {
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof set, &set) == 0 && CPU_COUNT(&set) > 0) return CPU_COUNT(&set);
  const unsigned hardware = std::thread::hardware_concurrency();
  return hardware > 0 ? static_cast<int>(hardware) : 1;
}

ThreadPool::ThreadPool(int threads) {
  JELLO_ASSERT(threads >= 1);
  // A system that starts no more threads (a cgroup's limit) leaves the pool with those it did.
  try {
    for (int t = 1; t < threads; ++t) workers_.emplace_back([this] { workerLoop(); });
  } catch (const std::system_error&) {
  }
}

ThreadPool::~ThreadPool() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  for (std::thread& worker : workers_) worker.join();
}

void ThreadPool::runParts(int parts, Call call, const void* context) {
  JELLO_ASSERT(parts >= 1 && parts <= kMostParts);
  if (workers_.empty() || parts == 1) {
    for (int part = 0; part < parts; ++part) call(context, part);
    return;
  }
  // The fields first, then the word that publishes them. The workers of the last job have
  // finished every part of it: none reads the fields or counts a part until it takes one of
  // this job's, which the word's generation says.
  call_.store(call, std::memory_order_relaxed);
  context_.store(context, std::memory_order_relaxed);
  finished_.store(0, std::memory_order_relaxed);
  const std::uint32_t generation = generationOf(job_.load(std::memory_order_relaxed)) + 1;
  job_.store(word(generation, parts, 0));  // sequentially consistent, as sleeping_ below
  // The word is stored before sleeping_ is read, and a worker counts itself in sleeping_ before
  // it reads the word again under the mutex: either it sees this job or it is woken here.
  if (sleeping_.load() > 0) {
    std::lock_guard<std::mutex> lock(mutex_);
    wake_.notify_all();
  }
  takeParts(generation);
  for (int spins = 0; finished_.load(std::memory_order_acquire) != parts; ++spins) {
    if (spins < 4096)
      relax();
    else
      std::this_thread::yield();  // a worker holding the last part was descheduled
  }
}

void ThreadPool::takeParts(std::uint32_t generation) {
  for (;;) {
    std::uint64_t w = job_.load(std::memory_order_acquire);
    const int parts = int(w >> 16 & 0xffff), next = int(w & 0xffff);
    if (generationOf(w) != generation || next >= parts) return;
    // The fields are read before the part is taken: once taken, the job cannot end (and its
    // fields change) before this part returns; if the word changed, the take fails.
    const Call call = call_.load(std::memory_order_relaxed);
    const void* context = context_.load(std::memory_order_relaxed);
    if (!job_.compare_exchange_weak(w, w + 1, std::memory_order_acq_rel)) continue;
    call(context, next);
    finished_.fetch_add(1, std::memory_order_acq_rel);
  }
}

bool ThreadPool::awaitJob(std::uint32_t seen) {
  const auto until = std::chrono::steady_clock::now() + kSpinFor;
  for (int spins = 0; generationOf(job_.load(std::memory_order_acquire)) == seen && !stopping_;
       ++spins) {
    relax();
    if (spins % 256 != 255) continue;
    std::this_thread::yield();  // another program waiting for this core runs first
    if (std::chrono::steady_clock::now() > until) {
      std::unique_lock<std::mutex> lock(mutex_);
      ++sleeping_;
      wake_.wait(lock, [&] { return stopping_ || generationOf(job_.load()) != seen; });
      --sleeping_;
    }
  }
  return !stopping_;
}

void ThreadPool::workerLoop() {
  std::uint32_t seen = 0;
  while (awaitJob(seen)) {
    seen = generationOf(job_.load(std::memory_order_acquire));
    takeParts(seen);
  }
}

}  // namespace jello
