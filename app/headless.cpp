// headless.cpp: load, step, report; no GL anywhere on this path.

#include "app/headless.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "analysis/stability.h"
#include "core/output.h"
#include "core/progress.h"
#include "core/threadpool.h"
#include "io/scenereader.h"
#include "io/statefile.h"
#include "solver/integrators.h"
#include "solver/physics.h"
#include "solver/simulation.h"

namespace jello {

namespace {

using Clock = std::chrono::steady_clock;

constexpr long long kProgressEvery = 64;  // steps between looks at the progress line

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The run's progress line, redrawn at most a few times a second, and only once the run has
// taken long enough for a user to wonder.
class RunProgress {
 public:
  RunProgress(long long totalSteps, const FrameObserver* frames)
      : total_(totalSteps), frames_(frames) {}

  void update(long long done) {
    if (!line_.enabled() || done % kProgressEvery != 0) return;
    double elapsed = secondsSince(start_);
    if (elapsed < kQuietSeconds || elapsed - lastShown_ < kRefreshSeconds) return;
    lastShown_ = elapsed;
    double left = elapsed / done * (total_ - done);
    char text[160];
    if (frames_) {
      std::snprintf(text, sizeof text, "frame %d, %.0f frames/s, step %lld/%lld, %.0f s left",
                    frames_->framesDone(), frames_->framesDone() / elapsed, done, total_, left);
    } else {
      std::snprintf(text, sizeof text, "step %lld/%lld (%.0f%%), %.0f s left", done, total_,
                    100.0 * done / total_, left);
    }
    line_.show(text);
  }
  // The last line says the run is done, then ends: the summary starts a line of its own.
  void finish(long long total) {
    if (line_.shown())
      line_.finish(textf("step %lld/%lld (100%%) in %.1f s", total, total, secondsSince(start_)));
    else
      line_.finish();
  }

