// report.cpp: the grader's files (report.h). Every file is written whole by core/output's writer.
#include "grader/report.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "core/output.h"
#include "grader/shards.h"
#include "model/term.h"

namespace jello::grader {
namespace {

// Text for XML 1.0: printable (no control character, no byte outside UTF-8), the markup
// characters as entities, and the two characters XML forbids that UTF-8 can hold (U+FFFE,
// U+FFFF) written out: one student's file must not make the class's junit.xml ill-formed.
std::string xmlEscape(const std::string& text) {
  std::string out;
  std::string safe = printable(text);
  for (std::size_t n = 0; n < safe.size(); ++n) {
    char c = safe[n];
    if (c == '&')
      out += "&amp;";
    else if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '"')
      out += "&quot;";
    else if (safe.compare(n, 2, "\xEF\xBF") == 0 && n + 2 < safe.size() &&
             (safe[n + 2] == '\xBE' || safe[n + 2] == '\xBF')) {
      out += safe[n + 2] == '\xBE' ? "\\uFFFE" : "\\uFFFF";
      n += 2;
    } else
      out += c;
  }
  return out;
}

// Text for markdown: printable, and nothing in it read as markup, HTML or a table's edge (a
// compiler's message quotes the student's code: `int* p`, <windows.h>, a[i]).
std::string markdownText(const std::string& text) {
  std::string out;
  for (char c : printable(text)) {
    if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '&')
      out += "&amp;";
    else if (std::string("`*_[]|#~").find(c) != std::string::npos)
      out += std::string("\\") + c;
    else
      out += c;
  }
  return out;
}

// The compilers' log, line by line through printable: a student's #error reaches no terminal
// that shows build.log as an escape sequence.
std::string logText(const std::string& log) {
  std::string out;
  std::istringstream lines(log);
  for (std::string line; std::getline(lines, line);) out += printable(line) + "\n";
  return out;
}

// A CSV field: quoted, quotes doubled; a leading = + - @ is kept from spreadsheets' formulas.
std::string csvField(const std::string& text) {
  std::string out = "\"";
  if (!text.empty() && std::string("=+-@").find(text[0]) != std::string::npos) out += '\'';
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c == '\n' ? ' ' : c);
  return out + "\"";
}

// A CMake bracket argument that holds `text` whatever it contains.
std::string cmakeQuote(const std::string& text) {
  std::string equals;
  while (text.find("]" + equals + "]") != std::string::npos) equals += '=';
  return "[" + equals + "[" + text + "]" + equals + "]";
}

// A check's cell in the summary: its grade, or the figure it measured (speed).
// A submission's overall grade: FAIL when a check fails, near when one is near, else pass.
Grade overallGrade(const Graded& g) {
  Grade overall = Grade::Pass;
  for (const auto& r : g.results) {
    if (r.grade == Grade::Fail) return Grade::Fail;
    if (r.grade == Grade::Near) overall = Grade::Near;
  }
  return overall;
}

// The graded checks (pass, near or FAIL: info is not graded), and those of them that pass.
int gradedChecks(const Graded& g) {
  return static_cast<int>(
      std::count_if(g.results.begin(), g.results.end(),
                    [](const CheckResult& r) { return r.grade != Grade::Info; }));
}
int passedChecks(const Graded& g) {
  return static_cast<int>(
      std::count_if(g.results.begin(), g.results.end(),
                    [](const CheckResult& r) { return r.grade == Grade::Pass; }));
}

}  // namespace

std::string rootCause(const Graded& g) {
  // One mistake that shows in several checks, as their sentences name it.
  struct Cause {
    const char* mark;   // in each failing check's sentence
    const char* words;  // the cause, once
  };
  const Cause causes[] = {
      {"is the force not divided by the mass?", "the forces are not divided by the mass"},
      {"multiplied by the mass instead of divided", "the forces are multiplied by the mass"},
      {"did not return", "it does not return (an endless loop?)"}};
  for (const Cause& cause : causes) {
    std::string checks;
    int count = 0;
    for (const auto& r : g.results) {
      if (r.grade != Grade::Fail || r.diagnosis.find(cause.mark) == std::string::npos) continue;
      checks += (count++ ? ", " : "") + r.check;
    }
    if (count >= 2) return std::string(cause.words) + " (it explains " + checks + ")";
  }
  return "";
}

