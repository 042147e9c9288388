// grade: builds students' physics.cpp against the course API and grades them, each in a sandbox
// (README, "Grading"). Only this file prints errors and picks the exit status: 0 when every check
// of every submission ran, whatever the grades; 2 on bad usage or when no sandbox can be made.
// With --one (the tests grade --ctest writes) the status is the check's: 0 pass, near or info;
// 1 fail.
#include <sys/stat.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <limits>
#include <mutex>
#include <optional>
#include <random>
#include <sstream>
#include <thread>

#include "app/cli.h"
#include "core/exitstatus.h"
#include "core/output.h"
#include "grader/build.h"
#include "grader/checks.h"
#include "grader/probe.h"
#include "grader/report.h"
#include "grader/sandbox.h"
#include "grader/shards.h"
#include "grader/submission.h"
#include "model/term.h"

namespace fs = std::filesystem;
using namespace jello;
using namespace jello::grader;

namespace {

std::string programPath() {
  std::error_code error;
  fs::path self = fs::read_symlink("/proc/self/exe", error);
  return error ? std::string("grade") : self.string();
}

// The course worlds: beside the program (./grade at the project's root), or in the sources.
std::string worldDir() {
  fs::path beside = fs::path(programPath()).parent_path() / "world";
  if (fs::exists(beside / "rotate.w")) return beside.string();
  std::string sources = std::string(JELLO_SOURCE_DIR) + "/world";
  if (fs::exists(sources + "/rotate.w")) return sources;
  throw std::runtime_error("the course worlds (world/rotate.w, ...) are neither beside " +
                           programPath() + " nor in " + sources);
}

// The grade of a check that could not run: FAIL, but never for speed, which is not graded, nor
// for robust, beyond the course's domain (unless --strict).
CheckResult notRun(const std::string& check, const std::string& why, bool strict = false) {
  if (check == "speed") return {check, Grade::Info, "not measured: " + why, {}};
  if (check == "robust" && !strict) return {check, Grade::Info, why, {}};
  return {check, Grade::Fail, why, {}};
}

CheckResult buildCheck(const Submission& submission, const std::string& probePath, Graded& graded) {
  BuildResult build;
  try {
    build = buildSubmission(submission, probePath);
  } catch (const std::exception& e) {
    build.diagnosis = std::string("the grader could not build it: ") + e.what();
  }
  graded.how = build.how;
  graded.buildLog = build.log;
  CheckResult result{"builds", build.built ? Grade::Pass : Grade::Fail,
                     build.built ? "built from " + build.how : build.diagnosis, build.notes};
  return result;
}

// A check whose grader failed (a file it could not write, memory) fails with the reason: one
// submission's trouble never ends the grading of the class.
CheckResult runCheckSafely(const std::string& check, const std::string& probePath,
                           const GradingSetup& setup) {
  try {
    return runCheck(check, probePath, setup);
  } catch (const std::exception& e) {
    return {
        check, Grade::Fail, std::string("the grader could not run this check: ") + e.what(), {}};
  }
}

// The checks graded for one submission, in order; the first is "builds".
Graded gradeOne(const Submission& submission, const std::vector<std::string>& checks,
                const GradingSetup& setup, const std::string& workDir) {
  auto start = std::chrono::steady_clock::now();
  resetProbeBudget();
  Graded graded{submission, {}, {}, {}, 0};
  std::string probePath = workDir + "/" + submission.name + ".probe";
  graded.results.push_back(buildCheck(submission, probePath, graded));
  std::string hungIn;  // the check in which the submission did not return
  for (std::size_t n = 1; n < checks.size(); ++n) {
    const std::string& check = checks[n];
    if (graded.results.front().grade == Grade::Fail) {
      graded.results.push_back(notRun(check, "not built"));
    } else if (!hungIn.empty()) {
      graded.results.push_back(notRun(
          check, "not run: the submission did not return in the " + hungIn + " check (see it)",
          setup.strict));
    } else {
      graded.results.push_back(runCheckSafely(check, probePath, setup));
      // A hang in what the course never asks (a note of a check that passed) stops nothing.
      if (probeHung() && graded.results.back().grade == Grade::Fail) hungIn = check;
      if (probeHung() && hungIn.empty()) resetProbeBudget();
    }
  }
  fs::remove(probePath);
  fs::remove_all(programFilesOf(probePath));
  graded.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return graded;
}

// The lines a finished submission prints: its summary, then what is wrong, a line a check.
std::string finishedLines(const Graded& graded) {
  std::string lines = summaryLine(graded) + "\n";
  if (!rootCause(graded).empty()) lines += "  root cause: " + rootCause(graded) + "\n";
  for (const auto& r : graded.results) {
    if (r.grade == Grade::Fail || r.grade == Grade::Near)
      lines += "  " + r.check + " (" + gradeName(r.grade) + "): " + printable(r.diagnosis) + "\n";
    if (r.check == "builds" && r.grade == Grade::Fail) return lines;  // the rest: "not built"
  }
  return lines;
}

// Makes `dir` ready for the report of `submissions` (a grade or a merge), or throws saying why
// not; whether the grader's own files there are replaced.
Existing prepareReportFolder(const std::string& dir, const std::vector<Submission>& submissions,
                             bool overwrite) {
  bool made = !fs::exists(dir);
  // A folder this grader wrote before is graded into again: its own files are replaced. Grading
  // only some of its class there would drop the others from its summary: refused in words,
  // unless --overwrite asks for this grade alone.
  bool regrade = !made && isGradingReport(dir);
  if (regrade && !overwrite) {
    std::vector<std::string> dropped;
    for (const auto& name : earlierSubmissions(dir)) {
      bool again = std::any_of(submissions.begin(), submissions.end(),
                               [&](const Submission& s) { return s.name == name; });
      if (!again) dropped.push_back(name);
    }
    if (!dropped.empty())
      throw std::invalid_argument(textf(
          "%s: holds the reports of %zu other submission%s (%s%s), which this grade would drop "
          "from its summary: grade the whole class again into it, choose another -o, or add "
          "--overwrite to keep only this grade",
          dir.c_str(), dropped.size(), dropped.size() == 1 ? "" : "s", dropped.front().c_str(),
          dropped.size() > 1 ? ", ..." : ""));
  }
  Existing existing = overwrite || regrade ? Existing::Replace : Existing::Refuse;
  claimOutputs(dir, {"summary.md", "summary.csv", "junit.xml", kRecordName}, existing);
  if (made) removeIfEmptyOnSignal(dir);
  for (const auto& file : reportFiles(submissions)) {
    fs::path folder = fs::path(dir + "/" + file).parent_path();
    struct stat info;
    // A submission's folder in the report is a folder the grader makes or made: never a link
    // (written through, it would replace the files it points to) or anything else.
    if (lstat(folder.c_str(), &info) == 0 && !S_ISDIR(info.st_mode))
      throw std::runtime_error(folder.string() +
                               ": not a folder (a symbolic link, or a file); the report writes "
                               "into folders of its own: move it away, or choose another -o");
    if (!fs::exists(folder)) removeIfEmptyOnSignal(folder.string());
    fs::create_directories(folder);
    std::string why = whyNotWritable(dir + "/" + file, existing);
    if (!why.empty()) throw std::runtime_error(dir + "/" + file + ": " + why);
  }
  return existing;
}

int gradeAll(const std::vector<Submission>& submissions, const std::vector<std::string>& checks,
             const GradingSetup& setup, const std::string& dir, bool overwrite, int jobs) {
  Existing existing = prepareReportFolder(dir, submissions, overwrite);
  Scratch work;  // the built programs, trusted: never shown to a sandbox but by copy
  jobs = std::max(1, std::min(jobs, static_cast<int>(submissions.size())));
  std::cerr << textf("grading %zu submission%s, %d at a time; unseen worlds from seed %llu\n",
                     submissions.size(), submissions.size() == 1 ? "" : "s", jobs,
                     static_cast<unsigned long long>(setup.seed));
  if (std::find(checks.begin(), checks.end(), "agreement") != checks.end())
    startAgreementReferences(setup);
  std::vector<Graded> graded(submissions.size());
  std::atomic<std::size_t> next{0}, done{0};
  std::mutex printing;
  auto worker = [&] {
    for (std::size_t n; (n = next++) < submissions.size();) {
      {
        std::lock_guard<std::mutex> hold(printing);
        std::cerr << textf("[%zu/%zu] %s: building and grading ...\n", n + 1, submissions.size(),
                           submissions[n].name.c_str());
      }
      graded[n] = gradeOne(submissions[n], checks, setup, work.path());
      std::lock_guard<std::mutex> hold(printing);
      std::cerr << textf("[%zu/%zu done] ", ++done, submissions.size()) + finishedLines(graded[n]);
    }
  };
  std::vector<std::thread> threads;
  for (int t = 0; t < jobs; ++t) threads.emplace_back(worker);
  for (auto& thread : threads) thread.join();
  stopAgreementReferences();
  writeReport(dir, graded, setup.seed, setup.strict, existing == Existing::Replace);
  std::cout << dir << "/summary.md, summary.csv, junit.xml; a report.md per submission\n";
  return 0;
}

std::vector<std::string> checkNames(const Graded& g) {
  std::vector<std::string> names;
  for (const CheckResult& r : g.results) names.push_back(r.check);
  return names;
}

// The reports of a class's parts (grade --shard K/N, each into its own folder) joined into `dir`,
// as one grade of the whole class writes it but for the measured times.
int mergeReports(const std::string& dir, const std::vector<std::string>& parts, bool overwrite) {
  std::vector<Graded> all;
  std::uint64_t seed = 0;
  bool strict = false;
  for (std::size_t n = 0; n < parts.size(); ++n) {
    GradedRecord record = readGradedRecord(parts[n]);
    if (n > 0 && (record.seed != seed || record.strict != strict))
      throw std::invalid_argument(parts[n] + ": graded with another --seed or --strict than " +
                                  parts[0] + ": its worlds differ; grade the parts alike");
    seed = record.seed;
    strict = record.strict;
    for (const Graded& g : record.graded) {
      // The same checks in every part: summary.csv's columns are one list.
      if (!all.empty() && checkNames(g) != checkNames(all.front()))
        throw std::invalid_argument(parts[n] +
                                    ": graded with other --checks than the parts "
                                    "before it; grade the parts alike");
      all.push_back(g);
    }
  }
  // One grade of the class takes its submissions in the order of their paths (a class's entries
  // in name order).
  std::stable_sort(all.begin(), all.end(), [](const Graded& a, const Graded& b) {
    return a.submission.path < b.submission.path;
  });
  std::vector<Submission> submissions;
  for (const Graded& g : all) {
    for (const Submission& s : submissions)
      if (s.name == g.submission.name)
        throw std::invalid_argument(g.submission.name + ": in two of the parts");
    submissions.push_back(g.submission);
  }
  if (submissions.empty()) throw std::invalid_argument("--merge: the parts hold no submission");
  // The record of an empty part says nothing about its checks: only the others are compared.
  Existing existing = prepareReportFolder(dir, submissions, overwrite);
  writeReport(dir, all, seed, strict, existing == Existing::Replace);
  std::cout << dir << "/summary.md, summary.csv, junit.xml: " << submissions.size()
            << " submissions from " << parts.size() << " parts\n";
  return 0;
}

// One check of one submission, as a CTest test: the build goes to dir/NAME/probe.
int gradeOneCheck(const std::string& check, std::size_t item, const std::string& dir) {
  GradingSetup setup{worldDir(), 0};
  std::vector<Submission> submissions =
      nameSubmissions(readCTestList(dir, &setup.seed, &setup.strict));
  if (item >= submissions.size())
    throw std::runtime_error("--item " + std::to_string(item) + ": no such submission");
  const Submission& s = submissions[item];
  fs::create_directories(dir + "/" + s.name);
  std::string probePath = dir + "/" + s.name + "/probe";
  CheckResult result;
  if (check == "builds") {
    Graded graded;
    fs::remove(probePath);
    result = buildCheck(s, probePath, graded);
    writeFileWhole(dir + "/" + s.name + "/build.log", graded.buildLog, Existing::Replace);
  } else if (!fs::exists(probePath)) {
    result = notRun(check, "not built");
  } else {
    result = runCheckSafely(check, probePath, setup);
  }
  // Printed through printable: a student's #error text never reaches the terminal raw.
  std::cout << s.name << "/" << check << ": " << gradeName(result.grade) << ": "
            << printable(result.diagnosis) << "\n";
  for (const auto& note : result.notes) std::cout << "  note: " << printable(note) << "\n";
  return result.grade == Grade::Fail ? 1 : 0;
}

// The checks asked for with --checks: "builds" and the named ones, in the table's order.
std::vector<std::string> chosenChecks(const std::string& list) {
  std::vector<std::string> names;
  std::stringstream words(list);
  for (std::string name; std::getline(words, name, ',');) {
    if (!isCheck(name)) throw std::invalid_argument("--checks: no check named '" + name + "'");
    names.push_back(name);
  }
  std::vector<std::string> checks;
  for (const auto& check : checkTable()) {
    bool asked = std::find(names.begin(), names.end(), check.name) != names.end();
    if (names.empty() || asked || std::string(check.name) == "builds") checks.push_back(check.name);
  }
  return checks;
}

struct Options {
  std::vector<std::string> paths;
  std::string checkList;  // --checks, comma-separated
  std::string dir = "grading", one;
  bool overwrite = false, ctest = false, strict = false;
  std::string shard, merge;           // --shard K/N; --merge OUT
  std::optional<std::uint64_t> seed;  // --seed; else the report folder's, else a new one
  std::size_t item = 0;
  int jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
};

// Parses the command line into `o`; an exit status when it is done (help, or a usage error).
std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  CLI::App app{
      "grade: builds each student's jello program as written (or its physics.cpp alone) and\n"
      "grades each check, every submission in a sandbox. README, \"Grading\"; docs/grading.md.",
      "grade"};
  app.add_option("SUBMISSION", o.paths, "a folder, .zip, .tar.gz or .tgz holding physics.cpp");
  app.add_option("-o,--output", o.dir, "the report's folder (default grading/)");
  app.add_flag("--overwrite", o.overwrite, "replace an earlier report in that folder");
  app.add_option("--seed", o.seed,
                 "the seed of the unseen worlds (default: the report folder's, or a new one, "
                 "printed)")
      ->transform(wholeNumber(0, std::numeric_limits<long long>::max()));
  app.add_option("--checks", o.checkList, "only these checks (and builds), e.g. --checks rest,rk4");
  app.add_option("-j,--jobs", o.jobs, "submissions graded at once (default: the cores)")
      ->transform(wholeNumber(1, 256));
  app.add_option("--shard", o.shard,
                 "grade only part K of N of the class (K/N; a submission is always in the same "
                 "part), for --merge");
  app.add_option("--merge", o.merge,
                 "join the report folders given (the parts of grade --shard) into this one");
  app.add_flag("--strict", o.strict,
               "grade what the course's worlds never ask too (resolution 1, points on a wall, a "
               "collapsed cube, a hard throw): FAIL, not notes");
  app.add_flag("--ctest", o.ctest, "write a CTest file into the report folder instead of grading");
  app.add_option("--one", o.one, "(for the CTest file) run one check")->group("");
  app.add_option("--item", o.item, "(for the CTest file) of this submission")
      ->group("")
      ->transform(wholeNumber(0, 100000));
  // One line for an argument refused (printed here: this is grade's main), or --help answered.
  const Outcome parsed = parseCommandLine(app, argc, argv);
  if (!parsed.ok()) return exitStatusOf(parsed);
  if (parsed.message == kAnswered) return kExitOk;
  return std::nullopt;
}

