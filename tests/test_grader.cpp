// The grader (./grade): every mutant of the correct course-API solution gets exactly its
// diagnosis, hostile submissions are contained, and CTest runs the checks one by one.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "grader/checkkit.h"
#include "grader/checks.h"
#include "grader/graderfiles.h"
#include "grader/sandbox.h"
#include "grader_test_support.h"
#include "test_support.h"

namespace fs = std::filesystem;
using namespace jello::test;

namespace {

const std::string kSeed = "5";

// mutants.txt's expectations: the checks each mutant must fail (or be near, marked ~).
std::map<std::string, std::set<std::string>> expectedFailures() {
  std::istringstream table(readText(std::string(JELLO_TEST_DATA) + "/mutants.txt"));
  std::map<std::string, std::set<std::string>> expected;
  for (std::string line; std::getline(table, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::string name = line.substr(0, line.find('|'));
    std::string fails =
        line.substr(name.size() + 1, line.find('|', name.size() + 1) - name.size() - 1);
    std::istringstream words(fails);
    for (std::string w; words >> w;) expected[name].insert(w[0] == '~' ? w.substr(1) : w);
    expected[name];
  }
  return expected;
}

void expectGrades(const std::string& dir, const std::vector<std::string>& names) {
  auto grades = readSummary(dir);
  auto expected = expectedFailures();
  for (const auto& name : names) {
    SCOPED_TRACE(name);
    ASSERT_TRUE(grades.count(name));
    for (const auto& [check, got] : grades[name]) {  // the checks graded
      bool bad = got == "FAIL" || got == "near";
      EXPECT_EQ(bad, expected[name].count(check) == 1) << check << ": " << got;
    }
  }
}

}  // namespace

TEST(Grader, MutantsAreTheCorrectSolutionWithTheTableReplacements) {
  std::string out = makeTempDir();
  CommandResult r = runProgram({std::string(JELLO_SOURCE_DIR) + "/scripts/make-mutants", out});
  ASSERT_EQ(r.status, 0) << r.err;
  int mutants = 0;
  for (const auto& entry : fs::directory_iterator(out)) {
    SCOPED_TRACE(entry.path().filename().string());
    EXPECT_EQ(readText(entry.path().string() + "/physics.cpp"),
              readText(kSubmissions + "/" + entry.path().filename().string() + "/physics.cpp"));
    EXPECT_NE(readText(entry.path().string() + "/physics.cpp"),
              readText(kSubmissions + "/correct/physics.cpp"));
    ++mutants;
  }
  EXPECT_EQ(mutants, static_cast<int>(expectedFailures().size()));
  EXPECT_GE(mutants, 14);
  removeTree(out);
}

// Every fixture, every check but the agreement (the next test's, on a few: it is half the time).
TEST(Grader, PassesTheCorrectSolutionAndGivesEveryMutantExactlyItsDiagnosisInWords) {
  if (!haveSandbox()) GTEST_SKIP() << jello::grader::sandboxProblem();
  std::string dir = makeTempDir() + "/report";
  std::vector<std::string> args = {
      "-o",       dir,
      "--seed",   kSeed,
      "--checks", "rest,structural,shear,bend,dampers,walls,plane,field,euler,rk4,robust,speed"};
  std::vector<std::string> names = {"correct"};
  for (const auto& [name, fails] : expectedFailures()) names.push_back(name);
  for (const auto& name : names) args.push_back(kSubmissions + "/" + name);
  CommandResult r = grade(args);
  ASSERT_EQ(r.status, 0) << r.err;
  expectGrades(dir, names);
  // The words: the term, the stage, the measured value against the expected.
  std::string summary = rendered(readText(dir + "/summary.md"));
  for (const char* line : {
           "bend-rest/bend (FAIL): rest length 0.142857143 m measured on the bend spring",
           "rk4-stage3/rk4 (FAIL): RK4's third stage (k3) is evaluated at state + dt/2*k1",
           "rk4-quarter/rk4 (FAIL): RK4's third stage (k3) is evaluated at state + dt/4*k2",
           "field-order/field (FAIL): the field's nodes are read in the wrong order",
           "plane-side/plane (FAIL): plane: pushes points on its positive side",
           "walls-some/walls (FAIL): walls x = +2, y = +2, z = +2: no force on points across it",
           "damping-sign/dampers (FAIL): damping sign flipped",
           "damping-whole/dampers (FAIL): the dampers act on the whole relative velocity",
           "euler-new-v/euler (FAIL): Euler moves p with the new velocity",
           "shear-missing/shear (FAIL): no shear springs",
           "rounded-rest/structural (near): rest length 0.142857 m measured",
           "no-compile/builds (FAIL): physics.cpp:",
           "segfault/rest (FAIL): computeAcceleration was killed by signal 11",
           "never-returns/rest (FAIL): computeAcceleration did not return within 5 s: an endless "
           "loop?",
           "never-returns/structural (FAIL): not run: the submission did not return in the rest "
           "check",
           "dampers-some/dampers (FAIL): no damping on the spring at offset (1,1,0)",
           "rk4-global/rk4 (FAIL): every stage of RK4 gets the accelerations of the start",
           "nan-inside/walls (FAIL): all six walls: NaN or infinity in the accelerations",
           "nan-inside/euler (FAIL): computeAcceleration gave NaN or infinity",
       }) {
    EXPECT_NE(summary.find(line), std::string::npos) << line;
  }
  std::string junit = readText(dir + "/junit.xml");
  EXPECT_NE(junit.find("<testcase classname=\"bend-rest\" name=\"bend\"><failure message=\"rest"),
            std::string::npos);
  EXPECT_NE(junit.find("<testcase classname=\"correct\" name=\"rk4\"><system-out>pass: classic"),
            std::string::npos);
  // Regrading one student into the class's report folder would drop the others from its
  // summary: refused in words, nothing changed.
  CommandResult one = grade({"-o", dir, "--checks", "rest", kSubmissions + "/bend-rest"});
  EXPECT_EQ(one.status, 2) << one.err;
  EXPECT_NE(one.err.find("which this grade would drop from its summary"), std::string::npos)
      << one.err;
  EXPECT_TRUE(fs::exists(dir + "/correct/report.md"));
  // With --overwrite the grade replaces the grader's own files there: the submissions graded
  // then and not now are gone from it. Without --seed it grades on the folder's seed.
  CommandResult again =
      grade({"-o", dir, "--overwrite", "--checks", "rest", kSubmissions + "/bend-rest"});
  EXPECT_EQ(again.status, 0) << again.err;
  EXPECT_NE(again.err.find("unseen worlds from seed " + kSeed), std::string::npos) << again.err;
  EXPECT_TRUE(fs::exists(dir + "/bend-rest/report.md"));
  EXPECT_FALSE(fs::exists(dir + "/correct"));
  EXPECT_EQ(readSummary(dir).size(), 1u);
  // A folder the grader did not write is refused.
  std::string other = fs::path(dir).parent_path().string() + "/other";
  fs::create_directories(other);
  writeText(other + "/summary.md", "mine\n");
  CommandResult refused = grade({"-o", other, "--seed", kSeed, kSubmissions + "/bend-rest"});
  EXPECT_EQ(refused.status, 2);
  EXPECT_NE(refused.err.find("already exists"), std::string::npos) << refused.err;
  EXPECT_EQ(readText(other + "/summary.md"), "mine\n");
  removeTree(fs::path(dir).parent_path().string());
}

// The whole runs: right, near for rounded constants, wrong for a wrong stage; and the worlds'
// tolerances as the report states them.
TEST(Grader, AgreesWithTheCorrectSolutionWithinEachWorldsOwnTolerance) {
  if (!haveSandbox()) GTEST_SKIP() << jello::grader::sandboxProblem();
  std::string dir = makeTempDir() + "/report";
  std::vector<std::string> names = {"correct", "rounded-rest", "rk4-stage3", "euler-new-v"};
  std::vector<std::string> args = {"-o", dir, "--seed", kSeed, "--checks", "agreement"};
  for (const auto& name : names) args.push_back(kSubmissions + "/" + name);
  CommandResult r = grade(args);
  ASSERT_EQ(r.status, 0) << r.err;
  expectGrades(dir, names);
  std::string report = readText(dir + "/correct/report.md");
  for (const char* world : {"rotate.w", "jello.w", "moveLeft.w", "skewedCorner.w", "gravity.w",
                            "unseen RK4 world (seed 5)", "unseen Euler world (seed 5)"}) {
    EXPECT_NE(report.find(std::string("agreement: ") + world + ": "), std::string::npos) << world;
  }
  removeTree(fs::path(dir).parent_path().string());
}

// Each hostile submission is the correct solution with an attack at the top of
// computeAcceleration; it is graded beside the correct one, whose grades must not change.
TEST(Grader, ContainsHostileSubmissionsAndHarmsNothingElse) {
  if (!haveSandbox()) GTEST_SKIP() << jello::grader::sandboxProblem();
  std::string root = makeTempDir();
  chmod(root.c_str(), 0755);  // readable by anyone: only the sandbox keeps them out
  std::string victim = root + "/victim.txt", secret = root + "/secret.txt";
  std::string report = root + "/report";
  writeText(victim, "untouched\n");
  chmod(victim.c_str(), 0666);
  writeText(secret, "TOP-SECRET-ANSWERS\n");
  std::string correct = readText(kSubmissions + "/correct/physics.cpp");
  const std::string entry =
      "void computeAcceleration(struct world* jello, struct point a[8][8][8]) {";
  std::map<std::string, std::string> hostile = {
      {"forks", "  for (;;) fork();"},
      {"allocates",
       "  char* big = (char*)malloc(100000000000ull); memset(big, 1, 100000000000ull);"},
      {"writes", "  FILE* victim = fopen(\"" + victim +
                     "\", \"w\");\n"
                     "  if (victim) { fputs(\"PWNED\", victim); fclose(victim); }\n"
                     "  FILE* summary = fopen(\"" +
                     report +
                     "/summary.md\", \"w\");\n"
                     "  if (summary) fclose(summary);"},
      {"reads", "  if (fopen(\"" + secret + "\", \"r\")) abort();"},
  };
  std::vector<std::string> args = {"-o", report, "--seed", kSeed, "--checks", "rest,robust"};
  for (const auto& [name, code] : hostile) {
    std::string text = correct;
    text.replace(text.find(entry), entry.size(), entry + "\n" + code);
    fs::create_directories(root + "/" + name);
    writeText(root + "/" + name + "/physics.cpp", "#include <unistd.h>\n" + text);
    args.push_back(root + "/" + name);
  }
  fs::create_directories(root + "/includes");
  writeText(root + "/includes/physics.cpp", "#include \"" + secret + "\"\n");
  args.push_back(root + "/includes");
  args.push_back(kSubmissions + "/correct");
  CommandResult r = grade(args);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(readText(victim), "untouched\n");
  auto grades = readSummary(report);
  for (std::string check : {"builds", "rest", "robust"}) {
    EXPECT_EQ(grades["correct"][check], "pass") << check;  // graded beside them, unharmed
    EXPECT_EQ(grades["reads"][check], "pass") << check;    // it could not open the secret
    EXPECT_EQ(grades["writes"][check], "pass") << check;   // nor the files, to write
    if (check != "builds") {
      // robust is beyond the course's domain: not graded without --strict.
      EXPECT_EQ(grades["forks"][check], check == "robust" ? "info" : "FAIL") << check;
      EXPECT_EQ(grades["allocates"][check], check == "robust" ? "info" : "FAIL") << check;
    }
  }
  EXPECT_EQ(grades["includes"]["builds"], "FAIL");
  for (const auto& file : fs::recursive_directory_iterator(report)) {
    if (file.is_regular_file()) {
      EXPECT_EQ(readText(file.path()).find("TOP-SECRET"), std::string::npos) << file.path();
    }
  }
  removeTree(root);
}

TEST(Grader, MakesACTestTestForEveryCheck) {
  if (!haveSandbox()) GTEST_SKIP() << jello::grader::sandboxProblem();
  std::string dir = makeTempDir() + "/ctest";
  CommandResult r = grade({"--ctest", "-o", dir, "--seed", kSeed, kSubmissions + "/correct",
                           kSubmissions + "/walls-some"});
  ASSERT_EQ(r.status, 0) << r.err;
  ProgramSetup inDir;
  inDir.cwd = dir;
  CommandResult list = runProgram({CTEST_COMMAND, "-N"}, inDir);
  EXPECT_NE(list.out.find("Total Tests: " + std::to_string(2 * jello::grader::checkTable().size())),
            std::string::npos)
      << list.out;
  // One student's one check: its build comes first, as a fixture.
  CommandResult walls = runProgram({CTEST_COMMAND, "-R", "walls-some/walls", "--output-on-failure",
                                    "--output-junit", "junit.xml"},
                                   inDir);
  EXPECT_NE(walls.status, 0);
  EXPECT_NE(walls.out.find("walls-some/builds"), std::string::npos) << walls.out;
  EXPECT_NE(walls.out.find("walls x = +2, y = +2, z = +2: no force on points across it"),
            std::string::npos)
      << walls.out;
  CommandResult rest = runProgram({CTEST_COMMAND, "-R", "correct/rest"}, inDir);
  EXPECT_EQ(rest.status, 0) << rest.out;
  EXPECT_NE(readText(dir + "/junit.xml").find("walls-some/walls"), std::string::npos);
  removeTree(fs::path(dir).parent_path().string());
}

TEST(Grader, BuildsWithItsOwnHeadersWhenTheyServeAndTheCourseApiWhenNot) {
  if (!haveSandbox()) GTEST_SKIP() << jello::grader::sandboxProblem();
  std::string root = makeTempDir(), report = root + "/report";
  std::string physics = readText(kSubmissions + "/correct/physics.cpp");
  // A student's jello.h as the course's: GL first, then the course's layout and macros.
  for (const char* name : {"glut", "missing-pic"}) {
    fs::create_directories(root + "/" + name);
    writeText(root + "/" + name + "/physics.cpp", physics);
    writeText(root + "/" + name + "/physics.h", jello::grader::graderFile("course/physics.h"));
    std::string first =
        std::string(name) == "glut" ? "#include <GL/glut.h>\n" : "#include \"pic.h\"\n";
    writeText(root + "/" + name + "/jello.h", first + jello::grader::graderFile("course/jello.h"));
  }
  // File names the compiler must not take for options, and a file that would make a pattern
  // search for main( recurse 200,000 times.
  fs::create_directories(root + "/odd-names");
  writeText(root + "/odd-names/physics.cpp", physics);
  writeText(root + "/odd-names/@options.cpp", "-wrapper /bin/sh,-c,touch\\ /out/pwned\n");
  writeText(root + "/odd-names/-o.cpp", "int notCompiled = ;\n");
  writeText(root + "/odd-names/blank.cpp", "/* main" + std::string(200000, ' ') + "*/\n");
  // The correct folder as a .tar.gz and a .zip, inside a folder of its own as students pack it.
  fs::create_directories(root + "/pack/alice");
  fs::copy_file(kSubmissions + "/correct/physics.cpp", root + "/pack/alice/physics.cpp");
  ProgramSetup inPack;
  inPack.cwd = root + "/pack";
  ASSERT_EQ(runProgram({"/bin/tar", "-czf", root + "/alice.tar.gz", "alice"}, inPack).status, 0);
  bool zip = fs::exists("/usr/bin/zip");
  if (zip) {
    ASSERT_EQ(runProgram({"/usr/bin/zip", "-qr", root + "/bob.zip", "alice"}, inPack).status, 0);
  }
  std::vector<std::string> args = {"-o",
                                   report,
                                   "--seed",
                                   kSeed,
                                   "--checks",
                                   "rest",
                                   root + "/glut",
                                   root + "/odd-names",
                                   root + "/missing-pic",
                                   root + "/alice.tar.gz"};
  if (zip) args.push_back(root + "/bob.zip");
  CommandResult r = grade(args);
  ASSERT_EQ(r.status, 0) << r.err;
  // GL and the picture library are stood in for, whether or not the machine has them.
  for (const char* name : {"glut", "missing-pic"}) {
    EXPECT_NE(readText(report + "/" + name + "/report.md")
                  .find("built from physics.cpp alone, its own headers"),
              std::string::npos)
        << name;
  }
  std::string odd = readText(report + "/odd-names/report.md");
  EXPECT_NE(odd.find("@options.cpp: left out"), std::string::npos) << odd;
  EXPECT_NE(odd.find("-o.cpp: left out"), std::string::npos) << odd;
  auto grades = readSummary(report);
  for (const char* name : {"glut", "missing-pic", "odd-names", "alice", "bob"}) {
    if (std::string(name) == "bob" && !zip) continue;
    EXPECT_EQ(grades[name]["builds"], "pass") << name;
    EXPECT_EQ(grades[name]["rest"], "pass") << name;
  }
  removeTree(root);
}

// The agreement's tolerance comes from the world: on rotate.w a one-ulp nudge stays below
// 1e-11 m, so the floor (1e-9 m) holds to step 2000; thrown fast with little damping, the cube
// of jello.w amplifies the nudge to about 1e-7 m by step 2000 (1e-5 m as a tolerance), so it is
// judged at an earlier step, where the tolerance is still 1e-6 m or less.
TEST(Grader, TakesEachWorldsToleranceFromItsOwnSensitivity) {
  using jello::grader::agreementReference;
  auto calm = agreementReference(jello::readWorldFile(JELLO_SOURCE_DIR "/world/rotate.w"));
  ASSERT_EQ(calm.tolerance.size(), 20u);
  EXPECT_EQ(calm.judged, 19u);
  EXPECT_EQ(calm.tolerance.back(), 1e-9);
  std::string dir = makeTempDir(), fast = dir + "/fast.w";
  ASSERT_EQ(runProgram({JELLO_CREATE_WORLD, "--preset", "jello", "--velocity", "30", "-20", "25",
                        "--d-elastic", "0.05", "--d-collision", "0.05", "-o", fast})
                .status,
            0);
  auto wild = agreementReference(jello::readWorldFile(fast));
  ASSERT_EQ(wild.tolerance.size(), 20u);
  EXPECT_GT(wild.tolerance.back(), 1e-6);
  EXPECT_LT(wild.judged, 19u);
  EXPECT_GT(wild.judged, 3u);
  EXPECT_LE(wild.tolerance[wild.judged], 1e-6);
  EXPECT_GT(wild.tolerance[wild.judged + 1], 1e-6);
  removeTree(dir);
}

// A class graded in three parts (grade --shard K/3, each into a folder of its own) and joined
// (grade --merge) gives the summary.csv and junit.xml of one grade of the whole class; every
// submission is in exactly one part, and always the same one.
TEST(Grader, AClassGradedInThreePartsAndMergedIsTheOneRunsReport) {
  if (!haveSandbox()) GTEST_SKIP() << jello::grader::sandboxProblem();
  std::string root = makeTempDir(), cls = root + "/class";
  fs::create_directories(cls);
  for (const char* name : {"correct", "bend-rest", "walls-some", "no-compile", "rk4-stage3",
                           "field-order", "damping-sign"})
    fs::copy(kSubmissions + "/" + name, cls + "/" + name, fs::copy_options::recursive);
  std::vector<std::string> common = {"--seed", kSeed, "--checks", "rest,bend,walls,field,rk4"};
  auto args = [&](std::vector<std::string> more) {
    more.insert(more.end(), common.begin(), common.end());
    more.push_back(cls);
    return more;
  };
  ASSERT_EQ(grade(args({"-o", root + "/whole"})).status, 0);
  std::vector<std::string> merge = {"--merge", root + "/merged"};
  std::size_t graded = 0;
  for (int part = 1; part <= 3; ++part) {
    std::string dir = root + "/part" + std::to_string(part);
    CommandResult r = grade(args({"-o", dir, "--shard", std::to_string(part) + "/3"}));
    ASSERT_EQ(r.status, 0) << r.err;
    if (fs::exists(dir + "/summary.csv")) graded += readSummary(dir).size();  // else empty
    merge.push_back(dir);
  }
  EXPECT_EQ(graded, 7u);
  CommandResult merged = grade(merge);
  ASSERT_EQ(merged.status, 0) << merged.err;
  EXPECT_EQ(readText(root + "/merged/summary.csv"), readText(root + "/whole/summary.csv"));
  EXPECT_EQ(readText(root + "/merged/junit.xml"), readText(root + "/whole/junit.xml"));
  EXPECT_EQ(readText(root + "/merged/bend-rest/build.log"),
            readText(root + "/whole/bend-rest/build.log"));
  // Parts graded on other worlds are not joined.
  CommandResult other = grade({"-o", root + "/other", "--seed", "6", "--shard", "1/1", "--checks",
                               "rest", kSubmissions + "/correct"});
  ASSERT_EQ(other.status, 0) << other.err;
  CommandResult refused = grade({"--merge", root + "/mixed", root + "/whole", root + "/other"});
  EXPECT_EQ(refused.status, 2);
  EXPECT_NE(refused.err.find("another --seed"), std::string::npos) << refused.err;
  removeTree(root);
}
