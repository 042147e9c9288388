#include "test_support.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <pty.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>
#include <stdexcept>

#include "analysis/stability.h"
#include "model/vec3.h"
#include "solver/integrators.h"
#include "solver/simulation.h"

namespace jello::test {

std::string dataPath(const std::string& name) { return std::string(JELLO_TEST_DATA) + "/" + name; }

std::vector<double> readExpectedPositions(const std::string& name) {
  std::ifstream in(dataPath("expected/" + name));
  if (!in) throw std::runtime_error("cannot open expected/" + name);
  std::vector<double> xyz;  // the file lists the points' x y z in turn
  double value;
  while (in >> value) xyz.push_back(value);
  if (xyz.size() != static_cast<std::size_t>(kNumCoords))
    throw std::runtime_error("bad expected file " + name);
  std::vector<double> p(kNumCoords);
  for (int q = 0; q < kNumPoints; ++q)
    store(p.data(), q, {xyz[3 * q], xyz[3 * q + 1], xyz[3 * q + 2]});
  return p;
}

double rmsDistance(const State& a, const State& b) {
  const int n = a.points();
  double sum = 0;
  for (int q = 0; q < n; ++q) {
    const Vec3 d = load(a.p(), q, n) - load(b.p(), q, n);
    sum += dot(d, d);
  }
  return std::sqrt(sum / n);
}

State expectEveryIntegratorsOrder(const Model& model, const State& start, double time) {
  auto run = [&](Integrator integrator, double dt) {
    Simulation s(model, start, integrator, dt);
    EXPECT_TRUE(s.advanceTo(time).ran());
    return s.state();
  };
  const State reference = run(Integrator::RK4, 1e-6);
  for (const IntegratorInfo& row : integratorTable()) {
    if (row.integrator == Integrator::RK45) continue;
    const double dt = row.order >= 4 ? 1e-3 : 2e-4;
    const double coarse = rmsDistance(run(row.integrator, dt), reference);
    const double fine = rmsDistance(run(row.integrator, dt / 2), reference);
    const double order = std::log2(coarse / fine);
    std::printf("%s: errors %.3g, %.3g: order %.2f\n", row.name(), coarse, fine, order);
    EXPECT_NEAR(order, row.order, 0.35) << row.name();
  }
  return reference;
}

double rmsDistance(const double* a, const double* b) {
  double sum = 0;
  for (int q = 0; q < kNumPoints; ++q) {
    Vec3 d = load(a, q) - load(b, q);
    sum += dot(d, d);
  }
  return std::sqrt(sum / kNumPoints);
}

State restLattice() { return restState(courseBody()); }

World springsOnlyWorld() {
  World w;
  w.kElastic = 500;
  w.dElastic = 0.25;
  w.kCollision = 1000;
  w.dCollision = 0.25;
  w.mass = 1.0 / 512;
  return w;
}

namespace {
// Every folder makeTempDir made in this process, removed as the process ends (a test that
// fails or returns early included); what a killed process leaves, the suite's TMPDIR
// (tests/CMakeLists.txt) keeps until the next run's setup empties it.
struct TempDirs {
  std::mutex lock;
  std::vector<std::string> made;
  ~TempDirs() {
    for (const auto& dir : made) removeTree(dir);
  }
};
TempDirs& tempDirs() {
  static TempDirs dirs;
  return dirs;
}
}  // namespace

std::string makeTempDir() {
  const char* base = std::getenv("TMPDIR");
  std::string pattern = std::string(base && *base ? base : "/tmp") + "/jello-test-XXXXXX";
  if (!::mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
  std::lock_guard<std::mutex> hold(tempDirs().lock);
  tempDirs().made.push_back(pattern);
  return pattern;
}

void writeText(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + path);
}

std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void removeTree(const std::string& dir) {
  if (dir.rfind("/tmp/", 0) == 0 || dir.find("/jello-test-") != std::string::npos) {
    std::error_code ignored;  // a test's leftovers; nothing to report
    std::filesystem::remove_all(dir, ignored);
  }
}

CommandResult runJello(const std::string& args, const std::string& cwd, const std::string& env) {
  return runShell((cwd.empty() ? "" : "cd '" + cwd + "' && ") + env + " " + jelloCommand() + " " +
                  args + " </dev/null");
}

std::string jelloCommand() { return std::string("'") + JELLO_BINARY + "'"; }

CommandResult runShell(const std::string& script) {
  std::string dir = makeTempDir();
  std::string command = "( " + script + " ) >" + dir + "/out 2>" + dir + "/err";
  int raw = std::system(command.c_str());
  CommandResult result;
  if (raw != -1 && WIFEXITED(raw)) result.status = WEXITSTATUS(raw);
  result.out = readText(dir + "/out");
  result.err = readText(dir + "/err");
  removeTree(dir);
  return result;
}

bool haveGnuplot() { return runShell("command -v gnuplot").status == 0; }

CommandResult runProgram(const std::vector<std::string>& argv, const ProgramSetup& setup) {
  std::string dir = makeTempDir();
  const std::string out = dir + "/out", err = dir + "/err";
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t child = ::fork();
  if (child == 0) {
    // Only async-signal-safe calls between fork and exec (and the caller's `before`).
    int in = ::open("/dev/null", O_RDONLY),
        o = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600),
        e = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    if (in < 0 || o < 0 || e < 0 || ::dup2(in, 0) < 0 || ::dup2(o, 1) < 0 || ::dup2(e, 2) < 0)
      ::_exit(126);
    if (!setup.cwd.empty() && ::chdir(setup.cwd.c_str()) != 0) ::_exit(126);
    if (setup.addressSpace > 0) {
      rlimit limit{setup.addressSpace, setup.addressSpace};
      if (::setrlimit(RLIMIT_AS, &limit) != 0) ::_exit(126);
    }
    if (setup.before) setup.before();
    ::alarm(
        setup.hangGuardSeconds);  // survives exec: a hang ends as a failed test, not a stuck suite
    ::execv(args[0], args.data());
    ::_exit(127);
  }
  CommandResult result;
  int raw = 0;
  if (child > 0 && ::waitpid(child, &raw, 0) == child && WIFEXITED(raw))
    result.status = WEXITSTATUS(raw);
  result.out = readText(out);
  result.err = readText(err);
  removeTree(dir);
  return result;
}

