// grader_test_support.h: what the grader's tests read back from a report folder.
#pragma once

#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "grader/sandbox.h"
#include "test_support.h"

namespace jello::test {

// The fixtures of submissions (tests/data/submissions), one folder each.
inline const std::string kSubmissions = std::string(JELLO_TEST_DATA) + "/submissions";

// Whether the sandbox can be made on this machine (bubblewrap and its namespaces).
inline bool haveSandbox() { return jello::grader::sandboxProblem().empty(); }

// Runs ./grade; a whole class of fixtures takes a minute on two cores, more under sanitizers.
inline CommandResult grade(const std::vector<std::string>& args) {
  std::vector<std::string> argv = {JELLO_GRADE};
  argv.insert(argv.end(), args.begin(), args.end());
  ProgramSetup setup;
  setup.hangGuardSeconds = 280;
  return runProgram(argv, setup);
}

// summary.csv as submission -> check -> grade.
inline std::map<std::string, std::map<std::string, std::string>> readSummary(
    const std::string& dir) {
  std::istringstream csv(readText(dir + "/summary.csv"));
  std::string line, field;
  std::getline(csv, line);
  std::vector<std::string> checks;
  std::istringstream header(line);
  while (std::getline(header, field, ',')) checks.push_back(field);
  std::map<std::string, std::map<std::string, std::string>> grades;
  while (std::getline(csv, line)) {
    std::istringstream row(line);
    std::string name;
    std::getline(row, name, ',');
    name = name.substr(1, name.size() - 2);
    for (std::size_t n = 1; std::getline(row, field, ','); ++n) {
      std::string check = checks[n];
      if (check == "speed_us") check = "speed", field = field.empty() ? "info" : field;
      if (check != "verdict" && check != "passed" && check != "graded") grades[name][check] = field;
    }
  }
  return grades;
}

// A report's markdown as it reads rendered: the escapes before markdown's characters dropped
// and HTML's entities read back.
inline std::string rendered(const std::string& text) {
  std::string out;
  for (std::size_t n = 0; n < text.size(); ++n) {
    if (text[n] == '\\' && n + 1 < text.size() &&
        std::string("\\`*_[]|#~").find(text[n + 1]) != std::string::npos) {
      out += text[++n];
    } else if (text.compare(n, 4, "&lt;") == 0) {
      out += '<', n += 3;
    } else if (text.compare(n, 4, "&gt;") == 0) {
      out += '>', n += 3;
    } else if (text.compare(n, 5, "&amp;") == 0) {
      out += '&', n += 4;
    } else {
      out += text[n];
    }
  }
  return out;
}

}  // namespace jello::test
