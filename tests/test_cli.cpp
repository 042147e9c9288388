// The command line of ./jello (README: Running), run as a user runs it.
#include <gtest/gtest.h>
#include <pty.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>

#include "app/cli.h"
#include "app/headless.h"
#include "app/pictures.h"
#include "solver/integrators.h"
#include "solver/physics.h"
#include "test_support.h"

namespace jello {
namespace {

using test::dataPath;
using test::runJello;

int lineCount(const std::string& text) {
  return static_cast<int>(std::count(text.begin(), text.end(), '\n'));
}

bool exists(const std::string& path) {
  struct stat info;
  return ::stat(path.c_str(), &info) == 0;
}

TEST(Cli, HeadlessRunPrintsTheSceneAndOneSummaryLine) {
  test::CommandResult r = runJello("--headless --steps 20 '" + dataPath("rotate.w") + "'");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(lineCount(r.out), 2) << r.out;
  EXPECT_EQ(r.out.rfind("scene: kept: ", 0), 0u) << r.out;
  for (const char* part :
       {"rotate.w", "RK4", "dt=0.001 ", "steps=20 ", "simulated=0.02 s", "wall=", "us/step"}) {
    EXPECT_NE(r.out.find(part), std::string::npos) << part << " missing from: " << r.out;
  }
  EXPECT_EQ(r.err, "") << "quiet when stderr is not a terminal";
}

TEST(Cli, BenchTimesEveryIntegratorWithBothKernels) {
  test::CommandResult r = runJello("--bench --steps 2 '" + dataPath("rotate.w") + "'");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.rfind("scene: kept: ", 0), 0u) << r.out;
  for (const char* part :
       {"512 points", "one thread", "general", "2 threads", "speed-up", "force evaluation",
        "per point", "EULER", "MIDPOINT", "RK4", "SYMPLECTIC", "VERLET", "RK45", "IMPLICIT",
        "world parsing", "a run of this body uses 1 thread"}) {
    EXPECT_NE(r.out.find(part), std::string::npos) << part << " missing from: " << r.out;
  }
}

// --integrator NAME times that integrator alone (a large body's IMPLICIT steps take seconds).
TEST(Cli, BenchTimesTheIntegratorItIsGivenAlone) {
  test::CommandResult r =
      runJello("--bench --steps 2 --integrator RK4 '" + dataPath("rotate.w") + "'");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("\nRK4 "), std::string::npos) << r.out;
  for (const char* other : {"EULER", "MIDPOINT", "IMPLICIT", "RK45"})
    EXPECT_EQ(r.out.find(other), std::string::npos) << other << " in: " << r.out;
}