CommandResult runJelloArgs(const std::vector<std::string>& args, const ProgramSetup& setup) {
  std::vector<std::string> argv = {JELLO_BINARY};
  argv.insert(argv.end(), args.begin(), args.end());
  return runProgram(argv, setup);
}

std::string runJelloOnTerminal(const std::vector<std::string>& args, int columns, int* status) {
  *status = -1;
  std::vector<std::string> argv = {JELLO_BINARY};
  argv.insert(argv.end(), args.begin(), args.end());
  std::vector<char*> pointers;
  for (const std::string& a : argv) pointers.push_back(const_cast<char*>(a.c_str()));
  pointers.push_back(nullptr);
  int terminal = -1, side = -1;
  winsize size{};
  size.ws_row = 24;
  size.ws_col = static_cast<unsigned short>(columns);
  if (::openpty(&terminal, &side, nullptr, nullptr, &size) != 0) return "";
  pid_t child = ::fork();
  if (child == 0) {
    int in = ::open("/dev/null", O_RDONLY);
    if (in < 0 || ::dup2(in, 0) < 0 || ::dup2(side, 1) < 0 || ::dup2(side, 2) < 0) ::_exit(126);
    ::close(terminal);
    ::alarm(120);  // a hang ends as a failed test
    ::execv(pointers[0], pointers.data());
    ::_exit(127);
  }
  ::close(side);
  // Read until the child has gone and the terminal is drained (EIO once no one holds its side).
  std::string received;
  char buffer[4096];
  for (ssize_t n; (n = ::read(terminal, buffer, sizeof buffer)) > 0;) received.append(buffer, n);
  ::close(terminal);
  int raw = 0;
  if (child > 0 && ::waitpid(child, &raw, 0) == child && WIFEXITED(raw)) *status = WEXITSTATUS(raw);
  return received;
}

