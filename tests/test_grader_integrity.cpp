// The grader against a red team: each submission here is an attack that worked on an earlier
// grader (answers that compare as anything, output in the answers' way, the environment, the
// disks, archives, links, the report's formats, an interrupted grade). Each must now fail its
// checks, or be kept from what it reached for, while the correct solution beside it passes.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>
#include <thread>

#include "grader/build.h"
#include "grader/sandbox.h"
#include "grader_test_support.h"
#include "test_support.h"

namespace fs = std::filesystem;
using namespace jello::test;

namespace {

const std::string kEntry =
    "void computeAcceleration(struct world* jello, struct point a[8][8][8]) {";

// The correct solution with `hook` run after its own computeAcceleration (a and jello in scope)
// and `top` before everything: a submission folder `name` under `root`.
std::string attack(const std::string& root, const std::string& name, const std::string& hook,
                   const std::string& top = "") {
  std::string text = readText(kSubmissions + "/correct/physics.cpp");
  text.replace(text.find(kEntry), kEntry.size(),
               "static void realAcceleration(struct world* jello, struct point a[8][8][8]) {");
  text = "#include <float.h>\n#include <stdio.h>\n" + top + "\n" + text + "\n" + kEntry +
         "\n  realAcceleration(jello, a);\n" + hook + "\n}\n";
  fs::create_directories(root + "/" + name);
  writeText(root + "/" + name + "/physics.cpp", text);
  return root + "/" + name;
}

// Every file under `dir`, read whole, concatenated.
std::string everything(const std::string& dir) {
  std::string all;
  for (const auto& file : fs::recursive_directory_iterator(dir)) {
    if (file.is_regular_file()) all += readText(file.path().string());
  }
  return all;
}

}  // namespace

// Answers that every comparison lets through: NaN where the probe's scene is undamped (RK4's
// observed order then NaN), NaN at every point but the last in a field, and +-DBL_MAX in turn
// (every difference inf - inf = NaN) from a submission with no springs at all.
TEST(GraderIntegrity, AnswersThatCompareAsAnythingFail) {
  if (!haveSandbox()) GTEST_SKIP() << jello::grader::sandboxProblem();
  std::string root = makeTempDir(), report = root + "/report";
  std::vector<std::string> args = {"-o", report,     "--seed",
                                   "5",  "--checks", "structural,shear,bend,dampers,field,rk4"};
  args.push_back(attack(root, "nan-undamped",
                        "  if (jello->dElastic == 0) a[3][3][3].x = 0.0 / (jello->dElastic * 0);"));
  args.push_back(attack(root, "field-nan",
                        "  if (jello->resolution == 7)\n"
                        "    for (int q = 0; q < 511; q++) (&a[0][0][0])[q].y = 0.0 / 0.0;"));
  args.push_back(
      attack(root, "extremes",
             "  static int flip = 0;\n  char ahead[4096];\n"
             "  fread(ahead, 1, sizeof ahead, stdin); /* nothing to read ahead */\n"
             "  flip = !flip;\n"
             "  for (int q = 0; q < 512; q++) {\n"
             "    double v = flip ? DBL_MAX : -DBL_MAX;\n"
             "    (&a[0][0][0])[q].x = v; (&a[0][0][0])[q].y = v; (&a[0][0][0])[q].z = v;\n"
             "  }"));
  args.push_back(kSubmissions + "/correct");
  CommandResult r = grade(args);
  ASSERT_EQ(r.status, 0) << r.err;
  auto grades = readSummary(report);
  EXPECT_EQ(grades["nan-undamped"]["rk4"], "FAIL");
  EXPECT_EQ(grades["field-nan"]["field"], "FAIL");
  for (const char* check : {"structural", "shear", "bend", "dampers", "rk4"})
    EXPECT_EQ(grades["extremes"][check], "FAIL") << check;
  for (const char* check : {"structural", "shear", "bend", "dampers", "field", "rk4"})
    EXPECT_EQ(grades["correct"][check], "pass") << check;
  removeTree(root);
}

