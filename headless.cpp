// headless.cpp: load, step, report; no GL anywhere on this path.

#include "headless.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "guard.h"
#include "output.h"
#include "integrators.h"
#include "physics.h"
#include "stability.h"

namespace jello {

namespace {

using Clock = std::chrono::steady_clock;

constexpr long long kGuardEvery = 8;  // steps between energy checks at least

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// A progress line on a terminal, rewritten in place at most a few times a second, only once
// the run has taken long enough for a user to wonder. Silent when stderr is not a terminal.
class Progress {
 public:
  Progress(long long totalSteps, const FrameObserver* frames)
      : total_(totalSteps), frames_(frames), enabled_(::isatty(STDERR_FILENO) == 1) {}

  void update(long long done) {
    if (!enabled_ || (done & 63) != 0) return;
    double elapsed = secondsSince(start_);
    if (elapsed < kQuietSeconds || elapsed - lastShown_ < kRefreshSeconds) return;
    lastShown_ = elapsed;
    double left = elapsed / done * (total_ - done);
    if (frames_) {
      std::fprintf(stderr, "\rframe %d, %.0f frames/s, step %lld/%lld, %.0f s left   ", frames_->framesDone(),
                   frames_->framesDone() / elapsed, done, total_, left);
    } else {
      std::fprintf(stderr, "\rstep %lld/%lld (%.0f%%), %.0f s left   ", done, total_, 100.0 * done / total_, left);
    }
    shown_ = true;
  }

  ~Progress() {
    if (shown_) std::fprintf(stderr, "\r%70s\r", "");
  }

