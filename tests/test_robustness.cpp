// Inputs that are not world files, or not files at all, and the same run twice.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <functional>

#include "core/memory.h"
#include "solver/integrators.h"
#include "solver/physics.h"
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
  test::CommandResult r =
      test::runShell(std::string(kHangGuard) + " " + test::jelloCommand() +
                     " --headless --steps 2 '" + fifo + "' & reader=$!; sleep 0.2; cat '" +
                     test::dataPath("jello.w") + "' > '" + fifo + "'; wait $reader");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("steps=2 "), std::string::npos) << r.out;
  r = test::runShell("cat '" + test::dataPath("jello.w") + "' > '" + fifo + "' & sleep 0.2; " +
                     kHangGuard + " " + test::jelloCommand() + " --headless --steps 2 '" + fifo +
                     "'");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("steps=2 "), std::string::npos) << r.out;
  test::removeTree(dir);
}

// Runs jello on `fifo` while `writer` (a command whose output goes into the FIFO) writes, then
// stops the writer. Sets *seconds to the reader's time.
test::CommandResult readWhileWriting(const std::string& fifo, const std::string& writer,
                                     double* seconds) {
  auto start = std::chrono::steady_clock::now();
  test::CommandResult r = test::runShell(
      writer + " > '" + fifo + "' & writer=$!; " + kHangGuard + " " + test::jelloCommand() +
      " --headless --steps 2 '" + fifo + "'; status=$?; kill $writer 2>/dev/null; exit $status");
  *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

TEST(SpecialFiles, AFifoWriterThatStallsIsRefusedAfterFiveSecondsAndASlowOneIsRead) {
  std::string dir = test::makeTempDir();
  std::string fifo = dir + "/a fifo.w";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0) << std::strerror(errno);
  const std::string world = "'" + test::dataPath("jello.w") + "'";
  double seconds = 0;
  // Opens and sends nothing: refused after the wait, as before.
  test::CommandResult r = readWhileWriting(fifo, "exec sleep 60", &seconds);
  expectRefused(r, "a FIFO nothing was written to within 5 s");
  EXPECT_GE(seconds, 4.9);
  EXPECT_LT(seconds, 15);
  // Sends 100000 bytes (3706 lines and part of the next), then nothing, and never closes.
  r = readWhileWriting(fifo, "sh -c 'head -c 100000 \"$0\"; exec sleep 60' " + world, &seconds);
  expectRefused(
      r,
      "a fifo.w:3707: nothing arrived for 5 s: the writer stopped sending before the world's end "
      "(force field node (4,3,9))");
  EXPECT_GE(seconds, 4.9);
  EXPECT_LT(seconds, 15) << "the reader waited for the writer's end";
  // Sends the world in four parts 1.5 s apart: 6 s in all, longer than the wait, and is read.
  r = readWhileWriting(
      fifo,
      "sh -c 'for part in 0 1 2 3; do dd if=\"$0\" bs=200000 skip=$part count=1 status=none; "
      "sleep 1.5; done' " +
          world,
      &seconds);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("steps=2 "), std::string::npos) << r.out;
  EXPECT_GE(seconds, 4.5);
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
  expectRefused(
      runOn(tail),
      ":28032: byte 0x00 in column 1: not a text file, not a world file (trailing garbage)");
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
  r = test::runShell("cat '" + path + "' | " + kHangGuard + " " + test::jelloCommand() +
                     " --headless --steps 2 /dev/stdin");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("/dev/stdin: RK4"), std::string::npos) << r.out;
  test::removeTree(dir);
}

// AddressSanitizer reserves terabytes of address space: no RLIMIT_AS (test::kAddressSanitizer).
using test::kAddressSanitizer;

constexpr std::uint64_t kTwoGigabytes = 2'000'000'000;

// A valid start of a world with an R = 512 field, its 134M field lines a sparse gigabyte of
// zeros: enough bytes for the reader's size check, no disk, and refused at line 7 if read.
std::string writeHugeWorld(const std::string& dir) {
  std::string path = dir + "/huge.w";
  test::writeText(path, "RK4\n0.001 1\n500 0.25 1000 0.25\n0.001953125\n0\n512\n");
  EXPECT_EQ(::truncate(path.c_str(), 1LL << 30), 0) << std::strerror(errno);
  return path;
}

