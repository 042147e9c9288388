// probe.h: talking to a built submission (grader/course/probe.cpp) through the sandbox.
//
// A Script is the requests of one probe run; each answering request gives one Answer, in order.
// The run's answers are checked for count and form here, so that the checks see numbers or the
// reason there are none (a crash, a hang, garbage), never half an answer.
#pragma once

#include <string>
#include <vector>

#include "grader/sandbox.h"
#include "model/world.h"

namespace jello::grader {

class Script {
 public:
  // W: the world (its parameters, field and state) as the course's input code reads it. The
  // first world of a script is also the world file the student's own main() reads (argv[1]).
  void world(const World& world, const RunSettings& run, const State& state);
  // S: the state.
  void state(const State& state);
  // A: answers the accelerations (m/s^2) at the state, per-point arrays (coordIndex).
  void accelerations();
  // E n or R n: n steps of Euler (integrator Euler) or RK4 (any other); answers "ok".
  void steps(Integrator integrator, long n);
  // P: answers the state.
  void read();
  // T n: n RK4 steps; answers the microseconds a step took.
  void timing(long n);

  // The requests, each ending in an answering command: one is sent after the last is answered.
  const std::vector<std::string>& requests() const { return requests_; }
  const std::string& firstWorld() const { return firstWorld_; }
  // What each answer is, in order: 'A', 'E', 'P' or 'T'.
  const std::vector<char>& answering() const { return answering_; }
  const std::vector<std::string>& doing() const { return doing_; }

 private:
  void answer(char kind, std::string command, std::string doing);
  std::string pending_;  // W and S requests waiting for the next answering command
  std::string firstWorld_;
  std::vector<std::string> requests_;
  std::vector<char> answering_;
  std::vector<std::string> doing_;  // per answer: "computeAcceleration", ...
};

struct ProbeRun {
  std::vector<std::vector<double>> answers;  // per answering command, complete ones only
  SandboxResult sandbox;
  // "" when every command answered; otherwise what went wrong and in which function, e.g.
  // "RK4 did not finish in time" or "computeAcceleration was killed by signal 11 (...)".
  std::string failure;
  bool complete() const { return failure.empty(); }
  // An answer as a state (P) or as per-point values (A: the velocities half is unused).
  State state(std::size_t answer) const;
};

// A probe run's time: `scale` times the budget of this thread, which is kProbeSeconds until a
// run on the thread does not finish in time, and kProbeSecondsAfterHang after that (for the
// further runs of the same check); ./grade then fails the submission's later checks as "not
// run" (probeHung), so that one that never returns costs seconds, not minutes. Under CTest
// each check is a process of its own and waits its own kProbeSeconds. resetProbeBudget() when
// a thread starts on the next submission.
constexpr double kProbeSeconds = 5;  // CPU seconds
constexpr double kWallBackstop = 4;  // wall-clock seconds a run may take, per CPU second
constexpr double kProbeSecondsAfterHang = 2;
void resetProbeBudget();
// Whether a probe run on this thread did not finish in time since resetProbeBudget().
bool probeHung();
struct ProbeLimits {
  double scale = 1;
};

// The folder of the files beside a built program's source (buildSubmission): a run finds a
// copy of them in its working directory (/tmp).
std::string programFilesOf(const std::string& probePath);

ProbeRun runProbe(const std::string& probePath, const Script& script, ProbeLimits limits = {});

// An answer the checks can compare: every number finite and at most kLargestAnswer in size (so
// that no difference or square of answers overflows into an infinity or a NaN, which every
// comparison would let pass). False for NaN, infinity, and the like of +-DBL_MAX.
constexpr double kLargestAnswer = 1e100;
bool allUsable(const std::vector<double>& values);

}  // namespace jello::grader