// What a submission prints (from a global constructor, before the grader's probe starts, in
// the answers' own format), reads (the environment: its own, and pid 1's, which is
// bubblewrap's) or writes (every file system it sees) changes nothing but its own answers.
TEST(GraderIntegrity, PrintingReadingTheEnvironmentAndFillingDisksChangeNoGrade) {
  if (!haveSandbox()) GTEST_SKIP() << jello::grader::sandboxProblem();
  std::string root = makeTempDir(), report = root + "/report";
  setenv("JELLO_GRADE_TEST_SECRET", "grader-secret-3141", 1);
  std::vector<std::string> args = {"-o", report, "--seed", "5", "--checks", "rest,rk4,speed"};
  args.push_back(attack(root, "prints", "",
                        "struct Chatter {\n  Chatter() {\n"
                        "    for (int q = 0; q < 2000; q++) printf(\"0 0 0\\n\");\n"
                        "    printf(\"ok\\n.\\n\");\n    fflush(stdout);\n  }\n} chatter;\n"));
  args.push_back(
      attack(root, "environment",
             "  for (const char* where : {\"/proc/1/environ\", \"/proc/self/environ\"}) {\n"
             "    FILE* f = fopen(where, \"r\");\n    char text[1 << 16] = {0};\n"
             "    if (!f) continue;\n    fread(text, 1, sizeof text - 1, f);\n    fclose(f);\n"
             "    for (size_t n = 0; n + 6 < sizeof text; n++)\n"
             "      if (memcmp(text + n, \"grader\", 6) == 0) a[1][2][3].x = 0.0 / 0.0;\n"
             "  }"));
  args.push_back(attack(
      root, "fills-disks",
      "  static int done = 0;\n  if (done++) return;\n  signal(SIGXFSZ, SIG_IGN);\n"
      "  static char block[1 << 20];\n"
      "  for (const char* where : {\"/\", \"/dev\", \"/dev/shm\", \"/tmp\", \"/work\", \"/proc\"}) "
      "{\n"
      "    long long total = 0;\n"
      "    for (int file = 0; file < 80 && total < (600LL << 20); file++) {\n"
      "      char name[64];\n      snprintf(name, sizeof name, \"%s/fill%d\", where, file);\n"
      "      FILE* f = fopen(name, \"w\");\n      if (!f) break;\n"
      "      for (int mb = 0; mb < 8; mb++) total += fwrite(block, 1, sizeof block, f);\n"
      "      fclose(f);\n    }\n"
      "    if (total > (300LL << 20)) a[0][0][0].x = 0.0 / 0.0; /* an unbounded disk */\n"
      "  }",
      "#include <signal.h>\n"));
  CommandResult r = grade(args);
  unsetenv("JELLO_GRADE_TEST_SECRET");
  ASSERT_EQ(r.status, 0) << r.err;
  auto grades = readSummary(report);
  for (const char* name : {"prints", "environment", "fills-disks"}) {
    EXPECT_EQ(grades[name]["rest"], "pass") << name;
    EXPECT_EQ(grades[name]["rk4"], "pass") << name;
  }
  EXPECT_EQ(everything(report).find("grader-secret-3141"), std::string::npos);
  removeTree(root);
}