// --threads N: a whole number from 1 to 256, refused otherwise in one line; a run on several
// threads ends in the state of a run on one, byte for byte (a 26^3 lattice: two threads or more).
TEST(Cli, ThreadsAreAWholeNumberAndChangeNoResult) {
  for (const char* bad : {"0", "257", "2.5", "two", "-1"}) {
    test::CommandResult r = runJello(std::string("--headless --steps 1 --threads ") + bad + " '" +
                                     dataPath("rotate.w") + "'");
    EXPECT_EQ(r.status, 2) << bad;
    EXPECT_NE(r.err.find("--threads"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  const std::string dir = test::makeTempDir();
  test::writeText(dir + "/big.toml",
                  "dt = 0.0001\ngravity = [0, 0, -9.81]\n[jelly]\nshape = \"lattice\"\n"
                  "size = [26, 26, 26]\nspacing = 0.04\nstiffness = 2000\ndamping = 0.5\n");
  for (const char* threads : {"1", "2", "5"}) {
    test::CommandResult r =
        runJello(std::string("--headless --steps 20 --threads ") + threads + " --save-state '" +
                 dir + "/state" + threads + ".csv' '" + dir + "/big.toml'");
    ASSERT_EQ(r.status, 0) << r.err;
  }
  const std::string one = test::readText(dir + "/state1.csv");
  EXPECT_GT(one.size(), 100000u);
  EXPECT_EQ(test::readText(dir + "/state2.csv"), one);
  EXPECT_EQ(test::readText(dir + "/state5.csv"), one);
  test::removeTree(dir);
}

// A scene's jelly other than the course cube has no world file to time the parsing of (formatWorld
// writes the course cube's 512 points: it read past a smaller body's arrays before).
TEST(Cli, BenchOfASceneWithItsOwnJellyTimesNoWorldFile) {
  test::CommandResult r =
      runJello("--bench --steps 2 '" + std::string(JELLO_SOURCE_DIR) + "/scenes/bar.toml'");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("world parsing                       -  (a scene's jelly"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("RK4"), std::string::npos) << r.out;
}

// The pictures' library is loaded for frames and only for them.
TEST(Cli, AHeadlessRunLoadsNoGlLibrary) {
  const char* pictureLibraries[] = {"libGL.so", "libOSMesa.so", "libglut.so", "libX11.so",
                                    "libjpeg.so"};
  test::CommandResult r =
      runJello("--headless --steps 3 '" + dataPath("rotate.w") + "'", "", "env LD_DEBUG=libs");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("calling init"), std::string::npos) << "LD_DEBUG says nothing here";
  for (const char* library : pictureLibraries)
    EXPECT_EQ(r.err.find(library), std::string::npos) << library;
#ifdef JELLO_HAVE_GRAPHICS
  std::string dir = test::makeTempDir();
  r = runJello("--headless --steps 3 --frames frames '" + dataPath("rotate.w") + "'", dir,
               "env LD_DEBUG=libs");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("libOSMesa.so"), std::string::npos) << "frames were drawn without OSMesa?";
  test::removeTree(dir);
#endif
}

TEST(Cli, DefaultLengthIsThreeHundredFramesOfNSteps) {
  test::CommandResult r =
      runJello("--headless --n 2 --integrator euler --dt 1e-5 '" + dataPath("moveLeft.w") + "'");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("EULER dt=1e-05 steps=600 "), std::string::npos) << r.out;
}

TEST(Cli, TimeIsConvertedToSteps) {
  test::CommandResult r = runJello("--headless --time 0.05 '" + dataPath("jello.w") + "'");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("steps=100 "), std::string::npos) << r.out;
  EXPECT_EQ(stepsForTime(1.0, 0.001), 1000);
  EXPECT_EQ(stepsForTime(0.3, 0.1), 3);
  EXPECT_EQ(stepsForTime(0.25, 0.1), 3);
}

TEST(Cli, ATimeOfMoreStepsThanARunMayTakeIsRefusedNamingTimeAndDt) {
  // Before: steps=-9223372036854775807, exit 0, nothing simulated.
  EXPECT_EQ(stepsForTime(1e9, 1e-3), 999999999000LL) << "kMaxSteps (less the slack) is allowed";
  EXPECT_EQ(stepsForTime(1.1e9, 1e-3), std::nullopt);
  EXPECT_EQ(stepsForTime(1e16, 1e-3), std::nullopt);
  EXPECT_EQ(stepsForTime(1, 1e-300), std::nullopt);
  EXPECT_EQ(stepsForTime(1e300, 1e-300), std::nullopt) << "T/dt = inf";
  const std::string world = " '" + dataPath("jello.w") + "'";
  for (const char* args : {"--headless --time 1e16", "--headless --dt 1e-300 --time 1",
                           "--headless --time 1e300 --dt 1e-300"}) {
    test::CommandResult r = runJello(args + world);
    EXPECT_EQ(r.status, 2) << args << ": " << r.out;
    EXPECT_EQ(lineCount(r.err), 1) << args << ": " << r.err;
    EXPECT_NE(r.err.find("--time"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("--dt"), std::string::npos) << r.err;
    EXPECT_EQ(r.out, "") << args;
  }
  test::CommandResult r = runJello("--headless --time 1e16 --dt 0.001" + world);
  EXPECT_EQ(
      r.err,
      "jello: --time 1e+16 s at --dt 0.001 s would take 1e+19 steps, more than the 1e+12 a run may "
      "take; choose a shorter --time or a larger --dt\n");
  // --report runs the world's own dt to --time: refused before its folder is made.
  std::string dir = test::makeTempDir();
  r = runJello("--report '" + dir + "/report' --dt 1e-300" + world);
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("--time 1 s at --dt 1e-300 s"), std::string::npos) << r.err;
  EXPECT_EQ(::access((dir + "/report").c_str(), F_OK), -1);
  test::removeTree(dir);
}

