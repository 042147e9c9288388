// compilerlog.h: what the grader reads in the compiler's output of a submission's build
// (build.cpp): the first error that counts, a token no attempt can mend, the stand-ins used.
#pragma once

#include <string>
#include <vector>

namespace jello::grader {

// The grader's own file of a build, which calls the course API.
extern const char* const kProbeName;
// How a build error in the grader's own probe begins: the student changed the course API.
extern const std::string kApiChanged;
// What the build notes when a token missing in physics.cpp ends it (unmendable).
extern const std::string kUnmendable;

// The first line of the compiler's output that says what is wrong, without sandbox paths: of a
// file the program needs (physics.cpp, its main, the probe) or of the link, before one of a file
// the linker would have taken only if needed (a "lib": its error matters only when the link
// then fails, which says so itself). An error of the probe's begins with kApiChanged.
std::string firstError(const std::string& log);

// A token missing in physics.cpp itself (a ';', a brace) as `firstError`: no other attempt
// changes physics.cpp, and no header puts a token back.
bool unmendable(const std::string& firstError);

// The lenient stand-ins a build used: each says so as it is included (#pragma message).
std::vector<std::string> standInsUsed(const std::string& log);

}  // namespace jello::grader