// A compile-time loop (a constexpr evaluation of minutes) costs the submission's budget once,
// not once an attempt: with a budget of 3 s the first attempt is stopped at it and no other
// compiler runs; the build fails saying so.
TEST(GraderIntegrity, ACompileTimeLoopSpendsTheBudgetOfAllAttemptsOnce) {
  if (!haveSandbox()) GTEST_SKIP() << jello::grader::sandboxProblem();
  std::string root = makeTempDir();
  std::string bomb = attack(root, "bomb", "",
                            "constexpr long spin() {\n  long x = 0;\n"
                            "  for (long i = 0; i < 200000; ++i)\n"
                            "    for (long j = 0; j < 200000; ++j) x += (i ^ j) % 7;\n"
                            "  return x;\n}\nconstexpr long spun = spin();\n");
  const auto started = std::chrono::steady_clock::now();
  jello::grader::BuildResult build =
      jello::grader::buildSubmission({bomb, "bomb"}, root + "/probe", 3);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  EXPECT_FALSE(build.built);
  EXPECT_NE(build.log.find("the compiler used the submission's whole budget (3 s for all its "
                           "attempts): a compile-time loop?"),
            std::string::npos)
      << build.log.substr(0, 3000);
  std::size_t compilers = 0;
  for (std::size_t at = build.log.find("jello-grader: compiling root\n"); at != std::string::npos;
       at = build.log.find("jello-grader: compiling root\n", at + 1))
    ++compilers;
  EXPECT_EQ(compilers, 1u) << build.log.substr(0, 3000);
  EXPECT_LT(seconds, 60) << "a hang detector: the budget is 3 s of CPU";
  removeTree(root);
}

// What the compiler writes is bounded in total, not per file only: a program whose object and
// executable are 150 MB each (a data section of zeros) does not fit the sandbox's 256 MB /tmp,
// and the build fails saying so, on every attempt; nothing of it reaches the host's disk.
TEST(GraderIntegrity, ABuildWhoseOutputOverflowsTheSandboxFailsAtItsTotalBound) {
  if (!haveSandbox()) GTEST_SKIP() << jello::grader::sandboxProblem();
  std::string root = makeTempDir(), report = root + "/report";
  std::string big = attack(root, "big-output", "",
                           "asm(\".pushsection .data\\n.fill 150000000, 1, 0\\n.popsection\");\n");
  CommandResult r = grade({"-o", report, "--seed", "5", "--checks", "rest", big});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(readSummary(report)["big-output"]["builds"], "FAIL");
  std::string log = readText(report + "/big-output/build.log");
  EXPECT_NE(log.find("No space left on device"), std::string::npos) << log.substr(0, 2000);
  EXPECT_LT(fs::file_size(report + "/big-output/build.log"), 1u << 20);
  removeTree(root);
}

