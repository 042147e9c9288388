// What jello writes, and what it never does: hostile file names, full disks, signals, two runs
// at once, files it was not told to replace (issue 12; README "Reliability").
#include <dirent.h>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "analysis/stability.h"
#include "app/commandline.h"
#include "core/exitstatus.h"
#include "core/output.h"
#include "core/plot.h"
#include "test_support.h"

namespace jello {
namespace {

std::vector<std::string> entries(const std::string& dir) {
  std::vector<std::string> names;
  if (DIR* d = ::opendir(dir.c_str())) {
    while (dirent* e = ::readdir(d))
      if (std::string(e->d_name) != "." && std::string(e->d_name) != "..")
        names.push_back(e->d_name);
    ::closedir(d);
  }
  std::sort(names.begin(), names.end());
  return names;
}

int lines(const std::string& text) {
  return static_cast<int>(std::count(text.begin(), text.end(), '\n'));
}

off_t sizeOf(const std::string& path) {
  struct stat info {};
  return ::stat(path.c_str(), &info) == 0 ? info.st_size : -1;
}

// ---- Item 1: no name reaches a script -----------------------------------------------------

const std::vector<std::string> kHostileNames = {
    "x'; system 'touch PWNED'; print '.w", "a`touch PWNED`b.w", "$(touch PWNED).w",
    "new\nline'\n system 'touch PWNED.w", "\xff\xfe not utf-8 \\ '.w"};

// The whole path once (one report is seconds of work, more under the sanitizers), with every
// hostile kind of character in one name.
TEST(HostileNames, AWorldNamedLikeGnuplotCodeIsDrawnAsItsNameAndRunsNothing) {
  if (!test::haveGnuplot()) GTEST_SKIP() << "gnuplot is not installed";
  const std::string name = "x'; system 'touch PWNED'; print '`touch PWNED`$(touch PWNED)\n\xff.w";
  std::string dir = test::makeTempDir();
  test::writeText(dir + "/" + name, test::readText(test::dataPath("rotate.w")));
  test::CommandResult r = test::runJelloArgs(
      {"--report", "rep", "--time", "0.001", "--integrators", "EULER", name}, {dir});
  EXPECT_EQ(r.status, 0) << r.err;
  std::vector<std::string> expected = {name, "rep"};
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(entries(dir), expected) << "something ran";
  EXPECT_GT(sizeOf(dir + "/rep/report.png"), 1000);
  // The script stays valid gnuplot and draws the same picture again, running nothing.
  EXPECT_EQ(test::runShell("cd '" + dir + "/rep' && gnuplot report.gp 2>&1").out, "");
  EXPECT_EQ(entries(dir + "/rep"),
            (std::vector<std::string>{"report.csv", "report.gp", "report.md", "report.png"}));
  test::removeTree(dir);
}

// Each kind alone, through the same drawing path as the report's, in a script of a few lines.
TEST(HostileNames, EachHostileTitleIsDrawnAndRunsNothing) {
  if (!test::haveGnuplot()) GTEST_SKIP() << "gnuplot is not installed";
  for (const std::string& name : kHostileNames) {
    std::string dir = test::makeTempDir();
    test::writeText(dir + "/t.gp",
                    "set terminal pngcairo size 200,100\nif (!exists(\"png\")) png = 't.png'\n"
                    "set output png\nset title " +
                        gnuplotString(name) + "\nplot x\n");
    EXPECT_EQ(drawWithGnuplot(dir, "t.gp", "t.png", Existing::Refuse), "") << name;
    EXPECT_EQ(entries(dir), (std::vector<std::string>{"t.gp", "t.png"}))
        << "something ran: " << name;
    test::removeTree(dir);
  }
}

TEST(HostileNames, AnErrorAboutANameWithANewlineStaysOneLine) {
  test::CommandResult r = test::runJelloArgs({"--headless", "no\nsuch\x01world.w"});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("no\\x0Asuch\\x01world.w"), std::string::npos) << r.err;
}

TEST(HostileNames, CheckJsonOfANameThatIsNotUtf8IsValidJsonNotAnException) {
  StabilityReport report;
  report.criticalRest = report.criticalInitial = report.criticalFaceOnWall =
      std::vector<double>(kExplicitIntegrators.size(), 1e-3);
  RunSettings run;
  std::string json;
  ASSERT_NO_THROW(json = stabilityJson("bad\xff\xfename.w", run, report));
  EXPECT_NE(json.find("\"world\": \"bad\xEF\xBF\xBD\xEF\xBF\xBDname.w\""), std::string::npos)
      << json;
}

TEST(HostileNames, PrintableEscapesControlsAndBrokenUtf8ButKeepsRealText) {
  EXPECT_EQ(printable("caf\xC3\xA9 \xE2\x82\xAC ok"), "caf\xC3\xA9 \xE2\x82\xAC ok");
  EXPECT_EQ(printable("a\nb\tc\x7F"), "a\\x0Ab\\x09c\\x7F");
  EXPECT_EQ(printable("\xC3(\xED\xA0\x80\xF5"),
            "\\xC3(\\xED\\xA0\\x80\\xF5");  // cut, surrogate, past U+10FFFF
  EXPECT_EQ(printable("back\\slash"), "back\\\\slash");
  // C1 controls (U+009B is a terminal's CSI, U+009D its OSC) and bidirectional overrides
  // (U+202E, U+2066) act on a terminal or reorder what a reader sees: written as \uNNNN.
  EXPECT_EQ(printable("a\xC2\x9B"
                      "31mb\xC2\x9D"
                      "c"),
            "a\\u009B31mb\\u009Dc");
  EXPECT_EQ(printable("x\xE2\x80\xAEy\xE2\x81\xA6z"), "x\\u202Ey\\u2066z");
  EXPECT_EQ(printable("\xC2\xA0\xE2\x80\x94"), "\xC2\xA0\xE2\x80\x94");  // NBSP, em dash kept
}

// ---- Item 2: --dump's rule ------------------------------------------------------------------

test::CommandResult dump(const std::string& target, const std::string& world) {
  return test::runJelloArgs({"--headless", "--steps", "1", "--dump", target, world});
}

TEST(DumpRule, NeverReplacesADeviceALinkAFolderAReadOnlyFileOrTheWorldItself) {
  std::string dir = test::makeTempDir();
  const std::string world = dir + "/w.w", other = dir + "/other.txt", readOnly = dir + "/ro.w";
  test::writeText(world, test::readText(test::dataPath("still.w")));
  test::writeText(other, "mine");
  test::writeText(readOnly, "keep");
  ::chmod(readOnly.c_str(), 0444);
  ASSERT_EQ(::symlink(other.c_str(), (dir + "/link.w").c_str()), 0);
  ASSERT_EQ(::mkfifo((dir + "/fifo.w").c_str(), 0644), 0);
  // A device of its own (a copy of /dev/full's numbers), so that a jello that wrongly replaces
  // devices harms no device the machine uses. Making one needs root; without it, the FIFO
  // stands alone for what is not a regular file.
  const std::string device = dir + "/full";
  const bool haveDevice = ::mknod(device.c_str(), S_IFCHR | 0666, ::makedev(1, 7)) == 0;
  std::vector<std::pair<std::string, std::string>> cases = {
      {dir + "/link.w", "symbolic link"},
      {dir + "/fifo.w", "not a regular file"},
      {dir, "is a directory"},
      {readOnly, "read-only"},
      {world, "the world being run"},
      {dir + "/./w.w", "the world being run"}};
  if (haveDevice) cases.push_back({device, "not a regular file"});
  for (const auto& [target, says] : cases) {
    test::CommandResult r = dump(target, world);
    EXPECT_EQ(r.status, 2) << target;
    EXPECT_EQ(r.out, "") << "refused before the run: " << target;
    EXPECT_NE(r.err.find(says), std::string::npos) << r.err;
  }
  struct stat info {};
  if (haveDevice) {
    ASSERT_EQ(::stat(device.c_str(), &info), 0);
    EXPECT_TRUE(S_ISCHR(info.st_mode));
  }
  EXPECT_EQ(test::readText(other), "mine");
  EXPECT_EQ(test::readText(readOnly), "keep");
  ASSERT_EQ(::lstat((dir + "/link.w").c_str(), &info), 0);
  EXPECT_TRUE(S_ISLNK(info.st_mode));
  EXPECT_EQ(test::readText(world), test::readText(test::dataPath("still.w")));
  test::removeTree(dir);
}

TEST(DumpRule, ReplacesARegularFileItNamesAndKeepsItsMode) {
  std::string dir = test::makeTempDir();
  const std::string out = dir + "/out.w";
  test::writeText(out, "old");
  ::chmod(out.c_str(), 0640);
  test::CommandResult r = dump(out, test::dataPath("still.w"));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(readWorldFile(out).run.dt, readWorldFile(test::dataPath("still.w")).run.dt);
  struct stat info {};
  ASSERT_EQ(::stat(out.c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 0777, 0640u);
  EXPECT_EQ(entries(dir), std::vector<std::string>{"out.w"}) << "a temporary file was left";
  test::removeTree(dir);
}

TEST(DumpRule, ALongValidNameIsWrittenAndATooLongOneIsRefusedBeforeTheRun) {
  std::string dir = test::makeTempDir();
  const std::string longest(248, 'n'), tooLong(300, 'n');
  test::CommandResult r = dump(dir + "/" + longest, test::dataPath("still.w"));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_GT(sizeOf(dir + "/" + longest), 0);
  r = dump(dir + "/" + tooLong, test::dataPath("still.w"));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, "") << "refused before the run";
  EXPECT_NE(r.err.find("bytes long, more than the 255 its folder's file system allows"),
            std::string::npos)
      << r.err;
  test::removeTree(dir);
}

// ---- Item 3: no exception escapes -----------------------------------------------------------

TEST(NoCrash, BenchReadsAWorldFromAPipeOnce) {
  test::CommandResult r = test::runShell("cat '" + test::dataPath("still.w") + "' | " +
                                         test::jelloCommand() + " --bench --steps 1 /dev/stdin");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("world parsing"), std::string::npos);
}