namespace {

std::string gradeCell(const CheckResult& r, const char* unit) {
  return r.figure >= 0 ? textf("%.0f%s", r.figure, unit) : std::string(gradeName(r.grade));
}

std::string submissionReport(const Graded& g) {
  std::ostringstream md;
  md << "# " << g.submission.name << "\n\nSubmission: " << markdownText(g.submission.path);
  if (!g.how.empty()) md << ", built from " << g.how;
  md << textf(". Graded in %.1f s.\n\n", g.seconds);
  if (!rootCause(g).empty()) md << "**Root cause**: " << markdownText(rootCause(g)) << ".\n\n";
  md << "| check | grade | what it found |\n|---|---|---|\n";
  for (const auto& r : g.results)
    md << "| " << r.check << " | " << gradeName(r.grade) << " | " << markdownText(r.diagnosis)
       << " |\n";
  for (const auto& r : g.results) {
    for (const auto& note : r.notes) md << "\n- " << r.check << ": " << markdownText(note);
  }
  md << "\n\nThe compiler's output is in build.log.\n";
  return md.str();
}

std::string summaryMarkdown(const std::vector<Graded>& graded, std::uint64_t seed) {
  std::ostringstream md;
  md << "# Grading summary\n\nUnseen worlds from seed " << seed << ". pass: right; near: right but "
     << "for a rounded constant; FAIL: wrong (see the submission's report.md); info: not "
        "graded.\n\n"
     << "| submission |";
  const std::vector<CheckResult>& columns = graded.front().results;
  for (const auto& c : columns) md << " " << c.check << " |";
  md << "\n|---|";
  for (std::size_t n = 0; n < columns.size(); ++n) md << "---|";
  for (const auto& g : graded) {
    md << "\n| " << g.submission.name << " |";
    for (const auto& r : g.results) md << " " << gradeCell(r, " us") << " |";
  }
  md << "\n\n## What failed\n";
  for (const auto& g : graded) {
    for (const auto& r : g.results) {
      if (r.grade == Grade::Fail || r.grade == Grade::Near)
        md << "\n- " << g.submission.name << "/" << r.check << " (" << gradeName(r.grade)
           << "): " << markdownText(r.diagnosis);
    }
  }
  return md.str() + "\n";
}

// summary.csv: a row a submission, its overall verdict and score first (columns an instructor
// can sort), then a column a check: its grade, and for speed the microseconds a step (a number,
// or empty when not measured).
std::string summaryCsv(const std::vector<Graded>& graded) {
  std::ostringstream csv;
  csv << "submission,verdict,passed,graded";
  for (const auto& c : graded.front().results)
    csv << "," << c.check << (c.check == "speed" ? "_us" : "");
  for (const auto& g : graded) {
    csv << "\n"
        << csvField(g.submission.name) << "," << gradeName(overallGrade(g)) << ","
        << passedChecks(g) << "," << gradedChecks(g);
    for (const auto& r : g.results) {
      if (r.check == "speed")
        csv << "," << (r.figure >= 0 ? textf("%.0f", r.figure) : std::string());
      else
        csv << "," << gradeName(r.grade);
    }
  }
  return csv.str() + "\n";
}

std::string junit(const std::vector<Graded>& graded) {
  int tests = 0, failures = 0;
  std::ostringstream cases;
  for (const auto& g : graded) {
    for (const auto& r : g.results) {
      ++tests;
      cases << "    <testcase classname=\"" << xmlEscape(g.submission.name) << "\" name=\""
            << r.check << "\">";
      if (r.grade == Grade::Fail) {
        ++failures;
        cases << "<failure message=\"" << xmlEscape(r.diagnosis) << "\"/>";
      } else if (!r.diagnosis.empty()) {
        cases << "<system-out>" << gradeName(r.grade) << ": " << xmlEscape(r.diagnosis)
              << "</system-out>";
      }
      cases << "</testcase>\n";
    }
  }
  return textf(
             "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites>\n  <testsuite name=\"jello "
             "grading\" "
             "tests=\"%d\" failures=\"%d\">\n",
             tests, failures) +
         cases.str() + "  </testsuite>\n</testsuites>\n";
}

void makeFolder(const std::string& dir) {
  if (mkdir(dir.c_str(), 0755) != 0 && errno != EEXIST)
    throw std::runtime_error(dir + ": cannot make the folder");
}

}  // namespace

