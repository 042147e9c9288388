// core/team.h: two threads sharing one job: the calling thread and a helper thread that waits
// between jobs. For the force kernel of one run, which is a few microseconds: the helper spins
// between jobs (a job follows the last within microseconds while a run is stepping) and sleeps
// only after kSpinFor without one, so a paused window or a finished run costs no core. When the
// helper has not taken its part by the time this thread has done its own (the other core busy
// with another program), this thread does that part too: a job never waits for a helper that
// the system has not scheduled.
//
// Lifetime: the helper starts with the Team and is joined by its destructor. One thread at a
// time calls run(); a Team is not shared between runs.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>

namespace jello {

class Team {
 public:
  static constexpr int kParts = 2;
  // How long the helper spins for the next job before it sleeps.
  static constexpr std::chrono::microseconds kSpinFor{200};

  Team();
  ~Team();
  Team(const Team&) = delete;
  Team& operator=(const Team&) = delete;

  // Runs job(0) on this thread and job(1) on the helper (or here, after job(0), when the helper
  // has not begun it); returns when both have returned. The job must not throw.
  template <class Job>
  void run(const Job& job) {
    runParts([](const void* context, int part) { (*static_cast<const Job*>(context))(part); },
             &job);
  }

 private:
  using Call = void (*)(const void* context, int part);
  void runParts(Call call, const void* context);
  void helperLoop();
  bool awaitJob(unsigned seen);  // false: stop

  bool claim(unsigned job);  // whether this caller takes part 1 of `job`

  std::atomic<unsigned> posted_{0}, claimed_{0}, finished_{0};
  std::atomic<bool> sleeping_{false}, stopping_{false};
  Call call_ = nullptr;
  const void* context_ = nullptr;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::thread helper_;
};

}  // namespace jello
