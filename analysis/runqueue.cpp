// runqueue.cpp: the job queue of jello --report.

#include "analysis/runqueue.h"

#include <system_error>
#include <thread>

namespace jello {

void RunQueue::add(double cost, std::function<void()> job) {
  std::lock_guard<std::mutex> lock(mutex_);
  jobs_.push({cost, added_++, std::move(job)});
  changed_.notify_one();
}

void RunQueue::run(unsigned threads) {
  std::vector<std::thread> others;
  for (unsigned t = 1; t < threads; ++t) {
    try {
      others.emplace_back([this] { work(); });
    } catch (const std::system_error&) {
      break;
    }
  }
  work();
  for (std::thread& other : others) other.join();
  if (failure_) std::rethrow_exception(failure_);
}

void RunQueue::work() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    // Done when nothing is queued and no running job can add more.
    changed_.wait(lock, [this] { return !jobs_.empty() || running_ == 0; });
    if (jobs_.empty()) return;
    Job job = jobs_.top();
    jobs_.pop();
    ++running_;
    const bool skip = failure_ != nullptr;  // after a failure the rest is not worth running
    lock.unlock();
    try {
      if (!skip) job.run();
    } catch (...) {
      std::lock_guard<std::mutex> failed(mutex_);
      if (!failure_) failure_ = std::current_exception();
    }
    lock.lock();
    --running_;
    changed_.notify_all();
  }
}

}  // namespace jello