TEST(Cli, WithoutADisplayItSaysSoAndRunsHeadless) {
  std::string dir = test::makeTempDir();
  test::CommandResult r =
      runJello("--steps 5 '" + dataPath("rotate.w") + "'", dir, "env -u DISPLAY");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("running headless"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("steps=5 "), std::string::npos) << r.out;
  test::removeTree(dir);
}

TEST(Cli, DumpHoldsTheFinalStateBitForBitAndTheOverrides) {
  std::string dir = test::makeTempDir();
  std::string out = dir + "/final.w";
  test::CommandResult r = runJello("--headless --steps 50 --integrator EULER --dt 0.0002 --dump '" +
                                   out + "' '" + dataPath("gravity.w") + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  WorldFile dumped = readWorldFile(out);
  WorldFile f = readWorldFile(dataPath("gravity.w"));
  Model model = makeModel(f.world, f.state);
  Stepper stepper(Integrator::Euler);
  for (int s = 0; s < 50; ++s) stepper.step(model, f.state, 0.0002);
  EXPECT_EQ(dumped.state.y, f.state.y);
  EXPECT_EQ(dumped.run.integrator, Integrator::Euler);
  EXPECT_EQ(dumped.run.dt, 0.0002);
  EXPECT_EQ(dumped.world.field.forces, f.world.field.forces);
  test::removeTree(dir);
}

TEST(Cli, DivergenceStopsWithStatusOneNamingStepTimeAndDt) {
  std::string dir = test::makeTempDir();
  std::string out = dir + "/never.w";
  test::CommandResult r = runJello("--headless --steps 2000 --integrator EULER --dt 0.01 --dump '" +
                                   out + "' '" + dataPath("jello.w") + "'");
  EXPECT_EQ(r.status, 1) << r.out << r.err;
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  for (const char* part : {"diverged at step ", "(t=", "dt=0.01", "EULER"}) {
    EXPECT_NE(r.err.find(part), std::string::npos) << part << " missing from: " << r.err;
  }
  EXPECT_FALSE(exists(out)) << "a diverged run wrote a dump";
  test::removeTree(dir);
}

class CliMalformedWorld : public ::testing::TestWithParam<test::MalformedCase> {};

TEST_P(CliMalformedWorld, ExitsTwoWithOneLineNamingTheLine) {
  const test::MalformedCase& c = GetParam();
  std::string dir = test::makeTempDir();
  std::string path = dir + "/bad world.w";
  std::string dump = dir + "/dump.w";
  test::writeText(path, c.text);
  test::CommandResult r = runJello("--headless --steps 3 --dump '" + dump + "' '" + path + "'");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(path + ":" + std::to_string(c.line) + ": "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("(" + c.field), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_FALSE(exists(dump));
  test::removeTree(dir);
}

INSTANTIATE_TEST_SUITE_P(Cases, CliMalformedWorld, ::testing::ValuesIn(test::malformedCases()),
                         [](const auto& testInfo) { return testInfo.param.name; });

struct UsageCase {
  const char* name;
  std::string args;
  const char* says;
  bool ownWorld = false;  // the arguments name the world themselves; otherwise rotate.w is run
};

void PrintTo(const UsageCase& c, std::ostream* os) { *os << c.args; }

class CliUsage : public ::testing::TestWithParam<UsageCase> {};

TEST_P(CliUsage, ExitsTwoWithOneLine) {
  const UsageCase& c = GetParam();
  test::CommandResult r =
      runJello(c.ownWorld ? c.args : c.args + " '" + dataPath("rotate.w") + "'");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(c.says), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");
}

INSTANTIATE_TEST_SUITE_P(
    Cases, CliUsage,
    ::testing::Values(
        UsageCase{"unknown_option", "--headless --fast", "--fast: no such option (see"},
        UsageCase{"misspelled_option", "--headless --step 100",
                  "--step: no such option; did you mean --steps?"},
        UsageCase{"misspelled_flag", "--headles",
                  "--headles: no such option; did you mean --headless?"},
        UsageCase{"single_dash", "--headless -time 1",
                  "-time: no such option; did you mean --time?"},
        UsageCase{"fps_without_frames", "--headless --fps 10", "--fps goes with --frames"},
        UsageCase{"fps_with_check", "--check --fps 10", "--fps goes with --frames"},
        UsageCase{"camera_without_frames", "--headless --camera 30,20",
                  "--camera goes with --frames or the window"},
        UsageCase{"colouring_with_check", "--check --colouring friction",
                  "--colouring goes with --frames or the window"},
        UsageCase{"negative_fps", "--headless --fps -1 --frames /tmp/never", "--fps"},
        UsageCase{"steps_and_time", "--headless --steps 3 --time 1", "--time"},
        UsageCase{"negative_steps", "--headless --steps -3", "--steps"},
        UsageCase{"zero_dt", "--headless --dt 0", "--dt"},
        UsageCase{"nan_dt", "--headless --dt nan", "--dt"},
        UsageCase{"inf_time", "--headless --time inf", "--time"},
        UsageCase{"zero_n", "--headless --n 0", "--n"},
        UsageCase{"word_steps", "--headless --steps many", "--steps"},
        UsageCase{"save_state_with_window", "--save-state /tmp/never.csv",
                  "--save-state goes with --headless"},
        UsageCase{"static_and_check", "--static --check", "each a command of its own"},
        UsageCase{"static_with_time", "--static --time 1", "--static takes no --time"},
        UsageCase{"compare_with_save_state", "--compare-materials --save-state /tmp/never.csv",
                  "--save-state goes with a headless run or --static"},
        UsageCase{"compare_a_course_world", "--compare-materials",
                  "needs a scene of one jelly of finite elements"},
        UsageCase{"newline_in_number", "--headless --time '0.\nx'", "--time: '0.\\x0Ax' is not"},
        UsageCase{"unknown_integrator", "--headless --integrator RK3", "unknown integrator 'RK3'"},
        UsageCase{"missing_world", "--headless /no/such/world.w", "/no/such/world.w: cannot open",
                  true},
        UsageCase{"dump_into_missing_dir", "--headless --dump /no/such/dir/out.w", "/no/such/dir"},
        UsageCase{"dump_onto_directory", "--headless --dump /tmp", "is a directory"},
        UsageCase{"two_worlds", "--headless a.w b.w", "not expected", true}),
    [](const auto& testInfo) { return std::string(testInfo.param.name); });

// jello --static: the cantilever at rest, its state written; --compare-materials on a small block
// of elements: the four runs, the last the reference.
TEST(Cli, StaticFindsTheCantileverAtRestAndCompareMaterialsTablesTheFourRuns) {
  std::string dir = test::makeTempDir();
  const std::string scenes = std::string(JELLO_SOURCE_DIR) + "/scenes/";
  test::CommandResult r =
      runJello("--static --save-state '" + dir + "/rest.csv' '" + scenes + "cantilever.toml'");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("at rest after 3 Newton steps"), std::string::npos) << r.out;
  // The farthest point moved 0.0909 mm (the tip's corner; beam theory's tip 0.092 mm).
  EXPECT_NE(r.out.find("point [40][0][8], by 9.09"), std::string::npos) << r.out;
  EXPECT_TRUE(exists(dir + "/rest.csv"));
  std::ofstream(dir + "/block.toml")
      << "dt = 0.0005\nn = 10\ngravity = [0, 0, -9.81]\n[[pin]]\nk = [0, 0]\n[bounds]\n"
         "present = false\n[jelly]\nshape = \"lattice\"\nsize = [3, 3, 4]\nspacing = 0.05\n"
         "material = \"corotated\"\nyoungs_modulus = 2e4\npoisson_ratio = 0.3\ndensity = 1000\n";
  r = runJello("--compare-materials --time 0.05 '" + dir + "/block.toml'");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* row : {"springs (fitted)         0.05 ", "elements (corotated)     0.05 ",
                          "springs (fitted)         0.025", "(reference)"})
    EXPECT_NE(r.out.find(row), std::string::npos) << row << " missing from:\n" << r.out;
  EXPECT_NE(r.out.find("10 samples"), std::string::npos) << r.out;
  test::removeTree(dir);
}