// ---- Item 7: a full disk leaves nothing behind and says so ----------------------------------

void limitFileSize(rlim_t bytes) {
  ::signal(SIGXFSZ, SIG_IGN);  // a write past the limit fails with EFBIG, as on a full disk
  rlimit limit{bytes, bytes};
  ::setrlimit(RLIMIT_FSIZE, &limit);
}
void smallFiles() { limitFileSize(2048); }
// Room for a report's text files (its report.md, with commands to run, is about 2-4 KB), not
// for its picture (about 30 KB).
void reportTextSizedFiles() { limitFileSize(8192); }

TEST(FullDisk, ADumpThatDoesNotFitLeavesNoFileAndExitsTwo) {
  std::string dir = test::makeTempDir();
  test::CommandResult r = test::runJelloArgs(
      {"--headless", "--steps", "1", "--dump", dir + "/out.w", test::dataPath("still.w")},
      {"", 0, smallFiles});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("cannot write"), std::string::npos) << r.err;
  EXPECT_EQ(entries(dir), std::vector<std::string>{});
  test::removeTree(dir);
}

// A mesh that does not fit (PLY and OBJ alike) is named in the one line, and leaves no file.
TEST(FullDisk, AnExportedMeshThatDoesNotFitIsNamedAndLeavesNoFile) {
  for (const std::string format : {"ply", "obj"}) {
    std::string dir = test::makeTempDir();
    test::CommandResult r =
        test::runJelloArgs({"--headless", "--steps", "1", "--export", dir + "/m", "--export-format",
                            format, test::dataPath("still.w")},
                           {"", 0, smallFiles});
    EXPECT_EQ(r.status, 2) << format;
    EXPECT_EQ(lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(dir + "/m/0000." + format + ": cannot write"), std::string::npos) << r.err;
    EXPECT_EQ(entries(dir + "/m"), std::vector<std::string>{}) << format;
    test::removeTree(dir);
  }
}

