// headless.cpp: load, step, report; no GL anywhere on this path.

#include "headless.h"

#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "integrators.h"
#include "physics.h"

namespace jello {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// A progress line on a terminal, rewritten in place at most a few times a second, only once
// the run has taken long enough for a user to wonder. Silent when stderr is not a terminal.
class Progress {
 public:
  explicit Progress(long long total) : total_(total), enabled_(::isatty(STDERR_FILENO) == 1) {}

  void update(long long done) {
    if (!enabled_ || (done & 255) != 0) return;
    double elapsed = secondsSince(start_);
    if (elapsed < kQuietSeconds || elapsed - lastShown_ < kRefreshSeconds) return;
    lastShown_ = elapsed;
    double left = elapsed / done * (total_ - done);
    std::fprintf(stderr, "\rstep %lld/%lld (%.0f%%), %.0f s left   ", done, total_,
                 100.0 * done / total_, left);
    shown_ = true;
  }

  ~Progress() {
    if (shown_) std::fprintf(stderr, "\r%60s\r", "");
  }

 private:
  static constexpr double kQuietSeconds = 1.0;
  static constexpr double kRefreshSeconds = 0.25;
  long long total_;
  bool enabled_;
  bool shown_ = false;
  double lastShown_ = 0;
  Clock::time_point start_ = Clock::now();
};

// Why `path` cannot be written, or "" when it can: checked before a long run, not after it.
std::string whyNotWritable(const std::string& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode)) return "is a directory";
  std::size_t slash = path.find_last_of('/');
  std::string dir = slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
  if (::access(dir.c_str(), W_OK) != 0) return std::string("cannot write into ") + dir + ": " + std::strerror(errno);
  return {};
}

}  // namespace

long long stepsForTime(double time, double dt) {
  return static_cast<long long>(std::ceil(time / dt * (1 - 1e-9)));
}

int runHeadless(const RunOptions& options) {
  WorldFile file;
  try {
    file = readWorldFile(options.worldPath);
  } catch (const WorldFileError& e) {
    std::fprintf(stderr, "jello: %s\n", e.what());
    return kExitBadInput;
  }
  World& world = file.world;
  if (options.integrator) world.integrator = *options.integrator;
  if (options.dt) world.dt = *options.dt;
  if (options.n) world.n = *options.n;
  if (!isImplemented(world.integrator)) {
    std::fprintf(stderr, "jello: integrator %s is not available yet (EULER and RK4 are)\n",
                 integratorName(world.integrator));
    return kExitBadInput;
  }

  long long steps = kDefaultFrames * world.n;
  if (options.steps) steps = *options.steps;
  if (options.time) steps = stepsForTime(*options.time, world.dt);

  if (!options.dumpPath.empty()) {
    std::string why = whyNotWritable(options.dumpPath);
    if (!why.empty()) {
      std::fprintf(stderr, "jello: --dump %s: %s\n", options.dumpPath.c_str(), why.c_str());
      return kExitBadInput;
    }
  }

  const Model model = makeModel(world, file.state);
  State& state = file.state;
  Workspace workspace;
  Progress progress(steps);
  Clock::time_point start = Clock::now();
  for (long long s = 1; s <= steps; ++s) {
    step(model, world.integrator, world.dt, state, workspace);
    int bad = findDivergedPoint(state);
    if (bad >= 0) {
      Vec3 p = load(state.p(), bad), v = load(state.v(), bad);
      bool finite = std::isfinite(dot(p, p)) && std::isfinite(dot(v, v));
      std::fprintf(stderr,
                   "jello: %s: diverged at step %lld (t=%.9g s) with %s dt=%.9g: point %s %s; "
                   "try a smaller --dt\n",
                   options.worldPath.c_str(), s, s * world.dt, integratorName(world.integrator),
                   world.dt, ("p" + latticeLabel(bad)).c_str(),
                   finite ? "is more than 100 m from the origin" : "is no longer finite");
      return kExitDiverged;
    }
    progress.update(s);
  }
  double wall = secondsSince(start);

  std::printf("%s: %s dt=%.9g steps=%lld simulated=%.9g s wall=%.6f s %.2f us/step\n",
              options.worldPath.c_str(), integratorName(world.integrator), world.dt, steps,
              steps * world.dt, wall, steps > 0 ? wall * 1e6 / steps : 0.0);
  std::fflush(stdout);

  if (!options.dumpPath.empty()) {
    try {
      writeWorldFile(options.dumpPath, world, state);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "jello: %s\n", e.what());
      return kExitBadInput;
    }
  }
  return kExitOk;
}

}  // namespace jello
