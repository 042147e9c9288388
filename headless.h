// headless.h: a simulation run without a window (SPEC.md section 4).
#pragma once

#include <optional>
#include <string>

#include "integrators.h"
#include "physics.h"
#include "world.h"

namespace jello {

// What the command line asks of a run; unset values come from the world file.
struct RunOptions {
  std::string worldPath;
  std::optional<long long> steps;  // --steps N
  std::optional<double> time;      // --time T, seconds
  std::optional<Integrator> integrator;
  std::optional<double> dt;  // s
  std::optional<int> n;
  std::optional<std::string> dumpPath;  // --dump FILE
  Tolerances tolerances;  // RK45's error control
  KernelChoice kernel = KernelChoice::Specialised;  // --kernel general: every term at every point
};

// Exit statuses of SPEC.md section 4.
constexpr int kExitOk = 0;
constexpr int kExitDiverged = 1;
constexpr int kExitBadInput = 2;

// The default length of a run: 300 drawn frames of n steps each.
constexpr long long kDefaultFrames = 300;
// A default run longer than this (n above 100,000) is refused rather than started: at about
// 100 us an RK4 step it would take most of an hour, which nobody asks for without saying so.
constexpr long long kMostDefaultSteps = 30'000'000;

// Receives the frames a viewer would draw: the state at step 0 and after every n steps.
class FrameObserver {
 public:
  virtual ~FrameObserver() = default;
  // Called once before the first frame (e.g. to claim the output folder). Throws
  // std::runtime_error with a one-line message to stop the run with exit status 2.
  virtual void begin() {}
  // Throws std::runtime_error like begin().
  virtual void frame(const Model& model, const State& state) = 0;
  // False once the observer wants no more frames (the run itself goes on).
  virtual bool wantsMore() const = 0;
  virtual int framesDone() const = 0;
  // How the summary line names the frames, e.g. "300 frames in animation/".
  virtual std::string describe() const = 0;
};

// The most steps a run may take. 1e12 steps are months of computing at the kernel's microseconds
// a step, so no run meant to finish asks for more; and up to it a step count, and the time
// s * dt of step s, are exact in a double (2^53 ~ 9e15) and far from long long's limit.
constexpr double kMaxSteps = 1e12;

// Number of steps that --time T asks for at step dt: the fewest that reach T (a relative slack
// of 1e-9 keeps T = 1, dt = 0.001 at 1000 steps despite rounding). Empty when T/dt is not a
// finite number or exceeds kMaxSteps (--time 1e16, or --dt 1e-300): no conversion to an
// integer is attempted then.
std::optional<long long> stepsForTime(double time, double dt);
// The one line (without "jello: ") that refuses such a --time at such a dt.
std::string tooManyStepsMessage(double time, double dt);

// --dump FILE's rule (README, "Reliability"): it creates FILE or replaces a regular, writable
// file of that name, because the option names it; never the world being run, nor anything
// that is not a regular file (output.h). Why `dumpPath` may not be written, or "".
std::string whyNotDumpable(const std::string& dumpPath, const std::string& worldPath);


// Reads the world of `options` and applies its overrides. On bad input prints one line on
// stderr and returns false.
bool loadRun(const RunOptions& options, WorldFile* out);

// Loads the world, runs it (handing its frames to `frames` when given), prints the summary
// line on stdout (errors on stderr, one line each) and returns the exit status.
int runHeadless(const RunOptions& options, FrameObserver* frames = nullptr);

}  // namespace jello