// Archives and links: a .tar.gz of hard links that unpacks to 80 MB from a few kB is refused;
// a submission named through a symbolic link is refused by name; a file the submission's owner
// cannot read, hard-linked into the folder, is not read when the grader runs as root.
TEST(GraderIntegrity, ArchivesAndLinksReachNothingBeyondTheStudentsOwnFiles) {
  if (!haveSandbox()) GTEST_SKIP() << jello::grader::sandboxProblem();
  std::string root = makeTempDir(), report = root + "/report";
  fs::create_directories(root + "/bomb/links");
  fs::copy_file(kSubmissions + "/correct/physics.cpp", root + "/bomb/physics.cpp");
  writeText(root + "/bomb/links/zeros.h", std::string(2 << 20, ' '));
  for (int n = 0; n < 40; ++n)
    fs::create_hard_link(root + "/bomb/links/zeros.h",
                         root + "/bomb/links/z" + std::to_string(n) + ".h");
  ProgramSetup inRoot;
  inRoot.cwd = root;
  ASSERT_EQ(runProgram({"/bin/tar", "-czf", root + "/bomb.tar.gz", "bomb"}, inRoot).status, 0);
  EXPECT_LT(fs::file_size(root + "/bomb.tar.gz"), 64u << 10);
  fs::create_directory_symlink(kSubmissions + "/correct", root + "/alias");
  CommandResult link = grade({"-o", report, root + "/alias"});
  EXPECT_EQ(link.status, 2);
  EXPECT_NE(link.err.find("alias: a symbolic link"), std::string::npos) << link.err;
  std::vector<std::string> args = {
      "-o", report, "--seed", "5", "--checks", "rest", root + "/bomb.tar.gz"};
  bool asRoot = geteuid() == 0;
  std::string secret = root + "/root-only.txt";
  if (asRoot) {
    writeText(secret, "ROOT-ONLY-SECRET\n");
    chmod(secret.c_str(), 0600);
    std::string student = attack(root, "student", "", "#include \"secret.h\"\n");
    fs::create_hard_link(secret, student + "/secret.h");
    for (const auto& p : {root, student}) chmod(p.c_str(), 0755);
    ASSERT_EQ(chown(student.c_str(), 65534, 65534), 0);
    ASSERT_EQ(chown((student + "/physics.cpp").c_str(), 65534, 65534), 0);
    args.push_back(student);
  }
  CommandResult r = grade(args);
  ASSERT_EQ(r.status, 0) << r.err;
  auto grades = readSummary(report);
  EXPECT_EQ(grades["bomb"]["builds"], "FAIL");
  EXPECT_NE(readText(report + "/bomb/report.md").find("hard links counted"), std::string::npos);
  // A submission's folder in the report that is a link (to a folder of someone else's files) is
  // refused by name before anything is written through it.
  fs::create_directories(root + "/elsewhere");
  writeText(root + "/elsewhere/report.md", "precious\n");
  fs::remove_all(report + "/bomb");
  fs::create_directory_symlink(root + "/elsewhere", report + "/bomb");
  CommandResult through =
      grade({"-o", report, "--overwrite", "--checks", "rest", root + "/bomb.tar.gz"});
  EXPECT_EQ(through.status, 2);
  EXPECT_NE(through.err.find(report + "/bomb: not a folder (a symbolic link"), std::string::npos)
      << through.err;
  EXPECT_EQ(readText(root + "/elsewhere/report.md"), "precious\n");
  fs::remove(report + "/bomb");
  // A report file that may not be replaced is named.
  const std::string fresh = root + "/fresh";
  fs::create_directories(fresh + "/other");
  writeText(fresh + "/other/report.md", "mine\n");
  fs::copy(kSubmissions + "/correct", root + "/other");
  CommandResult named = grade({"-o", fresh, "--checks", "rest", root + "/other"});
  EXPECT_EQ(named.status, 2);
  EXPECT_NE(named.err.find(fresh + "/other/report.md: already exists"), std::string::npos)
      << named.err;
  if (asRoot) {
    EXPECT_EQ(grades["student"]["builds"], "FAIL");  // secret.h was not copied
    EXPECT_EQ(everything(report).find("ROOT-ONLY-SECRET"), std::string::npos);
  }
  removeTree(root);
}

// A compiler's message quotes the student's file: U+FFFE (which XML 1.0 forbids), terminal
// escapes and HTML reach neither junit.xml, report.md, the terminal, nor CTest's output raw.
TEST(GraderIntegrity, AStudentsTextIsEscapedInEveryReportAndOnTheTerminal) {
  if (!haveSandbox()) GTEST_SKIP() << jello::grader::sandboxProblem();
  std::string root = makeTempDir(), report = root + "/report";
  fs::create_directories(root + "/weird");
  writeText(root + "/weird/physics.cpp",
            "#error \"\xEF\xBF\xBE \x1b[31mred\x1b[0m <script>alert(1)</script> `x` *y*\"\n");
  CommandResult r = grade({"-o", report, "--checks", "rest", root + "/weird"});
  ASSERT_EQ(r.status, 0) << r.err;
  std::string junit = readText(report + "/junit.xml"), md = readText(report + "/weird/report.md");
  for (const std::string& text : {junit, md, r.err, r.out})
    EXPECT_EQ(text.find('\x1b'), std::string::npos);
  EXPECT_EQ(junit.find("\xEF\xBF\xBE"), std::string::npos);  // ill-formed XML 1.0
  EXPECT_NE(junit.find("\\uFFFE"), std::string::npos) << junit;
  EXPECT_EQ(everything(report).find('\x1b'), std::string::npos);  // build.log too
  EXPECT_EQ(md.find("<script>"), std::string::npos) << md;
  EXPECT_NE(md.find("&lt;script&gt;"), std::string::npos) << md;
  // The CTest route prints the same line, escaped too.
  std::string ctest = root + "/ctest";
  ASSERT_EQ(grade({"--ctest", "-o", ctest, "--checks", "rest", root + "/weird"}).status, 0);
  CommandResult one = grade({"--one", "builds", "--item", "0", ctest});
  EXPECT_EQ(one.status, 1);
  EXPECT_EQ(one.out.find('\x1b'), std::string::npos) << one.out;
  EXPECT_NE(one.out.find("\\x1B[31mred"), std::string::npos) << one.out;
  removeTree(root);
}

