// The grader on whole programs laid out as students keep them: tests/data/students/base (the
// course's jello.h with its extern int pause, the spring list built in jello.cpp's main, the
// viewer, input and picture code) and its shapes (scripts/make-students), each graded and
// checked against its expect.txt.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <sstream>

#include "grader/sandbox.h"
#include "grader_test_support.h"
#include "test_support.h"

namespace fs = std::filesystem;
using namespace jello::test;

namespace {

const std::string kStudents = std::string(JELLO_TEST_DATA) + "/students";

// report.md's rows as check -> (grade, what it found), and its notes, the markdown undone
// enough to compare words (the escapes before markdown's characters dropped).
struct Report {
  std::map<std::string, std::pair<std::string, std::string>> rows;
  std::string notes;
};

Report readReport(const std::string& path) {
  Report report;
  std::istringstream lines(readText(path));
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("- ", 0) == 0) report.notes += rendered(line) + "\n";
    if (line.rfind("| ", 0) != 0 || line.rfind("| check", 0) == 0) continue;
    std::vector<std::string> cells;
    std::string cell;
    for (std::size_t n = 1; n < line.size(); ++n) {
      if (line[n] == '|' && line[n - 1] != '\\') {
        cells.push_back(cell);
        cell.clear();
      } else {
        cell += line[n];
      }
    }
    if (cells.size() < 3) continue;
    auto trim = [](std::string t) {
      t.erase(0, t.find_first_not_of(' '));
      t.erase(t.find_last_not_of(' ') + 1);
      return t;
    };
    report.rows[trim(cells[0])] = {trim(cells[1]), rendered(trim(cells[2]))};
  }
  return report;
}

// Checks one graded shape against its expect.txt: "CHECK GRADE [WORDS]" (the check has that
// grade and its line holds WORDS), "builds note WORDS" (the build's notes hold WORDS), "* pass"
// (every other check graded passes, or is info).
void expectShape(const std::string& shape, const Report& report) {
  SCOPED_TRACE(shape);
  // The base program itself ("course") builds whole and passes everything.
  std::istringstream expect(shape == "course" ? "builds pass its whole program\n* pass\n"
                                              : readText(kStudents + "/" + shape + "/expect.txt"));
  std::map<std::string, bool> named;
  bool restPass = false;
  for (std::string line; std::getline(expect, line);) {
    std::istringstream words(line);
    std::string check, grade, text;
    words >> check >> grade;
    std::getline(words, text);
    text.erase(0, text.find_first_not_of(' '));
    if (check == "*") {
      restPass = true;
      continue;
    }
    if (!report.rows.count(check)) continue;  // not graded in this run
    if (grade == "note") {
      EXPECT_NE(report.notes.find(text), std::string::npos) << check << " note: " << text;
      continue;
    }
    named[check] = true;
    EXPECT_EQ(report.rows.at(check).first, grade) << check << ": " << report.rows.at(check).second;
    EXPECT_NE(report.rows.at(check).second.find(text), std::string::npos)
        << check << ": " << report.rows.at(check).second << "\nexpected: " << text;
  }
  if (!restPass) return;
  for (const auto& [check, row] : report.rows) {
    if (named.count(check)) continue;
    EXPECT_TRUE(row.first == "pass" || row.first == "info") << check << ": " << row.second;
  }
}

}  // namespace