double secondsOf(const std::function<void()>& run) {
  auto start = std::chrono::steady_clock::now();
  run();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void expectNotEnoughMemory(const test::CommandResult& r, const std::string& starts,
                           double seconds) {
  EXPECT_EQ(r.status, 2) << "not a clean refusal (-1: killed by a signal): " << r.err;
  EXPECT_EQ(r.err.rfind(starts, 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_LT(seconds, 2) << "refused only after work";
}

TEST(MemoryLimits, AWorldTooLargeForTheAddressSpaceLimitIsRefusedBeforeAllocating) {
  if (kAddressSanitizer) GTEST_SKIP() << "AddressSanitizer cannot run under RLIMIT_AS";
  std::string dir = test::makeTempDir();
  const std::string world = writeHugeWorld(dir);
  test::CommandResult r;
  // A run holds 80 bytes a node (134M nodes), and 128 MiB besides: 10.9 GB.
  double seconds = secondsOf([&] {
    r = test::runProgram({JELLO_BINARY, "--headless", "--steps", "2", world}, {"", kTwoGigabytes});
  });
  expectNotEnoughMemory(
      r, "jello: " + world + ":6: not enough memory for this world: needs 10.9 GB, 1.", seconds);
  EXPECT_NE(r.err.find(" GB available (resolution)\n"), std::string::npos) << r.err;
  // createWorld holds the field once: 24 bytes a node, 3.36 GB; refused before building it.
  const std::string out = dir + "/out.w";
  seconds = secondsOf([&] {
    r = test::runProgram(
        {JELLO_CREATE_WORLD, "--field-resolution", "512", "--field-swirl", "1", "-o", out},
        {"", kTwoGigabytes});
  });
  expectNotEnoughMemory(r, "createWorld: not enough memory for this world: needs 3.36 GB, 1.",
                        seconds);
  // Taken --from a world, the field is refused by the reader, before it is read.
  seconds = secondsOf([&] {
    r = test::runProgram({JELLO_CREATE_WORLD, "--from", world, "-o", out}, {"", kTwoGigabytes});
  });
  expectNotEnoughMemory(
      r, "createWorld: " + world + ":6: not enough memory for this world: needs 3.36 GB, 1.",
      seconds);
  EXPECT_NE(::access(out.c_str(), F_OK), 0) << "a world was written";
  test::removeTree(dir);
}

TEST(MemoryLimits, MaxMemoryStandsInForTheMachinesMemory) {
  std::string dir = test::makeTempDir();
  const std::string out = dir + "/out.w";
  test::CommandResult r;
  double seconds = secondsOf([&] {
    r = test::runProgram(
        {JELLO_CREATE_WORLD, "--max-memory", "1.5", "--field-resolution", "512", "-o", out});
  });
  expectNotEnoughMemory(
      r, "createWorld: not enough memory for this world: needs 3.36 GB, 1.5 GB available\n",
      seconds);
  r = test::runProgram(
      {JELLO_CREATE_WORLD, "--max-memory", "0.5", "--field-resolution", "128", "-o", out});
  EXPECT_EQ(r.status, 0) << r.err;  // 178 MB
  EXPECT_EQ(readWorldFile(out).world.field.resolution, 128);
  // The library's limit, as jello's command line sets it: the reader refuses at the resolution.
  setMemoryLimit(150'000'000);
  try {
    readWorldFile(out);
    ADD_FAILURE() << "read under a limit it exceeds";
  } catch (const InputError& e) {
    EXPECT_EQ(
        std::string(e.what()),
        out +
            ":6: not enough memory for this world: needs 0.302 GB, 0.15 GB available (resolution)");
  }
  setMemoryLimit(0);
  EXPECT_NO_THROW(readWorldFile(out));
  test::removeTree(dir);
}

// --dump writes its text in blocks: a run that fits its limit can also dump (the text of an
// R = 160 field, 25 MB here and 262 MB set aside for it before, no longer comes on top).
TEST(MemoryLimits, ARunThatFitsItsLimitCanDumpItsWorld) {
  if (kAddressSanitizer) GTEST_SKIP() << "AddressSanitizer cannot run under RLIMIT_AS";
  std::string dir = test::makeTempDir();
  const std::string world = dir + "/steps.w", dump = dir + "/dump.w";
  test::CommandResult r = test::runProgram({JELLO_CREATE_WORLD, "--field-resolution", "160",
                                            "--field-expr", "x > 0; 0; 0", "-o", world});
  ASSERT_EQ(r.status, 0) << r.err;
  // The run needs 0.462 GB (80 bytes a node, 4.1M nodes, and 128 MiB); it uses 0.34 GB.
  r = test::runProgram({JELLO_BINARY, "--headless", "--steps", "1", "--dump", dump, world},
                       {"", 500'000'000});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(test::readText(dump).substr(0, 30), test::readText(world).substr(0, 30));
  test::removeTree(dir);
}

TEST(Tolerances, RK45WithToleranceBeyondDoublesStopsAtOnceNamingThem) {
  // Before: the error control switched off, the run diverged at step 2 and its diagnosis took
  // minutes; now the first step is given up after 22 rejections.
  test::CommandResult r =
      runOn(test::dataPath("rotate.w"), "--integrator RK45 --rtol 1e-300 --atol 1e-300 --dt 0.01");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("RK45 cannot meet --rtol 1e-300 --atol 1e-300: at step 1 (t=0.01 s)"),
            std::string::npos)
      << r.err;
}

// The same world, integrator and options give the same bits, run to run: in one process (two
// steppers) and in two processes (the dumps of two runs).
TEST(Determinism, SameInputsGiveBitIdenticalResults) {
  WorldFile f = readWorldFile(test::dataPath("rotate.w"));
  for (Integrator integrator :
       {Integrator::Euler, Integrator::Midpoint, Integrator::RK4, Integrator::Symplectic,
        Integrator::Verlet, Integrator::RK45, Integrator::Implicit}) {
    const int steps = integrator == Integrator::Implicit ? 5 : 200;
    const double dt = 2e-4;
    State a = f.state, b = f.state;
    Model model = makeModel(f.world, f.state);
    Stepper first(integrator), second(integrator);
    for (int s = 0; s < steps; ++s) first.step(model, a, dt);
    for (int s = 0; s < steps; ++s) second.step(model, b, dt);
    EXPECT_EQ(std::memcmp(a.y.data(), b.y.data(), a.y.size() * sizeof(double)), 0)
        << integratorName(integrator);
  }
  std::string dir = test::makeTempDir();
  for (const char* integrator : {"RK4", "RK45", "IMPLICIT"}) {
    for (const char* run : {"1", "2"}) {
      test::CommandResult r = test::runJello(
          std::string("--headless --steps 5 --dt 2e-4 --integrator ") + integrator + " --dump '" +
          dir + "/" + integrator + run + ".w' '" + test::dataPath("rotate.w") + "'");
      EXPECT_EQ(r.status, 0) << r.err;
    }
    EXPECT_EQ(test::readText(dir + "/" + integrator + "1.w"),
              test::readText(dir + "/" + integrator + "2.w"))
        << integrator;
  }
  test::removeTree(dir);
}

}  // namespace
}  // namespace jello
