// core/team.cpp: the two-thread job of team.h. Why the waiting is done this way: a condition
// variable alone costs a futex wake and a context switch (~5-20 us here), more than the whole
// force evaluation it would share; spinning alone would hold a core for as long as the Team
// lives, paused windows included.

#include "core/team.h"

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

Team::Team() : helper_([this] { helperLoop(); }) {}

Team::~Team() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_one();
  helper_.join();
}

void Team::runParts(Call call, const void* context) {
  call_ = call;
  context_ = context;
  // posted_ is read by the helper after sleeping_ is set, and sleeping_ here after posted_ is
  // bumped (both sequentially consistent): either the helper sees the job or this sees it asleep.
  const unsigned job = posted_.fetch_add(1) + 1;
  if (sleeping_.load()) {
    std::lock_guard<std::mutex> lock(mutex_);
    wake_.notify_one();
  }
  call(context, 0);
  if (claim(job)) {
    call(context, 1);
    return;
  }
  while (finished_.load(std::memory_order_acquire) != job) relax();
}

bool Team::claim(unsigned job) {
  unsigned previous = job - 1;
  return claimed_.compare_exchange_strong(previous, job);
}

bool Team::awaitJob(unsigned seen) {
  const auto until = std::chrono::steady_clock::now() + kSpinFor;
  for (int spins = 0; posted_.load(std::memory_order_acquire) == seen && !stopping_; ++spins) {
    relax();
    if (spins % 256 == 255 && std::chrono::steady_clock::now() > until) {
      std::unique_lock<std::mutex> lock(mutex_);
      sleeping_ = true;
      wake_.wait(lock, [&] { return stopping_ || posted_.load() != seen; });
      sleeping_ = false;
    }
  }
  return !stopping_;
}

void Team::helperLoop() {
  unsigned seen = 0;
  while (awaitJob(seen)) {
    seen = posted_.load(std::memory_order_acquire);
    if (!claim(seen)) continue;  // the caller took part 1 itself
    call_(context_, 1);
    finished_.store(seen, std::memory_order_release);
  }
}

}  // namespace jello