// Stopped by SIGINT while a submission runs, the grader leaves none of its scratch folders
// (students' sources, their programs) and no empty report folder behind; while it runs, no other
// user can enter a scratch folder.
TEST(GraderIntegrity, AnInterruptedGradeLeavesNoScratchFolderAndOthersCannotEnterOne) {
  if (!haveSandbox()) GTEST_SKIP() << jello::grader::sandboxProblem();
  std::string root = makeTempDir(), tmp = root + "/tmp", report = root + "/report";
  fs::create_directories(tmp);
  for (const auto& folder : {root, tmp}) chmod(folder.c_str(), 0755);  // as /tmp: others pass
  {
    setenv("TMPDIR", tmp.c_str(), 1);
    jello::grader::Scratch scratch;
    unsetenv("TMPDIR");
    struct stat info;
    ASSERT_EQ(stat(scratch.path().c_str(), &info), 0);
    EXPECT_EQ(info.st_mode & 07, 0u) << std::oct << info.st_mode;
  }
  EXPECT_TRUE(fs::is_empty(tmp));
  pid_t child = fork();
  if (child == 0) {
    setenv("TMPDIR", tmp.c_str(), 1);
    int null = open((root + "/grade.out").c_str(), O_WRONLY | O_CREAT, 0644);
    dup2(null, 1);
    dup2(null, 2);
    execl(JELLO_GRADE, JELLO_GRADE, "-o", report.c_str(), "--checks", "rest,structural",
          (kSubmissions + "/never-returns").c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  // Until the submission is built and its probe runs (its program is in a scratch folder).
  bool running = false;
  for (int wait = 0; wait < 600 && !running; ++wait) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    std::error_code error;
    for (const auto& entry : fs::recursive_directory_iterator(tmp, error)) {
      if (entry.path().filename() == "probe" && entry.path().parent_path().filename() != "out")
        running = true;
    }
  }
  EXPECT_TRUE(running);
  kill(child, SIGINT);
  int status = 0;
  waitpid(child, &status, 0);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGINT)
      << status << readText(root + "/grade.out");
  EXPECT_TRUE(fs::is_empty(tmp)) << everything(tmp).size();
  EXPECT_FALSE(fs::exists(report));
  removeTree(root);
}

// A program that prints more than the sandbox keeps is read to its end and not killed: what is
// beyond the cap is counted and dropped (a right program that prints a line a point for 2000
// steps passes); only answers beyond their cap end a run.
TEST(GraderIntegrity, OutputBeyondTheCapIsDiscardedNotAKill) {
  if (!haveSandbox()) GTEST_SKIP() << jello::grader::sandboxProblem();
  jello::grader::Scratch scratch;
  jello::grader::SandboxJob job;
  job.argv = {"/bin/sh", "-c", "head -c 3000000 /dev/zero; head -c 500000 /dev/zero >&2; exit 7"};
  job.hostDir = scratch.path();
  job.limits.outputBytes = 1 << 20;
  jello::grader::SandboxResult result = jello::grader::runSandboxed(job);
  EXPECT_TRUE(result.exitedWith(7)) << result.describe();
  EXPECT_FALSE(result.outputCut);
  EXPECT_EQ(result.output.size(), 1u << 20);
  EXPECT_EQ(result.outputDiscarded, 3000000u - (1u << 20) + 500000u - (64u << 10));
}