std::vector<std::string> reportFiles(const std::vector<Submission>& submissions) {
  std::vector<std::string> files = {"summary.md", "summary.csv", "junit.xml"};
  for (const auto& s : submissions) {
    files.push_back(s.name + "/report.md");
    files.push_back(s.name + "/build.log");
  }
  return files;
}

namespace {

const char* const kMark = ".jello-grade";

}  // namespace

bool isGradingReport(const std::string& dir) {
  struct stat info;
  return lstat((dir + "/" + kMark).c_str(), &info) == 0 && S_ISREG(info.st_mode);
}

std::vector<std::string> earlierSubmissions(const std::string& dir) {
  std::vector<std::string> names;
  if (!isGradingReport(dir)) return names;
  std::ifstream mark(dir + "/" + kMark);
  for (std::string line; std::getline(mark, line);) {
    if (!line.empty() && line[0] != '#' && line.find('/') == std::string::npos && line != "." &&
        line != "..")
      names.push_back(line);
  }
  return names;
}

std::optional<std::uint64_t> earlierSeed(const std::string& dir) {
  if (!isGradingReport(dir)) return std::nullopt;
  std::ifstream mark(dir + "/" + kMark);
  for (std::string line; std::getline(mark, line);) {
    if (line.rfind("# seed ", 0) == 0) {
      try {
        return std::stoull(line.substr(7));
      } catch (const std::exception&) {
        return std::nullopt;
      }
    }
  }
  return std::nullopt;
}