TEST(FullDisk, AReportWhosePictureDoesNotFitNamesNoPictureAndLeavesNoEmptyFile) {
  if (!test::haveGnuplot()) GTEST_SKIP() << "gnuplot is not installed";
  std::string dir = test::makeTempDir();
  test::CommandResult r = test::runJelloArgs({"--report", dir + "/rep", "--time", "0.002",
                                              "--integrators", "EULER", test::dataPath("rotate.w")},
                                             {"", 0, reportTextSizedFiles});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("report.png was not drawn"), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find("report.png"), std::string::npos) << "named as drawn: " << r.out;
  EXPECT_EQ(entries(dir + "/rep"),
            (std::vector<std::string>{"report.csv", "report.gp", "report.md"}));
  // The next run, with room, is not blocked by leftovers.
  r = test::runJelloArgs({"--report", dir + "/rep", "--overwrite", "--time", "0.002",
                          "--integrators", "EULER", test::dataPath("rotate.w")});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_GT(sizeOf(dir + "/rep/report.png"), 1000);
  test::removeTree(dir);
}

// ---- Item 8: a signal removes the temporary file of the write under way ----------------------

TEST(Signals, TheTemporaryFileOfAWriteUnderWayGoesWithTheSignal) {
  for (int signal : {SIGINT, SIGTERM, SIGHUP}) {
    std::string dir = test::makeTempDir();
    pid_t child = ::fork();
    if (child == 0) {
      installSignalCleanup();
      writeFileWhole(
          dir + "/out.w",
          [signal](std::FILE* file) {
            std::fputs("half a world", file);
            std::fflush(file);
            ::raise(signal);  // stopped in the middle of the write
          },
          Existing::Refuse);
      ::_exit(0);
    }
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal)
        << "the signal still ends the program";
    EXPECT_EQ(entries(dir), std::vector<std::string>{}) << "signal " << signal;
    test::removeTree(dir);
  }
}