// In --ctest mode each test reads its submission back from grading.txt by number: a class
// entry whose name holds a line break is still one submission, graded with its own code (a
// wrong one fails, the right one beside it passes).
TEST(GraderIntegrity, ACTestListBindsANameWithALineBreakToItsOwnSubmission) {
  if (!haveSandbox()) GTEST_SKIP() << jello::grader::sandboxProblem();
  std::string root = makeTempDir(), cls = root + "/class", ctest = root + "/ctest";
  fs::create_directories(cls);
  fs::copy(kSubmissions + "/bend-rest", cls + "/a\nb");
  fs::copy(kSubmissions + "/correct", cls + "/c");
  ASSERT_EQ(grade({"--ctest", "-o", ctest, "--checks", "bend", cls}).status, 0);
  EXPECT_EQ(grade({"--one", "builds", "--item", "0", ctest}).status, 0);
  CommandResult wrong = grade({"--one", "bend", "--item", "0", ctest});
  EXPECT_EQ(wrong.status, 1) << wrong.out;
  EXPECT_NE(wrong.out.find("rest length"), std::string::npos) << wrong.out;
  EXPECT_EQ(grade({"--one", "builds", "--item", "1", ctest}).status, 0);
  CommandResult right = grade({"--one", "bend", "--item", "1", ctest});
  EXPECT_EQ(right.status, 0) << right.out;
  removeTree(root);
}

// A regrade removes the reports of the submissions graded before and not now, and nothing else:
// not through a link planted where a submission's report folder was, nor for a name a planted
// mark lists.
TEST(GraderIntegrity, ARegradeRemovesNothingThroughALinkOrAPlantedMark) {
  if (!haveSandbox()) GTEST_SKIP() << jello::grader::sandboxProblem();
  std::string root = makeTempDir(), report = root + "/report", outside = root + "/outside";
  ASSERT_EQ(grade({"-o", report, "--seed", "5", "--checks", "rest", kSubmissions + "/correct",
                   kSubmissions + "/bend-rest"})
                .status,
            0);
  fs::create_directories(outside);
  writeText(outside + "/report.md", "someone else's\n");
  writeText(outside + "/build.log", "someone else's\n");
  fs::remove_all(report + "/bend-rest");
  fs::create_directory_symlink(outside, report + "/bend-rest");
  writeText(report + "/.jello-grade", readText(report + "/.jello-grade") + "../outside\n");
  CommandResult r = grade(
      {"-o", report, "--overwrite", "--seed", "5", "--checks", "rest", kSubmissions + "/correct"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(outside + "/report.md"));
  EXPECT_TRUE(fs::exists(outside + "/build.log"));
  EXPECT_TRUE(fs::exists(report + "/correct/report.md"));
  removeTree(root);
}

// The lenient build serves a library the hand-in names but does not carry from the system's copy
// through a link in its scratch folder: an include through that link (its own file in another
// case, "x/EVIL.h" for x/evil.h) is never written through it into the system's folder.
TEST(GraderIntegrity, NoIncludeIsWrittenThroughTheLinkToASystemLibrary) {
  if (!haveSandbox()) GTEST_SKIP() << jello::grader::sandboxProblem();
  if (!fs::is_directory("/usr/include/eigen3")) GTEST_SKIP() << "no system Eigen";
  const std::string planted = "/usr/include/eigen3/JelloGraderPlanted.h";
  std::string root = makeTempDir(), hand = root + "/hand";
  fs::copy(kSubmissions + "/correct", hand, fs::copy_options::recursive);
  fs::create_directories(hand + "/x");
  writeText(hand + "/x/jellograderplanted.h", "#define PLANTED 1\n");
  std::string physics = readText(hand + "/physics.cpp");
  writeText(hand + "/physics.cpp",
            "#include \"x/Eigen/Dense\"\n#include \"x/JelloGraderPlanted.h\"\n" + physics);
  CommandResult r = grade({"-o", root + "/report", "--seed", "5", "--checks", "rest", hand});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_FALSE(fs::exists(planted));
  fs::remove(planted);  // were it written, it goes again
  removeTree(root);
}