void requireSandbox() {
  std::string problem = sandboxProblem();
  if (!problem.empty()) throw std::runtime_error(problem);
}

int writeCTest(const Options& o, const std::vector<std::string>& paths,
               const std::vector<std::string>& checks) {
  std::vector<std::string> absolute;
  for (const auto& p : paths) absolute.push_back(fs::absolute(p).string());
  fs::create_directories(o.dir);
  writeCTestFiles(fs::absolute(o.dir).string(), programPath(), nameSubmissions(absolute), checks,
                  o.seed.value_or(std::random_device{}()), o.strict, o.overwrite);
  std::cout << "cd " << o.dir << " && ctest -j" << o.jobs << "   # " << paths.size() * checks.size()
            << " tests; --output-junit junit.xml for a learning platform\n";
  return 0;
}

int run(int argc, char** argv) {
  Options o;
  if (auto status = parseOptions(argc, argv, o)) return *status;
  if (!o.one.empty()) {
    if (!isCheck(o.one) || o.paths.size() != 1)
      throw std::invalid_argument("--one CHECK --item N DIR");
    requireSandbox();
    return gradeOneCheck(o.one, o.item, o.paths[0]);
  }
  if (!o.merge.empty()) {
    if (o.paths.empty()) throw std::invalid_argument("--merge OUT PART...: no part given");
    return mergeReports(o.merge, o.paths, o.overwrite);
  }
  std::vector<std::string> checks = chosenChecks(o.checkList);
  if (o.paths.empty())
    throw std::invalid_argument("no submission given: grade [-o DIR] SUBMISSION...");
  if (o.dir.empty()) throw std::invalid_argument("-o: an empty folder name");
  for (const auto& path : o.paths) {
    std::string why = whyNotSubmission(path);
    if (why.empty() && path.find('\n') != std::string::npos)
      why = path + ": a name with a line break";
    if (!why.empty()) throw std::invalid_argument(why);
  }
  std::vector<std::string> notes;
  std::vector<std::string> paths = expandClasses(o.paths, notes);
  for (const auto& note : notes) std::cerr << "grade: " << note << "\n";
  if (o.ctest) return writeCTest(o, paths, checks);
  requireSandbox();
  std::vector<Submission> submissions = nameSubmissions(paths);
  if (!o.shard.empty()) {
    // Named as in the whole class first: a part's names are the whole run's.
    Shard shard = parseShard(o.shard);
    submissions.erase(std::remove_if(submissions.begin(), submissions.end(),
                                     [&](const Submission& s) { return !inShard(s.name, shard); }),
                      submissions.end());
    std::cerr << textf("grade: part %d of %d: %zu submission%s\n", shard.part, shard.parts,
                       submissions.size(), submissions.size() == 1 ? "" : "s");
  }
  // A regrade into a report folder uses its seed, so that it is judged on the same worlds.
  std::uint64_t seed = o.seed ? *o.seed : earlierSeed(o.dir).value_or(std::random_device{}());
  if (submissions.empty()) {
    // An empty part (a small class): its record alone, so that --merge finds every part.
    Existing existing = prepareReportFolder(o.dir, submissions, o.overwrite);
    writeFileWhole(o.dir + "/" + kRecordName, gradedRecord({}, seed, o.strict), existing);
    std::cout << o.dir << "/" << kRecordName << ": no submission in this part\n";
    return 0;
  }
  return gradeAll(submissions, checks, {worldDir(), seed, o.strict}, o.dir, o.overwrite, o.jobs);
}

}  // namespace

int main(int argc, char** argv) {
  setProgramName("grade");
  installSignalCleanup();
  installScratchCleanup();  // before any thread: the signals go to its thread
  // What the grader makes for a sandbox (copies of sources, its probe) must be readable by the
  // sandbox's own user, whatever umask the grader was started with.
  umask(022);
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    printError(e.what());
    return 2;
  }
}