namespace {

// A small valid world (R = 2), its lines numbered as in the table of docs/world-format.md:
// 1 integrator, 2 dt n, 3 stiffness, 4 mass, 5 plane flag, 6 plane, 7 resolution,
// 8-15 field, 16-527 positions, 528-1039 velocities.
std::vector<std::string> baseLines() {
  World w = springsOnlyWorld();
  w.hasPlane = true;
  w.plane = {1, -1, -1, 4};
  w.field.resolution = 2;
  w.field.forces.assign(3 * 8, 0.5);
  std::string text = formatWorld(w, RunSettings{Integrator::RK4, 1e-4, 1}, restLattice());
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::string join(const std::vector<std::string>& lines, std::size_t count) {
  std::string text;
  for (std::size_t i = 0; i < count && i < lines.size(); ++i) text += lines[i] + "\n";
  return text;
}

}  // namespace

std::vector<MalformedCase> malformedCases() {
  const std::vector<std::string> base = baseLines();
  auto with = [&](int line, const std::string& replacement) {
    std::vector<std::string> lines = base;
    lines[line - 1] = replacement;
    return join(lines, lines.size());
  };
  return {
      {"empty", "", 1, "integrator"},
      {"blank", "\n  \r\n", 1, "integrator"},
      {"truncated_positions", join(base, 300), 301, "position p[4][3][5]"},
      {"missing_velocities", join(base, 527), 528, "velocity v[0][0][0]"},
      {"word_for_number", with(3, "500 soft 1000 0.25"), 3, "dElastic"},
      {"nan", with(4, "nan"), 4, "mass"},
      {"inf", with(16, "inf 0 0"), 16, "position p[0][0][0]"},
      {"negative_infinity", with(8, "0 -infinity 0"), 8, "force field node (0,0,0)"},
      {"out_of_range", with(3, "1e999 0.25 1000 0.25"), 3, "kElastic"},
      {"zero_dt", with(2, "0 1"), 2, "dt"},
      {"negative_dt", with(2, "-0.001 1"), 2, "dt"},
      {"zero_mass", with(4, "0"), 4, "mass"},
      {"negative_mass", with(4, "-0.001953"), 4, "mass"},
      {"zero_n", with(2, "0.001 0"), 2, "n"},
      {"fractional_n", with(2, "0.001 1.5"), 2, "n"},
      {"negative_stiffness", with(3, "-500 0.25 1000 0.25"), 3, "kElastic"},
      {"negative_collision_damping", with(3, "500 0.25 1000 -1"), 3, "dCollision"},
      {"plane_flag_2", with(5, "2"), 5, "incPlanePresent"},
      {"plane_flag_word", with(5, "yes"), 5, "incPlanePresent"},
      {"zero_plane_normal", with(6, "0 0 0 4"), 6, "plane a b c"},
      {"plane_beyond_the_range_of_doubles", with(6, "1e-300 0 0 1e10"), 6, "plane d"},
      {"short_plane", with(6, "1 -1 -1"), 6, "plane a b c d"},
      {"negative_resolution", with(7, "-1"), 7, "resolution"},
      {"huge_resolution", with(7, "100000"), 7, "resolution"},
      {"resolution_beyond_file", with(7, "200"), 7, "resolution"},
      {"unknown_integrator", with(1, "RK5"), 1, "integrator"},
      {"overlong_integrator", with(1, std::string(4000, 'X')), 1, "integrator"},
      {"two_integrators", with(1, "RK4 EULER"), 1, "integrator"},
      {"extra_number", with(16, "0 0 0 0"), 16, "position p[0][0][0]"},
      {"missing_number", with(600, "0 0"), 600, "velocity v[1][1][0]"},
      {"trailing_garbage", join(base, base.size()) + "1 2 3\n", 1040, "trailing garbage"},
      {"trailing_word", join(base, base.size()) + "\nend\n", 1041, "trailing garbage"},
  };
}

}  // namespace jello::test