namespace {

// Removes the report files of submission `name` in `dir`, never through a link: the folder is
// opened without following one (a link planted in its place, or a name in a planted mark,
// reaches nothing outside), and only the grader's two files are removed from it.
void removeEarlierReport(const std::string& dir, const std::string& name) {
  int top = open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (top < 0) return;
  int folder = openat(top, name.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  if (folder >= 0) {
    for (const char* file : {"report.md", "build.log"}) unlinkat(folder, file, 0);
    close(folder);
    unlinkat(top, name.c_str(), AT_REMOVEDIR);  // only when empty
  }
  close(top);
}

}  // namespace

void writeReport(const std::string& dir, const std::vector<Graded>& graded, std::uint64_t seed,
                 bool strict, bool overwrite) {
  Existing existing = overwrite ? Existing::Replace : Existing::Refuse;
  std::string mark = "# made by ./grade: the submissions graded here, a name a line\n# seed " +
                     std::to_string(seed) + "\n";
  for (const auto& g : graded) mark += g.submission.name + "\n";
  for (const auto& name : earlierSubmissions(dir)) {
    if (mark.find("\n" + name + "\n") == std::string::npos) removeEarlierReport(dir, name);
  }
  for (const auto& g : graded) {
    makeFolder(dir + "/" + g.submission.name);
    writeFileWhole(dir + "/" + g.submission.name + "/report.md", submissionReport(g), existing);
    writeFileWhole(dir + "/" + g.submission.name + "/build.log", logText(g.buildLog), existing);
  }
  writeFileWhole(dir + "/summary.md", summaryMarkdown(graded, seed), existing);
  writeFileWhole(dir + "/summary.csv", summaryCsv(graded), existing);
  writeFileWhole(dir + "/junit.xml", junit(graded), existing);
  writeFileWhole(dir + "/" + kRecordName, gradedRecord(graded, seed, strict), existing);
  writeFileWhole(dir + "/" + kMark, mark, Existing::Replace);
}

std::string summaryLine(const Graded& g) {
  int counts[4] = {0, 0, 0, 0};
  std::string failing;
  for (const auto& r : g.results) {
    ++counts[static_cast<int>(r.grade)];
    if (r.grade == Grade::Fail) failing += (failing.empty() ? "" : ", ") + r.check;
  }
  return textf("%s: %d pass, %d near, %d FAIL%s in %.1f s", g.submission.name.c_str(), counts[0],
               counts[1], counts[2], failing.empty() ? "" : (" (" + failing + ")").c_str(),
               g.seconds);
}

// A path as one line of grading.txt: every byte but letters, digits and "/._-" as %XX, so that
// a name holding a line break (or anything else) reads back as itself, bound to its submission.
std::string escapedPath(const std::string& path) {
  std::string out;
  for (unsigned char c : path) {
    if (std::isalnum(c) || c == '/' || c == '.' || c == '_' || c == '-')
      out += static_cast<char>(c);
    else
      out += textf("%%%02X", c);
  }
  return out;
}

std::string unescapedPath(const std::string& line) {
  std::string out;
  for (std::size_t n = 0; n < line.size(); ++n) {
    if (line[n] == '%' && n + 2 < line.size()) {
      out += static_cast<char>(std::stoi(line.substr(n + 1, 2), nullptr, 16));
      n += 2;
    } else {
      out += line[n];
    }
  }
  return out;
}

void writeCTestFiles(const std::string& dir, const std::string& gradeProgram,
                     const std::vector<Submission>& submissions,
                     const std::vector<std::string>& checks, std::uint64_t seed, bool strict,
                     bool overwrite) {
  Existing existing = overwrite ? Existing::Replace : Existing::Refuse;
  std::ostringstream list, tests;
  list << "seed " << seed << " strict " << (strict ? 1 : 0) << "\n";
  tests
      << "# Made by grade --ctest: a test SUBMISSION/CHECK for every check of every submission.\n";
  for (std::size_t n = 0; n < submissions.size(); ++n) {
    const Submission& s = submissions[n];
    list << escapedPath(s.path) << "\n";  // one line a path, whatever bytes it holds
    for (const auto& check : checks) {
      std::string name = s.name + "/" + check;
      tests << "add_test(" << cmakeQuote(name) << " " << cmakeQuote(gradeProgram) << " --one "
            << check << " --item " << n << " " << cmakeQuote(dir) << ")\n"
            << "set_tests_properties(" << cmakeQuote(name) << " PROPERTIES TIMEOUT 300 "
            << (check == "builds" ? "FIXTURES_SETUP " : "FIXTURES_REQUIRED ") << cmakeQuote(s.name)
            << ")\n";
    }
  }
  writeFileWhole(dir + "/grading.txt", list.str(), existing);
  writeFileWhole(dir + "/CTestTestfile.cmake", tests.str(), existing);
}

std::vector<std::string> readCTestList(const std::string& dir, std::uint64_t* seed, bool* strict) {
  std::ifstream in(dir + "/grading.txt");
  std::string line;
  if (!std::getline(in, line) || line.rfind("seed ", 0) != 0) {
    throw std::runtime_error(dir + "/grading.txt: not made by grade --ctest");
  }
  std::istringstream header(line.substr(5));
  std::string word;
  int strictFlag = 0;
  header >> *seed >> word >> strictFlag;
  *strict = word == "strict" && strictFlag == 1;
  std::vector<std::string> paths;
  while (std::getline(in, line)) paths.push_back(unescapedPath(line));
  return paths;
}

}  // namespace jello::grader
