// Inputs that are not world files, or not files at all, and the same run twice.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "integrators.h"
#include "physics.h"
#include "test_support.h"

namespace jello {
namespace {

// A run that must finish: a hang shows as status 124 (timeout's), never as a stuck suite.
constexpr const char* kHangGuard = "timeout 30";

test::CommandResult runOn(const std::string& path, const std::string& extra = "") {
  return test::runJello("--headless --steps 2 " + extra + " '" + path + "'", "", kHangGuard);
}

void expectRefused(const test::CommandResult& r, const std::string& says) {
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(says), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");
}

TEST(SpecialFiles, ADirectoryIsRefused) {
  std::string dir = test::makeTempDir();
  expectRefused(runOn(dir), "is a directory, not a world file");
  test::removeTree(dir);
}

TEST(SpecialFiles, DevZeroIsRefusedAtItsFirstByte) {
  expectRefused(runOn("/dev/zero"), "/dev/zero:1: byte 0x00 in column 1: not a text file");
}

TEST(SpecialFiles, AFifoIsReadAndAFifoWithoutWriterDoesNotHang) {
  std::string dir = test::makeTempDir();
  std::string fifo = dir + "/a fifo.w";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0) << std::strerror(errno);
  expectRefused(runOn(fifo), "a FIFO nothing was written to within 5 s");
  // With a writer it is read like a file, whether the writer comes first or second.
  test::CommandResult r = test::runShell(std::string(kHangGuard) + " " + test::jelloCommand() + " --headless --steps 2 '" +
                                         fifo + "' & reader=$!; sleep 0.2; cat '" + test::dataPath("jello.w") + "' > '" +
                                         fifo + "'; wait $reader");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("steps=2 "), std::string::npos) << r.out;
  r = test::runShell("cat '" + test::dataPath("jello.w") + "' > '" + fifo + "' & sleep 0.2; " + kHangGuard + " " +
                     test::jelloCommand() + " --headless --steps 2 '" + fifo + "'");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("steps=2 "), std::string::npos) << r.out;
  test::removeTree(dir);
}

TEST(SpecialFiles, AnUnreadableFileIsRefusedUnlessWeAreRoot) {
  std::string dir = test::makeTempDir();
  std::string path = dir + "/secret.w";
  test::writeText(path, test::readText(test::dataPath("jello.w")));
  ASSERT_EQ(::chmod(path.c_str(), 0), 0);
  test::CommandResult r = runOn(path);
  if (::geteuid() == 0) {
    EXPECT_EQ(r.status, 0) << "root reads any file: " << r.err;
  } else {
    expectRefused(r, "cannot open: Permission denied");
  }
  test::removeTree(dir);
}

// A sparse 2 GB file costs no disk; the reader must stop at its first line, not read it all.
TEST(SpecialFiles, ATwoGigabyteFileIsRefusedAtOnce) {
  std::string dir = test::makeTempDir();
  std::string zeros = dir + "/zeros.w";
  std::string tail = dir + "/world and zeros.w";
  constexpr off_t kTwoGigabytes = 2LL << 30;
  test::writeText(zeros, "");
  ASSERT_EQ(::truncate(zeros.c_str(), kTwoGigabytes), 0) << std::strerror(errno);
  test::writeText(tail, test::readText(test::dataPath("jello.w")));
  ASSERT_EQ(::truncate(tail.c_str(), kTwoGigabytes), 0) << std::strerror(errno);
  expectRefused(runOn(zeros), ":1: byte 0x00 in column 1");
  // A whole world, then zeros: refused at the first line after the velocities.
  expectRefused(runOn(tail), ":28032: byte 0x00 in column 1: not a text file, not a world file (trailing garbage)");
  test::removeTree(dir);
}

TEST(SpecialFiles, AnEndlessLineIsRefused) {
  std::string dir = test::makeTempDir();
  std::string path = dir + "/long.w";
  test::writeText(path, "RK4\n" + std::string(100000, '1') + "\n");
  expectRefused(runOn(path), ":2: line is longer than 4096 characters: not a world file (dt n)");
  test::removeTree(dir);
}

TEST(SpecialFiles, PathsWithSpacesAndPipesWork) {
  std::string dir = test::makeTempDir();
  std::string path = dir + "/my jello world.w";
  test::writeText(path, test::readText(test::dataPath("jello.w")));
  test::CommandResult r = runOn(path, "--dump '" + dir + "/after two steps.w'");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NO_THROW(readWorldFile(dir + "/after two steps.w"));
  r = test::runShell("cat '" + path + "' | " + kHangGuard + " " + test::jelloCommand() + " --headless --steps 2 /dev/stdin");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("/dev/stdin: RK4"), std::string::npos) << r.out;
  test::removeTree(dir);
}

TEST(Tolerances, RK45WithToleranceBeyondDoublesStopsAtOnceNamingThem) {
  // Before: the error control switched off, the run diverged at step 2 and its diagnosis took
  // minutes; now the first step is given up after 22 rejections.
  test::CommandResult r = runOn(test::dataPath("rotate.w"), "--integrator RK45 --rtol 1e-300 --atol 1e-300 --dt 0.01");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("RK45 cannot meet --rtol 1e-300 --atol 1e-300: at step 1 (t=0.01 s)"), std::string::npos)
      << r.err;
}

// The same world, integrator and options give the same bits, run to run: in one process (two
// steppers) and in two processes (the dumps of two runs).
TEST(Determinism, SameInputsGiveBitIdenticalResults) {
  WorldFile f = readWorldFile(test::dataPath("rotate.w"));
  for (Integrator integrator : {Integrator::Euler, Integrator::Midpoint, Integrator::RK4, Integrator::Symplectic,
                                Integrator::Verlet, Integrator::RK45, Integrator::Implicit}) {
    const int steps = integrator == Integrator::Implicit ? 5 : 200;
    const double dt = 2e-4;
    State a = f.state, b = f.state;
    Model model = makeModel(f.world, f.state);
    Stepper first(integrator), second(integrator);
    for (int s = 0; s < steps; ++s) first.step(model, a, dt);
    for (int s = 0; s < steps; ++s) second.step(model, b, dt);
    EXPECT_EQ(std::memcmp(a.y.data(), b.y.data(), a.y.size() * sizeof(double)), 0) << integratorName(integrator);
  }
  std::string dir = test::makeTempDir();
  for (const char* integrator : {"RK4", "RK45", "IMPLICIT"}) {
    for (const char* run : {"1", "2"}) {
      test::CommandResult r = test::runJello(std::string("--headless --steps 5 --dt 2e-4 --integrator ") + integrator +
                                             " --dump '" + dir + "/" + integrator + run + ".w' '" +
                                             test::dataPath("rotate.w") + "'");
      EXPECT_EQ(r.status, 0) << r.err;
    }
    EXPECT_EQ(test::readText(dir + "/" + integrator + "1.w"), test::readText(dir + "/" + integrator + "2.w")) << integrator;
  }
  test::removeTree(dir);
}

}  // namespace
}  // namespace jello