 private:
  static constexpr double kQuietSeconds = 1.0;
  static constexpr double kRefreshSeconds = 0.25;
  long long total_;
  const FrameObserver* frames_;
  Progress line_;
  double lastShown_ = 0;
  Clock::time_point start_ = Clock::now();
};

}  // namespace

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

namespace {

// The smallest multiple of `every` (>= 1) after `done`.
long long nextMultiple(long long done, long long every) {
  return every > 0 ? (done / every + 1) * every : done + 1;
}

// How many steps the run takes: --steps, --time, or by default 300 frames of n steps, or, when
// frames are saved by simulated time, --max-frames of them. Fails, saying why, when the run is
// refused.
Outcome stepsOfRun(const RunOptions& options, const RunSettings& world, const FrameObserver* frames,
                   long long* steps) {
  const bool byTime = frames && frames->options().fps > 0;
  std::string length = "300 frames of n steps";
  *steps = kDefaultFrames * world.n;
  if (byTime) {
    const PictureOptions& pictures = frames->options();
    *steps = FrameClock(pictures.fps, world.n, world.dt).stepsForFrames(pictures.maxFrames);
    length = textf("%d frames at %g a simulated second", pictures.maxFrames, pictures.fps);
  }
  if (!options.steps && !options.time && *steps > kMostDefaultSteps) {
    return failed(options.worldPath + ": the default run (" + length + ") would be " +
                  std::to_string(*steps) + " steps long; say how long with --steps N or --time T" +
                  (byTime ? ", or save fewer frames with --max-frames" : ", or lower n with --n"));
  }
  if (options.steps) *steps = *options.steps;
  if (options.time) {
    std::optional<long long> forTime = stepsForTime(*options.time, world.dt);
    if (!forTime) return failed(tooManyStepsMessage(*options.time, world.dt));
    *steps = *forTime;
  }
  return succeeded();
}

// Calls the frame observer; fails with its one-line message when it throws.
template <class Call>
Outcome observed(Call call) {
  try {
    call();
    return succeeded();
  } catch (const std::runtime_error& e) {
    return failed(e.what());
  }
}

// Why a run stopped: RK45's unmet tolerances are bad input, anything else a divergence.
Outcome runFailure(const RunOptions& options, const Simulation& run, const State& initial,
                   const RunOutcome& outcome) {
  if (outcome.kind == RunOutcome::Kind::ToleranceUnmet)
    return failed(options.worldPath + ": " +
                  toleranceFailure(options.tolerances, outcome.step, run.dt()));
  return diverged(options.worldPath + ": " +
                  divergenceMessage(run.model().world, initial, run.integrator(), run.dt(),
                                    outcome.step, outcome.time, outcome.reason));
}

// The summary line on stdout.
void printSummary(const RunOptions& options, const RunSettings& world, long long steps, double wall,
                  const StepStats& stats, int threads, const FrameObserver* frames) {
  std::printf("%s: %s dt=%.9g steps=%lld simulated=%.9g s wall=%.6f s %.2f us/step",
              options.worldPath.c_str(), integratorName(world.integrator), world.dt, steps,
              steps * world.dt, wall, steps > 0 ? wall * 1e6 / steps : 0.0);
  if (threads > 1) std::printf(" on %d threads", threads);
  if (world.integrator == Integrator::RK45) {
    std::printf("; %lld substeps accepted, %lld rejected, %lld evaluations", stats.steps,
                stats.rejected, stats.evaluations);
  }
  if (world.integrator == Integrator::Implicit) {
    std::printf("; %lld Newton iterations, %lld evaluations", stats.newtonIterations,
                stats.evaluations + stats.jacobians);
  }
  if (frames)
    std::printf("; %s (%.1f frames/s)", frames->describe().c_str(), frames->framesDone() / wall);
  std::printf("\n");
  std::fflush(stdout);
}

// Said when --max-frames stopped the saving before the run's end.
std::string frameLimitNote(const FrameObserver& frames, double savedUntil, double runTime) {
  const int most = frames.options().maxFrames;
  return textf(
      "note: %s: saving stopped at %d frames, the most --max-frames %d allows, at %.3g s of the "
      "run's %.3g s; raise --max-frames (up to %d) or lower --fps to save the whole run",
      frames.folders().c_str(), most, most, savedUntil, runTime, kMaxFrames);
}

}  // namespace

std::string whyNotDumpable(const std::string& dumpPath, const std::string& worldPath,
                           const std::vector<std::string>& inputs) {
  if (sameFile(dumpPath, worldPath))
    return "is the world being run; it is never replaced, name another file";
  for (const std::string& input : inputs)
    if (sameFile(dumpPath, input))
      return "is read by the scene being run (" + input +
             "); it is never replaced, name another file";
  if (heldByAnotherRun(folderOf(dumpPath)))
    return "its folder is in use by another run (its frames or meshes); wait for it, or name a "
           "file elsewhere";
  return whyNotWritable(dumpPath, Existing::Replace);
}

namespace {

// Whether --save-state and --dump may write their files (whyNotDumpable), and the world is one a
// world file holds.
Outcome checkDump(const RunOptions& options, const WorldFile& file) {
  const World& world = file.world;
  if (options.saveStatePath)
    if (const std::string why =
            whyNotDumpable(*options.saveStatePath, options.worldPath, file.inputs);
        !why.empty())
      return failed("--save-state " + *options.saveStatePath + ": " + why);
  if (!options.dumpPath) return succeeded();
  // A course world file holds the 8x8x8 cube and nothing else.
  const Body& body = bodyOf(world);
  if (!body.courseLattice || hasElements(world)) {
    const std::string what = body.joined()        ? "this scene has " + body.what
                             : hasElements(world) ? "this scene's jelly is made of finite elements"
                                                  : "this scene's jelly is " + body.what;
    return failed("--dump " + *options.dumpPath + ": a world file holds only the course's " +
                  "8x8x8 cube of springs, and " + what +
                  "; use --save-state for every point or --export for the surface");
  }
  std::string why = whyNotDumpable(*options.dumpPath, options.worldPath, file.inputs);
  if (!why.empty()) return failed("--dump " + *options.dumpPath + ": " + why);
  return succeeded();
}

// --dump FILE: the run's last state in a world file.
Outcome writeDump(const std::string& path, const World& world, const RunSettings& run,
                  const State& state) {
  try {
    writeWorldFile(path, world, run, state, true);
  } catch (const std::exception& e) {
    return failed(e.what());
  }
  // A course world holds no gravity, obstacles, pins or bounds: said, so that nobody runs the
  // dump alone and wonders why the jelly floats.
  if (world.scene)
    printError("note: " + path +
               " holds the state and the course parameters, not the scene's gravity, "
               "obstacles, pins or bounds; a scene with world = \"" +
               path + "\" and those keys continues from it");
  return succeeded();
}

// --save-state FILE and --dump FILE: the run's last state.
Outcome writeFinalState(const RunOptions& options, const Model& model, const RunSettings& run,
                        const State& state) {
  if (options.saveStatePath) {
    try {
      writeStateFile(*options.saveStatePath, model.body(), state);
    } catch (const std::exception& e) {
      return failed(e.what());
    }
  }
  return options.dumpPath ? writeDump(*options.dumpPath, model.world, run, state) : succeeded();
}

}  // namespace

Outcome runHeadless(const RunOptions& options, FrameObserver* frames) {
  WorldFile file;
  if (Outcome loaded = loadRun(options, &file); !loaded.ok()) return loaded;
  const World& world = file.world;
  long long steps = 0;
  if (Outcome counted = stepsOfRun(options, file.run, frames, &steps); !counted.ok())
    return counted;
  if (Outcome dumpable = checkDump(options, file); !dumpable.ok()) return dumpable;

  const Model model = makeModel(world, file.state, options.kernel);
  ThreadPool pool(threadsFor(model, options.threads));  // before the simulation, which uses it
  Simulation simulation(model, file.state, file.run, options.tolerances);
  simulation.setPool(&pool);
  RunProgress progress(steps, frames);
  Clock::time_point start = Clock::now();
  const auto showFrame = [&] {
    frames->frame(model, simulation.state(), simulation.step(), simulation.time());
  };
  if (frames) {
    if (Outcome begun = observed([&] {
          frames->begin();
          showFrame();
        });
        !begun.ok())
      return begun;
  }
  std::printf("%s%s\n", termsLine(model.forces).c_str(),
              options.kernel == KernelChoice::General
                  ? "; --kernel general computes every term at every point anyway"
                  : "");
  // In stretches that end where a frame is due or the progress line may be redrawn.
  const FrameClock clock(frames ? frames->options().fps : 0, file.run.n, simulation.dt());
  long long nextFrame = frames ? clock.nextAfter(0) : steps;
  long long lastFrame = 0;  // the step of the last frame saved
  while (simulation.step() < steps) {
    const long long done = simulation.step();
    const long long stop = std::min({steps, nextMultiple(done, kProgressEvery), nextFrame});
    const RunOutcome outcome = simulation.advance(stop - done);
    if (!outcome.ran()) return runFailure(options, simulation, file.state, outcome);
    if (frames && simulation.step() == nextFrame) {
      nextFrame = clock.nextAfter(nextFrame);
      if (frames->wantsMore()) {
        if (Outcome shown = observed(showFrame); !shown.ok()) return shown;
        lastFrame = simulation.step();
      }
    }
    progress.update(simulation.step());
  }
  progress.finish(steps);
  printSummary(options, file.run, steps, secondsSince(start), simulation.stats(),
               simulation.threads(), frames);
  if (frames && !frames->wantsMore() && lastFrame < steps)
    printError(frameLimitNote(*frames, lastFrame * simulation.dt(), steps * simulation.dt()));

  return writeFinalState(options, model, file.run, simulation.state());
}

}  // namespace jello