// A frame being written when SIGINT arrives leaves no temporary JPEG: the graphics library's
// own list of temporary files is cleaned too (its handler chained to the program's).
TEST(Signals, AFrameBeingWrittenLeavesNoTemporaryFileBehind) {
  const std::string world = test::dataPath("still.w");
  int leftovers = 0, runs = 0;
  for (int run = 0; run < 12; ++run) {
    std::string dir = test::makeTempDir(), frames = dir + "/f";
    pid_t child = ::fork();
    if (child == 0) {
      int null = ::open("/dev/null", O_WRONLY);
      ::dup2(null, 2);
      ::execl(JELLO_BINARY, JELLO_BINARY, "--headless", "--steps", "100000", "--n", "1", "--size",
              "4000x3000", "--max-frames", "10000", "--frames", frames.c_str(), world.c_str(),
              static_cast<char*>(nullptr));
      ::_exit(127);
    }
    for (int i = 0; i < 400 && sizeOf(frames + "/0000.jpg") < 0; ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    std::this_thread::sleep_for(std::chrono::milliseconds(9 * run));  // somewhere in a frame
    ::kill(child, SIGINT);
    int status = 0;
    ::waitpid(child, &status, 0);
    if (sizeOf(frames + "/0000.jpg") < 0) {
      test::removeTree(dir);
      GTEST_SKIP() << "no frames: pictures are not built here";
    }
    ++runs;
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGINT) << status;
    for (const std::string& name : entries(frames)) leftovers += name.rfind(".jello-", 0) == 0;
    test::removeTree(dir);
  }
  EXPECT_EQ(leftovers, 0) << "in " << runs << " runs";
}

