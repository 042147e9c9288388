// headless.h: a simulation run without a window (README: Running).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app/pictures.h"
#include "core/limits.h"
#include "core/outcome.h"
#include "model/world.h"
#include "solver/integrators.h"
#include "solver/physics.h"
#include "solver/run.h"
#include "solver/simulation.h"

namespace jello {

// Receives the frames to save (pictures, meshes): the state at step 0 and at the steps of a
// FrameClock (pictures.h) made from the observer's options.
class FrameObserver {
 public:
  virtual ~FrameObserver() = default;
  // What was asked of the pictures: --fps, --max-frames, the folder.
  virtual const PictureOptions& options() const = 0;
  // Called once before the first frame (e.g. to claim the output folder). Throws
  // std::runtime_error with a one-line message to stop the run with exit status 2.
  virtual void begin() {}
  // The state of the run's step `step`, `time` simulated seconds in. Throws
  // std::runtime_error like begin().
  virtual void frame(const Model& model, const State& state, long long step, double time) = 0;
  // False once the observer wants no more frames (the run itself goes on).
  virtual bool wantsMore() const = 0;
  virtual int framesDone() const = 0;
  // How the summary line names the frames, e.g. "300 frames in animation/".
  virtual std::string describe() const = 0;
  // The folders written, as messages name them: "animation/", "animation/ and meshes/".
  virtual std::string folders() const = 0;
};

// --time T runs stepsForTime(T, dt) steps (simulation.h), whole ones: it ends at or just past T.
// Why RK45 stopped at step s (a RunOutcome::Kind::ToleranceUnmet), in one line without "jello: ":
// its tolerances are beyond what double arithmetic resolves.
std::string toleranceFailure(const Tolerances& tolerances, long long s, double dt);

// --dump FILE's rule (README, "Reliability"): it creates FILE or replaces a regular, writable
// file of that name, because the option names it; never the world being run nor any file it
// reads (`inputs`: a scene's world, state, meshes), nor anything that is not a regular file
// (output.h). Why `dumpPath` may not be written, or "".
std::string whyNotDumpable(const std::string& dumpPath, const std::string& worldPath,
                           const std::vector<std::string>& inputs);

// Loads the world, runs it (handing its frames to `frames` when given) and prints the summary
// line on stdout. Fails (or diverges), saying why, without printing it.
Outcome runHeadless(const RunOptions& options, FrameObserver* frames = nullptr);

}  // namespace jello
