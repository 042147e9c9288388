// build.h: building a submission in the sandbox, as its student's program is built.
//
// The grader builds the student's program as they wrote it, headless (docs/grading.md, "How a
// submission is built"): their own main() (jello.cpp's, or whichever file calls glutMainLoop),
// their physics.cpp and input.cpp and whatever else the program needs, with their own headers,
// against stand-ins for GL, GLU, GLUT and the course's pic library that draw nothing; the
// stand-in glutMainLoop() hands the program to the grader's probe once the student's own setup
// has run. Each file is compiled apart and only what the program needs is linked (the rest goes
// into an archive). Where that does not build, the same leniently (the Windows headers, the
// standard headers another compiler includes on its own, file names in any case,
// -fpermissive, and two rewrites Visual C++ allows: each named in the report); then physics.cpp
// alone, with its own headers, then with the course API's (grader/course/).
#pragma once

#include <string>
#include <vector>

#include "grader/submission.h"

namespace jello::grader {

struct BuildResult {
  bool built = false;
  // When not built: the first error of the first attempt (the student's own program, with its
  // own headers), "FILE:LINE:COLUMN: error: ..." in the student's file; or what is missing.
  std::string diagnosis;
  std::string how;                 // how it was built, in words ("its whole program, ...")
  std::vector<std::string> notes;  // leniencies, fallbacks and why, files left out, links
  std::string log;                 // every compiler's output
  double seconds = 0;
};

// The CPU seconds the compiler may use for all of a submission's build attempts together (a
// compile-time loop is not repeated by every attempt), and for one attempt at most.
constexpr double kCompileBudgetSeconds = 240;
constexpr double kCompileSeconds = 120;

// Builds the submission in the sandbox and copies the program to `probePath`, and the files
// beside its source (what it may read as it starts: textures, worlds) to
// programFilesOf(probePath), where its runs start (probe.h). `budgetSeconds`: the compiler's CPU
// seconds for all its attempts.
BuildResult buildSubmission(const Submission& submission, const std::string& probePath,
                            double budgetSeconds = kCompileBudgetSeconds);

}  // namespace jello::grader
