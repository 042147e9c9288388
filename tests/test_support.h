// test_support.h: shared helpers of the test suite.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "io/input.h"
#include "model/world.h"
#include "solver/physics.h"

namespace jello::test {

// Whether the tests are built with AddressSanitizer (make test-sanitize).
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

// A file of tests/data (copied from ../shared/reference-worlds).
std::string dataPath(const std::string& name);

// The 512 positions of an `expected/` file (which lists x y z per point), as a per-point array.
std::vector<double> readExpectedPositions(const std::string& name);

// RMS over the 512 points of the distance between two position arrays (m).
double rmsDistance(const double* a, const double* b);

// RMS over the points of two states (of any body) of the distance between their positions (m).
double rmsDistance(const State& a, const State& b);

// The mean position of the course cube's 512 points (m).
inline Vec3 centroid(const State& s) {
  Vec3 sum;
  for (int q = 0; q < kNumPoints; ++q) sum += load(s.p(), q);
  return (1.0 / kNumPoints) * sum;
}

// Fits each integrator's order (RK45 aside: adaptive, its error follows its tolerance) from its
// errors at dt and dt/2 (dt 1e-3 for order 4 and above, 2e-4 below) against RK4 at 1e-6, over
// `time` seconds of `model` from `start`, printing the fits, and expects each within 0.35 of
// the table's order. Returns the reference's end state.
State expectEveryIntegratorsOrder(const Model& model, const State& start, double time);

// The ideal lattice p[i][j][k] = (i,j,k)/7, at rest.
State restLattice();

// A world with damped springs and nothing else: no plane, no field.
World springsOnlyWorld();
// The step the springs-only world is run at in the tests, s.
constexpr double kSpringsOnlyDt = 1e-4;

// A fresh directory under the system's temporary directory.
std::string makeTempDir();
void writeText(const std::string& path, const std::string& text);
std::string readText(const std::string& path);

struct CommandResult {
  int status = -1;  // exit status, or -1 if the process did not exit normally
  std::string out, err;
};
// Runs the jello binary under test with `args` (a shell-quoted string), in the working
// directory `cwd` when one is given, with `env` (e.g. "env -u DISPLAY") before it.
CommandResult runJello(const std::string& args, const std::string& cwd = "",
                       const std::string& env = "");
// The jello binary under test, quoted for a shell.
std::string jelloCommand();
// Runs a shell script (e.g. a pipeline around jelloCommand()), capturing its output.
CommandResult runShell(const std::string& script);
// Whether gnuplot is on the PATH: without it a report or a map has no PNG, and the tests of the
// pictures skip (gnuplot-nox is an optional package).
bool haveGnuplot();
// How runProgram starts a program.
struct ProgramSetup {
  std::string cwd;                  // working directory; "" for the test's own
  std::uint64_t addressSpace = 0;   // RLIMIT_AS, bytes; 0 for none
  void (*before)() = nullptr;       // run in the child just before exec (a setrlimit, say)
  unsigned hangGuardSeconds = 120;  // stopped after this long (status -1)
};
// A program still running after setup.hangGuardSeconds (120 s unless a test says otherwise) is
// stopped (status -1): a hang fails, never sticks.
// Runs argv[0] (a path) with arguments argv[1..] directly (no shell), stdin from /dev/null,
// output captured. status is -1 when it was killed by a signal (e.g. SIGABRT from an uncaught
// std::bad_alloc, or the hang guard).
CommandResult runProgram(const std::vector<std::string>& argv, const ProgramSetup& setup = {});
// runProgram of the jello binary under test with these arguments.
CommandResult runJelloArgs(const std::vector<std::string>& args, const ProgramSetup& setup = {});

// Runs the jello binary under test with these arguments on a pseudo-terminal `columns` wide,
// its stdout and stderr both, as a user at a terminal sees it (progress lines show only there).
// Returns all the terminal received (the terminal's output processing makes "\n" "\r\n") and
// the exit status in `status` (-1 when it did not exit normally).
std::string runJelloOnTerminal(const std::vector<std::string>& args, int columns, int* status);

// Removes a directory tree made by makeTempDir.
void removeTree(const std::string& dir);

// One malformed world file: its text, and the line and field its error must name.
struct MalformedCase {
  std::string name;
  std::string text;
  int line;
  std::string field;
};
std::vector<MalformedCase> malformedCases();
inline void PrintTo(const MalformedCase& c, std::ostream* os) { *os << c.name; }

}  // namespace jello::test