// A world starting a point at 1e308 m: --static says what a run says of it (beyond the guard),
// not a force left after no Newton step.
TEST(Cli, StaticOnAStartBeyondTheGuardSaysWhatARunSays) {
  const std::string dir = test::makeTempDir();
  std::string world = test::readText(std::string(JELLO_SOURCE_DIR) + "/world/rotate.w");
  std::size_t at = world.size() - 1;  // the last line is the last velocity; 1024 lines back, p[0]
  for (int lines = 0; lines < 1024; ++lines) at = world.rfind('\n', at - 1);
  world.replace(at + 1, world.find('\n', at + 1) - at - 1, "1e308 0 0");
  test::writeText(dir + "/far.w", world);
  const test::CommandResult run = runJello("--headless --steps 1 '" + dir + "/far.w'");
  const test::CommandResult rest = runJello("--static '" + dir + "/far.w'");
  EXPECT_EQ(run.status, 1);
  EXPECT_EQ(rest.status, 1);
  const std::string said = "the initial state is already beyond the guard";
  EXPECT_NE(run.err.find(said), std::string::npos) << run.err;
  EXPECT_NE(rest.err.find(said), std::string::npos) << rest.err;
  EXPECT_EQ(rest.err.find("Newton"), std::string::npos) << rest.err;
  test::removeTree(dir);
}