 private:
  static constexpr double kQuietSeconds = 1.0;
  static constexpr double kRefreshSeconds = 0.25;
  long long total_;
  const FrameObserver* frames_;
  bool enabled_;
  bool shown_ = false;
  double lastShown_ = 0;
  Clock::time_point start_ = Clock::now();
};

// Why RK45 stopped at step s: its tolerances are beyond what double arithmetic resolves.
std::string toleranceFailure(const Tolerances& tolerances, long long s, double dt) {
  char text[320];
  std::snprintf(
      text, sizeof text,
      "RK45 cannot meet --rtol %g --atol %g: at step %lld (t=%g s) its error estimate stayed above "
      "them down to substeps of %.2g s, where rounding decides it; loosen them (the defaults are "
      "--rtol 1e-6 --atol 1e-9)",
      tolerances.rtol, tolerances.atol, s, s * dt, kSmallestSubstep * dt);
  return text;
}

}  // namespace

std::string whyNotDumpable(const std::string& dumpPath, const std::string& worldPath) {
  if (sameFile(dumpPath, worldPath)) return "is the world being run; it is never replaced, name another file";
  return whyNotWritable(dumpPath, Existing::Replace);
}

std::optional<long long> stepsForTime(double time, double dt) {
  const double steps = std::ceil(time / dt * (1 - 1e-9));
  if (!(steps <= kMaxSteps)) return std::nullopt;  // also NaN and infinity
  return static_cast<long long>(std::max(steps, 0.0));
}

std::string tooManyStepsMessage(double time, double dt) {
  char steps[64] = "more steps than a double can count";
  if (std::isfinite(time / dt)) std::snprintf(steps, sizeof steps, "%g steps", time / dt);
  char text[256];
  std::snprintf(text, sizeof text,
                "--time %g s at --dt %g s would take %s, more than the %g a run may take; choose a "
                "shorter --time or a larger --dt",
                time, dt, steps, kMaxSteps);
  return text;
}

bool loadRun(const RunOptions& options, WorldFile* out) {
  try {
    *out = readWorldFile(options.worldPath);
  } catch (const WorldFileError& e) {
    printError(e.what());
    return false;
  }
  World& world = out->world;
  if (options.integrator) world.integrator = *options.integrator;
  if (options.dt) world.dt = *options.dt;
  if (options.n) world.n = *options.n;
  return true;
}

int runHeadless(const RunOptions& options, FrameObserver* frames) {
  WorldFile file;
  if (!loadRun(options, &file)) return kExitBadInput;
  const World& world = file.world;

  long long steps = kDefaultFrames * world.n;
  if (!options.steps && !options.time && steps > kMostDefaultSteps) {
    printError(options.worldPath + ": n = " + std::to_string(world.n) + " makes the default run (300 frames of n steps) " +
               std::to_string(steps) + " steps long; say how long with --steps N or --time T, or lower n with --n");
    return kExitBadInput;
  }
  if (options.steps) steps = *options.steps;
  if (options.time) {
    std::optional<long long> forTime = stepsForTime(*options.time, world.dt);
    if (!forTime) {
      std::fprintf(stderr, "jello: %s\n", tooManyStepsMessage(*options.time, world.dt).c_str());
      return kExitBadInput;
    }
    steps = *forTime;
  }

  if (options.dumpPath) {
    std::string why = whyNotDumpable(*options.dumpPath, options.worldPath);
    if (!why.empty()) {
      printError("--dump " + *options.dumpPath + ": " + why);
      return kExitBadInput;
    }
  }

  const Model model = makeModel(world, file.state, options.kernel);
  const State initial = file.state;
  State& state = file.state;
  DivergenceGuard guard(model, initial);
  Stepper stepper(world.integrator, options.tolerances);
  Progress progress(steps, frames);
  Clock::time_point start = Clock::now();
  try {
    if (frames) {
      frames->begin();
      frames->frame(model, state);
    }
  } catch (const std::runtime_error& e) {
    printError(e.what());
    return kExitBadInput;
  }
  std::printf("%s%s\n", sceneLine(model.scene, world).c_str(),
              options.kernel == KernelChoice::General ? "; --kernel general computes every term at every point anyway" : "");
  for (long long s = 1; s <= steps; ++s) {
    stepper.step(model, state, world.dt);
    if (stepper.stats().failed > 0) {
      std::fprintf(stderr, "jello: %s: %s\n", options.worldPath.c_str(),
                   toleranceFailure(options.tolerances, s, world.dt).c_str());
      return kExitBadInput;
    }
    // Every step: the cheap test of SPEC (non-finite, 100 m); every drawn frame, but not more
    // often than every kGuardEvery steps: the energy.
    std::string wrong;
    if (findDivergedPoint(state) >= 0 || s % std::max<long long>(world.n, kGuardEvery) == 0)
      wrong = guard.check(state, s * world.dt);
    if (!wrong.empty()) {
      printError(options.worldPath + ": " + divergenceMessage(world, initial, s, s * world.dt, wrong));
      return kExitDiverged;
    }
    if (frames && s % world.n == 0 && frames->wantsMore()) {
      try {
        frames->frame(model, state);
      } catch (const std::runtime_error& e) {
        printError(e.what());
        return kExitBadInput;
      }
    }
    progress.update(s);
  }
  double wall = secondsSince(start);

  std::printf("%s: %s dt=%.9g steps=%lld simulated=%.9g s wall=%.6f s %.2f us/step", options.worldPath.c_str(),
              integratorName(world.integrator), world.dt, steps, steps * world.dt, wall,
              steps > 0 ? wall * 1e6 / steps : 0.0);
  const StepStats& stats = stepper.stats();
  if (world.integrator == Integrator::RK45) {
    std::printf("; %lld substeps accepted, %lld rejected, %lld evaluations", stats.steps, stats.rejected,
                stats.evaluations);
  }
  if (world.integrator == Integrator::Implicit) {
    std::printf("; %lld Newton iterations, %lld evaluations", stats.newtonIterations, stats.evaluations + stats.jacobians);
  }
  if (frames) std::printf("; %s (%.1f frames/s)", frames->describe().c_str(), frames->framesDone() / wall);
  std::printf("\n");
  std::fflush(stdout);

  if (options.dumpPath) {
    try {
      writeWorldFile(*options.dumpPath, world, state, true);
    } catch (const std::exception& e) {
      printError(e.what());
      return kExitBadInput;
    }
  }
  return kExitOk;
}

}  // namespace jello
