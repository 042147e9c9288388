// report.h: what the grader writes: per submission report.md and build.log; for the class
// summary.md, summary.csv and junit.xml; for CTest a CTestTestfile.cmake.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "grader/checks.h"
#include "grader/submission.h"

namespace jello::grader {

struct Graded {
  Submission submission;
  std::string how;  // how it was built (builds), in words
  std::string buildLog;
  std::vector<CheckResult> results;  // the checks graded, in checkTable() order; "builds" first
  double seconds = 0;
};

// Whether `dir` holds a report this grader wrote (its mark, .jello-grade, a regular file): a
// grade into it again replaces the grader's own files there, without --overwrite.
bool isGradingReport(const std::string& dir);

// The files a report folder will hold, for the check before grading starts.
std::vector<std::string> reportFiles(const std::vector<Submission>& submissions);
// Writes them all under `dir` (made), replacing earlier ones only with `overwrite`, and the mark
// .jello-grade (the submissions' names); the report files of an earlier grade's submissions
// that this one does not grade are removed. Throws std::runtime_error with a one-line message.
// The submissions an earlier grade wrote into `dir`, and its seed, from the folder's mark (none
// when `dir` is no report of the grader's).
std::vector<std::string> earlierSubmissions(const std::string& dir);
std::optional<std::uint64_t> earlierSeed(const std::string& dir);

// One mistake that explains several FAILs, named once ("the forces are not divided by the mass
// (it explains structural, dampers, walls)"), or "".
std::string rootCause(const Graded& g);

// The report folder's files: summary.md, summary.csv, junit.xml, grading.json (the record a
// merge reads, shards.h), a report.md and build.log per submission, and the mark.
void writeReport(const std::string& dir, const std::vector<Graded>& graded, std::uint64_t seed,
                 bool strict, bool overwrite);
// One line a submission for the terminal: "alice: 12 pass, 1 near, 1 FAIL (rk4) in 9.8 s".
std::string summaryLine(const Graded& graded);

// dir/CTestTestfile.cmake and dir/grading.txt: a test SUBMISSION/CHECK for every check, each
// running `grade --one CHECK --item N dir`; "builds" is the fixture the others need.
void writeCTestFiles(const std::string& dir, const std::string& gradeProgram,
                     const std::vector<Submission>& submissions,
                     const std::vector<std::string>& checks, std::uint64_t seed, bool strict,
                     bool overwrite);
// Reads dir/grading.txt back: the seed, --strict, and the submissions' paths (each written with
// its bytes escaped, so that a name holding a line break stays one path).
std::vector<std::string> readCTestList(const std::string& dir, std::uint64_t* seed, bool* strict);

}  // namespace jello::grader