TEST(Cli, AMissingDefaultWorldIsSaidToBeTheDefaultWithHowToNameOne) {
  std::string dir = test::makeTempDir();
  test::CommandResult r = runJello("--headless", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("world/rotate.w: cannot open"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("no WORLD was named"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("jello path/to/world.w"), std::string::npos) << r.err;
  // A world the user named is not called the default.
  r = runJello("--headless world/rotate.w", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err.find("no WORLD was named"), std::string::npos) << r.err;
  test::removeTree(dir);
}

TEST(Cli, OptionNamesAnEditInFourCharactersAwayOrAPrefixAreSuggested) {
  EXPECT_EQ(editDistance("--step", "--steps"), 1u);
  EXPECT_EQ(editDistance("--itnegrator", "--integrator"), 2u);
  EXPECT_EQ(editDistance("", "abc"), 3u);
  CLI::App app;
  int value = 0;
  for (const char* name : {"--steps", "--time", "--integrator", "--integrators", "--frames"})
    app.add_option(name, value);
  EXPECT_EQ(nearestOption(app, "--step"), "--steps");
  EXPECT_EQ(nearestOption(app, "--itnegrator"), "--integrator");
  EXPECT_EQ(nearestOption(app, "--frame"), "--frames");
  EXPECT_EQ(nearestOption(app, "--integ"), "--integrator") << "a prefix: the first of its kind";
  EXPECT_EQ(nearestOption(app, "--bogus"), "");
  EXPECT_EQ(nearestOption(app, "--tim"), "--time") << "one edit in a short name";
  EXPECT_EQ(nearestOption(app, "--fames"), "--frames");
  EXPECT_EQ(nearestOption(app, "--tmie"), "") << "two edits in six characters are too many";
  EXPECT_EQ(nearestOption(app, "-x"), "") << "too short to be a prefix";
}

TEST(FrameClock, FramesFallOnTheFirstStepAtOrPastEachMultipleOfOneOverFps) {
  const FrameClock thirty(30, 1, 0.001);
  EXPECT_EQ(thirty.nextAfter(0), 34);  // 1/30 s = 33.3 steps
  EXPECT_EQ(thirty.nextAfter(34), 67);
  EXPECT_EQ(thirty.nextAfter(67), 100);  // 0.1 s exactly, although 100 * 0.001 * 30 rounds
  EXPECT_EQ(thirty.nextAfter(40), 67) << "from a step between frames";
  EXPECT_EQ(thirty.stepsForFrames(300), 9967);
  const FrameClock ten(10, 5, 0.001);
  for (long long step : {0LL, 100LL, 200LL, 900LL}) EXPECT_EQ(ten.nextAfter(step), step + 100);
  EXPECT_EQ(FrameClock(50, 1, 0.001).nextAfter(0), 20);
  // 580 * 0.001 * 50 is 28.999999999999996: still frame 29's step, so the next is frame 30's.
  EXPECT_EQ(FrameClock(50, 1, 0.001).nextAfter(580), 600);
  EXPECT_EQ(FrameClock(0, 7, 0.001).nextAfter(0), 7) << "fps 0: every n steps, the course's";
  EXPECT_EQ(FrameClock(0, 7, 0.001).nextAfter(8), 14);
  EXPECT_EQ(FrameClock(0, 7, 0.001).stepsForFrames(300), 299 * 7);
  EXPECT_EQ(FrameClock(2000, 1, 0.001).nextAfter(5), 6) << "never two frames of one step";
}

// What a program writes to a terminal: run under a pseudo-terminal (stdout and stderr both),
// read to its end.
std::string runInTerminal(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  int master = -1;
  const pid_t child = ::forkpty(&master, nullptr, nullptr, nullptr);
  if (child == 0) {
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  std::string out;
  char buffer[4096];
  for (ssize_t got; (got = ::read(master, buffer, sizeof buffer)) > 0;) out.append(buffer, got);
  ::close(master);
  ::waitpid(child, nullptr, 0);
  return out;
}

TEST(Cli, InATerminalTheProgressLineEndsWithItsFinalStateAndANewlineBeforeTheSummary) {
  // Long enough (2 s or more) for the progress line to be shown at all.
  const std::string world = dataPath("rotate.w");
  const std::string out =
      runInTerminal({JELLO_BINARY, "--headless", "--kernel", "general", "--steps", "20000", world});
  const std::size_t last = out.find("step 20000/20000 (100%) in ");
  ASSERT_NE(last, std::string::npos) << out;
  EXPECT_NE(out.find("step ", 0), last) << "earlier states were shown first";
  const std::size_t summary = out.find(world + ": RK4 dt=0.001 steps=20000 ");
  ASSERT_NE(summary, std::string::npos) << out;
  EXPECT_GT(summary, last);
  EXPECT_EQ(out[summary - 1], '\n') << "the summary starts a line of its own: " << out;
}

TEST(Cli, HelpAndVersion) {
  test::CommandResult help = runJello("--help");
  EXPECT_EQ(help.status, 0);
  for (const char* option :
       {"--headless", "--steps", "--time", "--integrator", "--dt", "--n", "--dump"}) {
    EXPECT_NE(help.out.find(option), std::string::npos) << option;
  }
  test::CommandResult version = runJello("--version");
  EXPECT_EQ(version.status, 0);
  EXPECT_NE(version.out.find("jello "), std::string::npos) << version.out;
}

}  // namespace
}  // namespace jello