// Every shape of student program: built as written (or leniently, or physics.cpp alone, as each
// expects, the report naming how), graded right, wrong ones told why. The agreement check is
// left to the mutants' test (it is half the time); CTest runs this beside the other tests.
TEST(GraderPrograms, BuildsAndGradesEveryStudentShapedProgramAsItsExpectationSays) {
  if (!jello::grader::sandboxProblem().empty()) GTEST_SKIP() << jello::grader::sandboxProblem();
  std::string root = makeTempDir(), cls = root + "/class", report = root + "/report";
  CommandResult made = runProgram({std::string(JELLO_SOURCE_DIR) + "/scripts/make-students", cls});
  ASSERT_EQ(made.status, 0) << made.err;
  CommandResult r =
      grade({"-o", report, "--seed", "5", "--checks",
             "rest,structural,shear,bend,dampers,walls,plane,field,euler,rk4,robust", cls});
  ASSERT_EQ(r.status, 0) << r.err;
  // One folder of submissions is a class: each graded, with a line as it starts and as it ends.
  int shapes = 0;
  for (const auto& entry : fs::directory_iterator(cls)) {
    std::string name = entry.path().filename().string();
    ++shapes;
    EXPECT_NE(r.err.find("] " + name + ": building and grading"), std::string::npos) << name;
    EXPECT_NE(r.err.find("] " + name + ": "), std::string::npos) << name;
    expectShape(name, readReport(report + "/" + name + "/report.md"));
  }
  EXPECT_GE(shapes, 16);
  EXPECT_NE(r.err.find("a class of " + std::to_string(shapes) + " submissions"), std::string::npos)
      << r.err;
  // What failed is on the terminal in words, not only in report.md.
  EXPECT_NE(r.err.find("missing-walls: "), std::string::npos);
  EXPECT_NE(
      r.err.find("  walls (FAIL): walls x = +2, y = +2, z = +2: no force on points across it"),
      std::string::npos)
      << r.err;
  removeTree(root);
}

// What the course's worlds never ask (a field of resolution 1, a collapsed cube) is a note by
// default and a FAIL with --strict: the course-domain shape, right on every course world.
TEST(GraderPrograms, StrictGradesWhatTheCoursesWorldsNeverAsk) {
  if (!jello::grader::sandboxProblem().empty()) GTEST_SKIP() << jello::grader::sandboxProblem();
  std::string root = makeTempDir(), cls = root + "/class";
  ASSERT_EQ(
      runProgram({std::string(JELLO_SOURCE_DIR) + "/scripts/make-students", cls, "course-domain"})
          .status,
      0);
  CommandResult r = grade({"-o", root + "/strict", "--strict", "--seed", "5", "--checks",
                           "field,robust", cls + "/course-domain"});
  ASSERT_EQ(r.status, 0) << r.err;
  Report strict = readReport(root + "/strict/course-domain/report.md");
  EXPECT_EQ(strict.rows["field"].first, "FAIL") << strict.rows["field"].second;
  EXPECT_NE(strict.rows["field"].second.find("with R = 1"), std::string::npos);
  EXPECT_NE(strict.rows["field"].second.find("(graded: --strict)"), std::string::npos);
  EXPECT_EQ(strict.rows["robust"].first, "FAIL") << strict.rows["robust"].second;
  EXPECT_NE(strict.rows["robust"].second.find("a cube collapsed to one point"), std::string::npos);
  removeTree(root);
}

// A copy of a library beside the program, its headers more than the grader copies and named
// before physics.cpp, crowds out none of the course's files: the folder holding physics.cpp is
// copied first.
TEST(GraderPrograms, ALibraryCopyOfAnySizeCrowdsOutNoneOfTheCoursesFiles) {
  if (!jello::grader::sandboxProblem().empty()) GTEST_SKIP() << jello::grader::sandboxProblem();
  std::string root = makeTempDir(), cls = root + "/class";
  ASSERT_EQ(runProgram({std::string(JELLO_SOURCE_DIR) + "/scripts/make-students", cls}).status, 0);
  std::string hand = cls + "/course";
  fs::create_directories(hand + "/aaa-library/include");
  for (int n = 0; n < 2100; ++n)
    writeText(hand + "/aaa-library/include/h" + std::to_string(n) + ".h", "/* a header */\n");
  // A file the program may read, too large to take: left out, and said.
  writeText(hand + "/huge.ppm", std::string(9u << 20, 'x'));
  CommandResult r = grade({"-o", root + "/report", "--seed", "5", "--checks", "rest", hand});
  ASSERT_EQ(r.status, 0) << r.err;
  Report report = readReport(root + "/report/course/report.md");
  EXPECT_EQ(report.rows["builds"].first, "pass") << report.rows["builds"].second;
  EXPECT_EQ(report.rows["rest"].first, "pass") << report.rows["rest"].second;
  EXPECT_NE(report.notes.find("more source than the grader takes"), std::string::npos)
      << report.notes;
  EXPECT_NE(report.notes.find("over 8 MB are left out (the first: huge.ppm)"), std::string::npos)
      << report.notes;
  removeTree(root);
}