// Stopped while gnuplot draws, --report leaves no temporary picture behind: gnuplot is killed
// with it (it wrote its .jello-XXXXXX.png a second later, after the folder's claim had ended).
TEST(Signals, AReportStoppedWhileGnuplotDrawsLeavesNoTemporaryPicture) {
  if (!test::haveGnuplot()) GTEST_SKIP() << "gnuplot is not installed";
  int leftovers = 0;
  for (int run = 0; run < 3; ++run) {
    std::string dir = test::makeTempDir(), rep = dir + "/rep";
    pid_t child = ::fork();
    if (child == 0) {
      int null = ::open("/dev/null", O_WRONLY);
      ::dup2(null, 1);
      ::dup2(null, 2);
      ::execl(JELLO_BINARY, JELLO_BINARY, "--report", rep.c_str(), "--time", "0.01",
              "--integrators", "RK4", test::dataPath("jello.w").c_str(),
              static_cast<char*>(nullptr));
      ::_exit(127);
    }
    // Until its child gnuplot runs.
    bool drawing = false;
    for (int i = 0; i < 20000 && !drawing; ++i) {
      for (const std::string& pid : entries("/proc")) {
        if (pid.find_first_not_of("0123456789") != std::string::npos) continue;
        std::string stat = test::readText("/proc/" + pid + "/stat");
        std::size_t name = stat.find(") ");
        if (stat.find("(gnuplot)") == std::string::npos || name == std::string::npos) continue;
        drawing |= std::atoi(stat.c_str() + name + 4) == child;  // "pid (comm) S ppid"
      }
      if (!drawing) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    ::kill(child, SIGTERM);
    ::waitpid(child, nullptr, 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(1500));  // a gnuplot left would write
    for (const std::string& name : entries(rep)) leftovers += name.rfind(".jello-", 0) == 0;
    test::removeTree(dir);
    if (!drawing) GTEST_SKIP() << "gnuplot was never seen running";
  }
  EXPECT_EQ(leftovers, 0);
}

// ---- Item 9: two runs cannot share a folder ---------------------------------------------------

TEST(FolderClaims, ASecondClaimOnAFolderIsRefusedUntilTheFirstEnds) {
  std::string dir = test::makeTempDir() + "/frames";
  int ready[2], done[2];
  ASSERT_EQ(::pipe(ready), 0);
  ASSERT_EQ(::pipe(done), 0);
  pid_t child = ::fork();
  if (child == 0) {
    FolderClaim claim = claimFolder(dir);
    char c = 1;
    (void)!::write(ready[1], &c, 1);
    (void)!::read(done[0], &c, 1);
    ::_exit(0);
  }
  char c = 0;
  ASSERT_EQ(::read(ready[0], &c, 1), 1);
  try {
    claimFolder(dir);
    ADD_FAILURE() << "two runs held one folder";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("in use by another run"), std::string::npos) << e.what();
  }
  (void)!::write(done[1], &c, 1);
  ::waitpid(child, nullptr, 0);
  EXPECT_NO_THROW(claimFolder(dir)) << "the claim ends with its process";
  test::removeTree(dir.substr(0, dir.rfind('/')));
}

