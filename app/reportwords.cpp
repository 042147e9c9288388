// reportwords.cpp: the words of jello --report that a user acts on: settings, speeds, the
// legend, and the commands that run or keep a recommended setting (report.h).

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <string_view>

#include "app/report.h"
#include "solver/integrators.h"

namespace jello {

namespace {

constexpr const char* kJelloProgram = "./jello";              // as README runs it
constexpr const char* kCreateWorldProgram = "./createWorld";  // as README runs it
constexpr double kWholeRatiosFrom = 10;  // "12 times", not "12.3 times"; below it one decimal

// A fitted order as the report shows it: "4.07".
std::string orderText(double order) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", order);
  return text;
}

// "2.3" or "12": a ratio as a reader takes it in.
std::string ratioText(double ratio) {
  char text[32];
  std::snprintf(text, sizeof text, ratio < kWholeRatiosFrom ? "%.1f" : "%.0f", ratio);
  return text;
}

// The world's path as a command's word: ./-odd.w, not an option -odd.w.
std::string worldWord(const std::string& worldPath) {
  return !worldPath.empty() && worldPath[0] == '-' ? "./" + worldPath : worldPath;
}

// world/rotate.w and MIDPOINT: world/rotate-midpoint.w, beside the world.
std::string worldFileFor(const std::string& worldPath, Integrator integrator) {
  const std::size_t slash = worldPath.rfind('/');
  const std::string folder = slash == std::string::npos ? "" : worldPath.substr(0, slash + 1);
  std::string stem = worldPath.substr(folder.size());
  const std::size_t dot = stem.rfind('.');
  if (dot != std::string::npos && dot > 0) stem.erase(dot);
  std::string name = integratorName(integrator);
  for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return worldWord(folder + stem + "-" + name + ".w");
}

// The characters no POSIX shell gives a meaning to within a word.
bool plainInShell(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) ||
         std::string_view("_-./:=@%+,").find(c) != std::string_view::npos;
}

}  // namespace

std::string exactNumber(double x) {
  char text[32];
  const std::to_chars_result end = std::to_chars(text, text + sizeof text, x);
  return std::string(text, end.ptr);
}

const char* fittedAgainst(Integrator integrator) {
  return integrator == Integrator::RK45 ? "tolerance" : "dt";
}

std::string fittedLaw(Integrator integrator, double order) {
  if (std::isnan(order)) return "n/a";
  return std::string("error \u221d ") + fittedAgainst(integrator) + "^" + orderText(order);
}

std::string legendLabel(Integrator integrator, double order) {
  std::string label = integratorName(integrator);
  if (std::isnan(order)) return label;
  return label + ": error \u221d " + fittedAgainst(integrator) + "^{" + orderText(order) + "}";
}

std::string speedAgainstOwn(double ownSeconds, double seconds) {
  const double ratio = ownSeconds / seconds;
  if (std::fmax(ratio, 1 / ratio) <= 1 + kSameSpeedWithin)
    return "the same speed as the world's own";
  if (ratio > 1) return ratioText(ratio) + " times as fast as the world's own";
  return "takes " + ratioText(1 / ratio) + " times as long as the world's own";
}

std::string settingText(const ReportRow& row) {
  std::string text = std::string(integratorName(row.integrator)) + " dt=" + exactNumber(row.dt);
  if (row.integrator != Integrator::RK45) return text;
  const Tolerances& t = row.tolerances;
  if (t.rtol == t.atol) return text + " rtol=atol=" + exactNumber(t.rtol);
  return text + " rtol=" + exactNumber(t.rtol) + " atol=" + exactNumber(t.atol);
}

bool worldFileHolds(const ReportRow& row) {
  const Tolerances defaults;
  return row.integrator != Integrator::RK45 ||
         (row.tolerances.rtol == defaults.rtol && row.tolerances.atol == defaults.atol);
}

std::vector<std::string> runCommand(const std::string& worldPath, const ReportRow& row) {
  std::vector<std::string> words = {kJelloProgram, "--integrator", integratorName(row.integrator),
                                    "--dt", exactNumber(row.dt)};
  if (!worldFileHolds(row)) {
    words.insert(words.end(), {"--rtol", exactNumber(row.tolerances.rtol), "--atol",
                               exactNumber(row.tolerances.atol)});
  }
  words.push_back(worldWord(worldPath));
  return words;
}

std::vector<std::string> worldFileCommand(const std::string& worldPath, const ReportRow& row) {
  if (!worldFileHolds(row)) return {};
  return {kCreateWorldProgram,
          "--from",
          worldWord(worldPath),
          "--integrator",
          integratorName(row.integrator),
          "--dt",
          exactNumber(row.dt),
          "-o",
          worldFileFor(worldPath, row.integrator)};
}

std::string shellWord(const std::string& word) {
  bool plain = !word.empty();
  for (char c : word) plain = plain && plainInShell(c);
  if (plain) return word;
  std::string quoted = "'";
  for (char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

std::string shellLine(const std::vector<std::string>& words) {
  std::string line;
  for (const std::string& word : words) line += (line.empty() ? "" : " ") + shellWord(word);
  return line;
}

}  // namespace jello
