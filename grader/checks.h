// checks.h: the grader's checks of a built submission, each isolating one part of the physics
// (docs/grading.md says what each means). A check runs the submission's probe in the sandbox,
// compares with the model of docs/physics.md (this project's code), and says in words what is
// wrong.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace jello::grader {

// Pass: right. Near: right but for rounding of a constant (a rest length written with six
// digits), a drift a user can see only after thousands of steps. Fail: wrong, or it crashed.
// Info: a figure, not graded.
enum class Grade { Pass, Near, Fail, Info };
const char* gradeName(Grade grade);  // "pass", "near", "FAIL", "info"

struct CheckResult {
  std::string check;
  Grade grade = Grade::Fail;
  std::string diagnosis;           // one line: what is wrong, or the figure (Info)
  std::vector<std::string> notes;  // what is not graded but worth knowing
  double figure = -1;              // speed: microseconds per RK4 step; -1 when none
};

struct GradingSetup {
  std::string worldDir;    // the course worlds (rotate.w, ...)
  std::uint64_t seed = 1;  // the unseen worlds of "agreement"
  // Whether what the course never asks of its worlds (docs/grading.md, "The course's domain": a
  // field of resolution 1, points exactly on a wall, a collapsed cube, a hard throw) is graded:
  // by default each is a note a student can read, never a FAIL.
  bool strict = false;
};

// A finding outside the course's domain: `line` ("NaN on a cube collapsed to one point") with
// what the course asks, as a FAIL under --strict, else as information.
CheckResult outsideDomain(const std::string& check, const std::string& line,
                          const GradingSetup& setup);
// The same finding beside a check's graded verdict: it fails the check under --strict (when the
// check passed so far), else it is a note.
void addOutsideDomain(CheckResult& result, const std::string& line, const GradingSetup& setup);

// A check, as the table carries it: its name, its line, and what runs it (null for "builds",
// which the grader's build answers).
struct CheckInfo {
  const char* name;  // in test names: SUBMISSION/NAME
  const char* what;  // one line for reports
  CheckResult (*run)(const std::string& probePath, const GradingSetup& setup);
};
// Every check, in the order they run; "builds" first.
const std::vector<CheckInfo>& checkTable();
bool isCheck(const std::string& name);

// Starts computing the references of the check "agreement" (this project's runs of its worlds,
// the same for every submission) in threads of their own, so that they are ready when the first
// submission has been built; the check waits for those not yet done.
void startAgreementReferences(const GradingSetup& setup);
// Ends those still being computed (at their next checkpoint) and waits for their threads: once
// the grading is over, before the program ends.
void stopAgreementReferences();

// Runs check `name` (not "builds") on the probe at `probePath`.
CheckResult runCheck(const std::string& name, const std::string& probePath,
                     const GradingSetup& setup);

}  // namespace jello::grader