TEST(FolderClaims, TwoFrameRunsIntoOneFolderDoNotBothSucceedNorADumpIntoIt) {
  std::string dir = test::makeTempDir();
  const std::string frames = dir + "/f", world = test::dataPath("still.w");
  // The first run is long (200 frames of 1000 steps); the second starts once it has begun.
  pid_t first = ::fork();
  if (first == 0) {
    ::execl(JELLO_BINARY, JELLO_BINARY, "--headless", "--steps", "200000", "--n", "1000",
            "--frames", frames.c_str(), world.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  for (int i = 0; i < 400 && sizeOf(frames + "/0000.jpg") < 0; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(25));
  test::CommandResult second =
      test::runJelloArgs({"--headless", "--steps", "10", "--overwrite", "--frames", frames, world});
  // Nor may a dump go into the folder the first run holds.
  test::CommandResult dump =
      test::runJelloArgs({"--headless", "--steps", "10", "--dump", frames + "/end.w", world});
  ::kill(first, SIGTERM);
  ::waitpid(first, nullptr, 0);
  if (sizeOf(frames + "/0000.jpg") < 0) GTEST_SKIP() << "no frames: pictures are not built here";
  EXPECT_EQ(second.status, 2) << second.err;
  EXPECT_NE(second.err.find("in use by another run"), std::string::npos) << second.err;
  EXPECT_EQ(dump.status, 2) << dump.err;
  EXPECT_NE(dump.err.find("--dump " + frames + "/end.w: its folder is in use by another run"),
            std::string::npos)
      << dump.err;
  EXPECT_LT(sizeOf(frames + "/end.w"), 0);
  test::removeTree(dir);
}

// --overwrite replaces an earlier run's frames or meshes only where each is a regular file it may
// write: a symbolic link, a FIFO or a read-only file named like one is refused by name, and
// nothing is removed (the regular 0001 beside it stays too).
TEST(OverwriteRule, FramesAndMeshesNeverReplaceALinkAFifoOrAReadOnlyFile) {
  const std::string world = test::dataPath("still.w");
  for (const std::string option : {"--frames", "--export"}) {
    for (const std::string kind : {"link", "fifo", "read-only"}) {
      SCOPED_TRACE(option + " " + kind);
      std::string dir = test::makeTempDir(), out = dir + "/out";
      ::mkdir(out.c_str(), 0755);
      const std::string ext = option == "--frames" ? ".jpg" : ".obj";
      const std::string first = out + "/0000" + ext, second = out + "/0001" + ext;
      test::writeText(dir + "/target.txt", "the user's own\n");
      test::writeText(second, "an earlier frame\n");
      if (kind == "link") {
        ASSERT_EQ(::symlink((dir + "/target.txt").c_str(), first.c_str()), 0);
      } else if (kind == "fifo") {
        ASSERT_EQ(::mkfifo(first.c_str(), 0644), 0);
      }
      if (kind == "read-only") {
        test::writeText(first, "read-only\n");
        ::chmod(first.c_str(), 0444);
      }
      test::CommandResult r = test::runJelloArgs(
          {"--headless", "--steps", "2", "--n", "1", "--overwrite", option, out, world});
      if (option == "--frames" && r.err.find("pictures") != std::string::npos) GTEST_SKIP();
      EXPECT_EQ(r.status, 2) << r.err;
      EXPECT_NE(r.err.find(first), std::string::npos) << r.err;
      EXPECT_EQ(test::readText(dir + "/target.txt"), "the user's own\n");
      EXPECT_EQ(test::readText(second), "an earlier frame\n");
      struct stat info {};
      ASSERT_EQ(::lstat(first.c_str(), &info), 0);
      if (kind == "link") {
        EXPECT_TRUE(S_ISLNK(info.st_mode));
      } else if (kind == "fifo") {
        EXPECT_TRUE(S_ISFIFO(info.st_mode));
      } else {
        EXPECT_EQ(test::readText(first), "read-only\n");
      }
      ::chmod(first.c_str(), 0644);
      test::removeTree(dir);
    }
  }
}

// ---- Item 10: --report and --map replace nothing they did not check --------------------------

TEST(ReportFiles, AHandEditedScriptOrPictureIsNeverReplacedWithoutOverwrite) {
  std::string dir = test::makeTempDir();
  for (std::string name : {"report.gp", "report.png"}) {
    test::removeTree(dir);
    ::mkdir(dir.c_str(), 0777);
    test::writeText(dir + "/" + name, "my edits");
    test::CommandResult r = test::runJelloArgs(
        {"--report", dir, "--time", "0.002", "--integrators", "EULER", test::dataPath("rotate.w")});
    EXPECT_EQ(r.status, 2) << name;
    EXPECT_NE(r.err.find(name + ": already exists"), std::string::npos) << r.err;
    EXPECT_EQ(test::readText(dir + "/" + name), "my edits");
    EXPECT_EQ(entries(dir), std::vector<std::string>{name}) << "refused before writing anything";
  }
  for (std::string name : {"stability-map.gp", "stability-map.png"}) {
    test::removeTree(dir);
    ::mkdir(dir.c_str(), 0777);
    test::writeText(dir + "/" + name, "my edits");
    test::CommandResult r =
        test::runJelloArgs({"--check", "--map", dir, test::dataPath("rotate.w")});
    EXPECT_EQ(r.status, 2) << name;
    EXPECT_EQ(test::readText(dir + "/" + name), "my edits");
  }
  test::removeTree(dir);
}

// ---- Item 12: numbers and names on the command line -----------------------------------------

// kGoOn when the command is to go on, else the exit status its outcome gets.
constexpr int kGoOn = -1;
int parse(std::vector<std::string> args, JelloCommand* command) {
  args.insert(args.begin(), "jello");
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  ::testing::internal::CaptureStderr();
  ::testing::internal::CaptureStdout();
  const ParsedCommand parsed =
      parseJelloCommandLine(static_cast<int>(argv.size()), argv.data(), command);
  const int status = parsed.goOn ? kGoOn : exitStatusOf(parsed.outcome);
  ::testing::internal::GetCapturedStdout();
  ::testing::internal::GetCapturedStderr();
  return status;
}

TEST(CommandLineNumbers, FollowTheWorldFilesGrammar) {
  JelloCommand c;
  for (const char* refused : {"0x1p-10", "+0.001", " 0.001", "1e-400x", "inf", "nan", "0.001s", ""})
    EXPECT_EQ(parse({"--dt", refused}, &c), kExitBadInput) << refused;
  ASSERT_EQ(parse({"--dt", "0.1"}, &c), kGoOn);
  double fromFile = 0;
  std::string why;
  ASSERT_TRUE(parseWorldNumber("0.1", &fromFile, &why));
  EXPECT_EQ(*c.run.dt, fromFile) << "the same double as a world file's 0.1, not strtold's rounding";
  // A decimal whose long-double rounding then double rounding differs from one rounding.
  ASSERT_EQ(parse({"--dt", "1.00000000000000011102230246251565404236316680908203125"}, &c), kGoOn);
  ASSERT_TRUE(
      parseWorldNumber("1.00000000000000011102230246251565404236316680908203125", &fromFile, &why));
  EXPECT_EQ(*c.run.dt, fromFile);
}

TEST(CommandLineNumbers, StepsBeyondTheLargestWholeNumberAreRefusedNotClamped) {
  JelloCommand c;
  EXPECT_EQ(parse({"--steps", "99999999999999999999"}, &c), kExitBadInput);
  EXPECT_EQ(parse({"--steps", "0x10"}, &c), kExitBadInput);
  // At most 1e12 steps, as --time allows: --bench --steps 2^63 - 1 ran until killed.
  EXPECT_EQ(parse({"--steps", "9223372036854775807"}, &c), kExitBadInput);
  EXPECT_EQ(parse({"--steps", "1000000000001"}, &c), kExitBadInput);
  ASSERT_EQ(parse({"--steps", "1000000000000"}, &c), kGoOn);
  EXPECT_EQ(*c.run.steps, 1000000000000LL);
}

TEST(CommandLineNames, AnEmptyFramesDumpReportOrMapFolderIsRefusedNotIgnored) {
  JelloCommand c;
  for (const char* option : {"--frames", "--dump", "--report"})
    EXPECT_EQ(parse({option, ""}, &c), kExitBadInput);
  EXPECT_EQ(parse({"--check", "--map", ""}, &c), kExitBadInput);
}

TEST(CommandLine, OptionsThatNeedAnotherAreRefusedAlone) {
  JelloCommand c;
  EXPECT_EQ(parse({"--json"}, &c), kExitBadInput);
  EXPECT_EQ(parse({"--tolerance", "1e-3"}, &c), kExitBadInput);
  EXPECT_EQ(parse({"--integrators", "RK4"}, &c), kExitBadInput);
  EXPECT_EQ(parse({"--map", "m"}, &c), kExitBadInput);
  EXPECT_EQ(parse({"--check", "--json"}, &c), kGoOn);
  EXPECT_EQ(c.mode, JelloCommand::Mode::Check);
}

// An option the command would ignore is refused, not run past (each ran and wrote nothing);
// --integrators names each integrator once.
TEST(CommandLine, OptionsACommandWouldIgnoreAreRefused) {
  for (const std::vector<std::string>& args :
       std::vector<std::vector<std::string>>{{"--check", "--dump", "x.w"},
                                             {"--check", "--report", "r"},
                                             {"--check", "--frames", "f"},
                                             {"--bench", "--report", "r"},
                                             {"--bench", "--frames", "f"},
                                             {"--report", "r", "--dump", "x.w"},
                                             {"--report", "r", "--integrators", ""},
                                             {"--report", "r", "--integrators", "RK4,rk4"}}) {
    JelloCommand c;
    EXPECT_EQ(parse(args, &c), kExitBadInput) << args[0] << " " << args[1];
  }
  JelloCommand c;
  ASSERT_EQ(parse({"--report", "r", "--integrators", "RK4,EULER"}, &c), kGoOn);
  EXPECT_EQ(c.report.integrators.size(), 2u);
}

TEST(DefaultRun, AWorldWhoseNMakesTheDefaultRunEndlessIsRefusedWithWhatToDo) {
  test::CommandResult r =
      test::runJelloArgs({"--headless", "--n", "2147483647", test::dataPath("still.w")});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("644245094100 steps long; say how long with --steps N or --time T"),
            std::string::npos)
      << r.err;
  r = test::runJelloArgs(
      {"--headless", "--n", "2147483647", "--steps", "3", test::dataPath("still.w")});
  EXPECT_EQ(r.status, 0) << r.err;
}

TEST(NoCrash, AWorldLargerThanMaxMemoryIsRefusedBeforeItIsRead) {
  test::CommandResult r =
      test::runJelloArgs({"--headless", "--max-memory", "0.05", test::dataPath("rotate.w")});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(
      r.err.find(
          ":7: not enough memory for this world: needs 0.136 GB, 0.05 GB available (resolution)"),
      std::string::npos)
      << r.err;
}

TEST(StandardOutput, AResultThatCannotBeWrittenIsAFailure) {
  test::CommandResult r = test::runShell(test::jelloCommand() + " --headless --steps 1 '" +
                                         test::dataPath("still.w") + "' >/dev/full");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("cannot write to standard output"), std::string::npos) << r.err;
  // createWorld's answers too (it exited 0 with --describe into a full disk).
  for (const std::string& args :
       {" --describe '" + test::dataPath("still.w") + "'", std::string(" --help")}) {
    test::CommandResult c = test::runShell(std::string(JELLO_CREATE_WORLD) + args + " >/dev/full");
    EXPECT_EQ(c.status, 2) << args;
    EXPECT_NE(c.err.find("createWorld: cannot write to standard output: No space left on device"),
              std::string::npos)
        << c.err;
  }
}

// --camera and --size read their numbers in the world files' grammar: no hexadecimal, no sign
// where none belongs, no blank (each was accepted).
TEST(CommandLineNumbers, CameraAndSizeTakeOnlyTheWorldFilesNumbers) {
  for (const char* camera : {"0x1e,0x1e", "+30,30", "30,30,0x6", " 30,30", "30,,30", "30"}) {
    JelloCommand c;
    EXPECT_EQ(parse({"--headless", "--frames", "f", "--camera", camera}, &c), kExitBadInput)
        << camera;
  }
  for (const char* size : {"+16x16", "16x+16", " 16x16", "0x10x16", "16x16x16", "16x"}) {
    JelloCommand c;
    EXPECT_EQ(parse({"--headless", "--frames", "f", "--size", size}, &c), kExitBadInput) << size;
  }
  JelloCommand c;
  ASSERT_EQ(
      parse({"--headless", "--frames", "f", "--camera", "-90,8,3.5", "--size", "320X240"}, &c),
      kGoOn);
  EXPECT_EQ(c.pictures.width, 320);
  EXPECT_EQ(c.pictures.camera->azimuth, -90);
}

}  // namespace
}  // namespace jello
