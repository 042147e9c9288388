// reportwords.cpp: the words of jello --report that a user acts on: settings, speeds, the
// legend, and the commands that run or keep a recommended setting (report.h).

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <string_view>
#include <vector>

#include "analysis/report.h"
#include "core/output.h"
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

// world/rotate.w, MIDPOINT and dt 0.00078125, reported into out/:
// out/rotate-midpoint-dt0.00078125.w, in the report's folder (never beside the world: that may be
// the project's own world/): each recommended setting a name of its own (two of one integrator once
// shared one).
std::string worldFileFor(const std::string& worldPath, const std::string& reportDir,
                         Integrator integrator, const std::string& dt) {
  const std::size_t slash = worldPath.rfind('/');
  std::string stem = worldPath.substr(slash == std::string::npos ? 0 : slash + 1);
  const std::size_t dot = stem.rfind('.');
  if (dot != std::string::npos && dot > 0) stem.erase(dot);
  std::string name = integratorName(integrator);
  for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return worldWord(reportDir + "/" + stem + "-" + name + "-dt" + dt + ".w");
}

// The characters no POSIX shell gives a meaning to within a word.
bool plainInShell(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) ||
         std::string_view("_-./:=@%+,").find(c) != std::string_view::npos;
}

// "the plane", "the walls and the plane".
std::string surfacesText(const std::vector<std::string>& touched) {
  std::string text;
  for (std::size_t i = 0; i < touched.size(); ++i)
    text += (i == 0 ? "" : i + 1 == touched.size() ? " and " : ", ") + ("the " + touched[i]);
  return text.empty() ? "a wall or the plane" : text;
}

// "41%", or "under 1%" for a contact of a few steps.
std::string shareText(long long part, long long whole) {
  const double percent = 100.0 * static_cast<double>(part) / static_cast<double>(whole);
  if (percent < 1) return "under 1%";
  char text[16];
  std::snprintf(text, sizeof text, "%.0f%%", percent);
  return text;
}

// A time just before `t` in two significant digits (0.0312 -> 0.031), for a --time that ends
// before the first contact.
std::string timeBefore(double t) {
  const double unit = std::pow(10.0, std::floor(std::log10(t)) - 1);
  char text[32];
  std::snprintf(text, sizeof text, "%.2g", std::floor(t / unit) * unit);
  return text;
}

// A figure in two significant digits: "1.2e-05", "0.031".
std::string shortNumber(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2g", x);
  return text;
}

// The contact reason of an order warning: where and when, why it matters, what to do.
std::string contactReason(const OrderCheck& c, const ContactActivity& contacts) {
  std::string text = "The cube touched " + surfacesText(contacts.touched) + " during " +
                     shareText(contacts.inContact, contacts.steps) + " of the run";
  if (contacts.firstContact > 0)
    text += ", first at t = " + shortNumber(contacts.firstContact) + " s";
  else
    text += ", from the start";
  text +=
      ". A contact's force switches on abruptly when a point crosses the surface (a kink in the "
      "force, and a jump where the contact has damping), and an integrator keeps its order only "
      "while the forces are smooth: across contacts every integrator does about as well as a "
      "first-order one. This is the physics of the world, not a fault of ";
  text += integratorName(c.integrator);
  if (contacts.firstContact > 0)
    text += std::string(": to see its order, end the report before the first contact, ") +
            "`--time " + timeBefore(contacts.firstContact) + "`";
  return text + ".";
}

}  // namespace

std::string orderWarning(const OrderCheck& c, const ContactActivity& contacts) {
  if (!c.far) return "";
  const std::string name = integratorName(c.integrator), theory = std::to_string(c.theory);
  std::string text = "**" + name + ": " + fittedLaw(c.integrator, c.fitted) +
                     ", where its theory says error \u221d dt^" + theory + ".** " + name +
                     " is most likely not broken; the runs show why its errors do not shrink as "
                     "dt^" +
                     theory + ":\n\n";
  if (c.contacts) text += "- " + contactReason(c, contacts) + "\n";
  if (c.divergedSteps)
    text +=
        "- Some of its largest steps diverged (they are left out of the fit): the steps "
        "swept reach its stability limit, near which the error grows faster than any power "
        "of dt.\n";
  if (c.edgeOfStability)
    text += "- Its largest step, dt = " + exactNumber(c.largestStep) +
            " s, is close to its stability limit, where the error grows faster than dt^" + theory +
            ": without that run the fit is " + fittedLaw(c.integrator, c.withoutLargest) + ".\n";
  if (c.nearReference)
    text += "- Its smallest errors (down to " + shortNumber(c.finestError) + " m) are within " +
            std::to_string(static_cast<int>(kReferenceMargin)) +
            " times the reference's own error (" + shortNumber(c.referenceError) +
            " m): the reference is too coarse a ruler for them, which flattens the line. A "
            "shorter --time lets the reference take finer steps.\n";
  if (!c.contacts && !c.divergedSteps && !c.edgeOfStability && !c.nearReference)
    text +=
        "- None of the usual causes (contacts, steps near the stability limit, the "
        "reference's own error) shows in these runs: the steps swept may still be too large "
        "for the error to follow dt^" +
        theory + ".\n";
  return text;
}

std::string orderWarningLine(const OrderCheck& c, const ContactActivity& contacts) {
  if (!c.far) return "";
  std::vector<std::string> reasons;
  if (c.contacts)
    reasons.push_back("the cube touched " + surfacesText(contacts.touched) + " during " +
                      shareText(contacts.inContact, contacts.steps) +
                      " of the run, and contacts are not smooth");
  if (c.divergedSteps || c.edgeOfStability)
    reasons.push_back("its largest steps are near its stability limit");
  if (c.nearReference) reasons.push_back("its smallest errors are near the reference's own");
  std::string line = std::string(integratorName(c.integrator)) + "'s fitted order is " +
                     orderText(c.fitted) + ", not " + std::to_string(c.theory);
  for (std::size_t i = 0; i < reasons.size(); ++i) line += (i == 0 ? ": " : "; ") + reasons[i];
  return line + " (report.md says more)";
}

std::string exactNumber(double x) {
  char text[32];
  // The general format reads like %g (0.0005, 9.765625e-05), in the fewest digits that read back.
  const std::to_chars_result end =
      std::to_chars(text, text + sizeof text, x, std::chars_format::general);
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

std::vector<std::string> worldFileCommand(const std::string& worldPath,
                                          const std::string& reportDir, const ReportRow& row) {
  if (!worldFileHolds(row)) return {};
  return {kCreateWorldProgram,
          "--from",
          worldWord(worldPath),
          "--integrator",
          integratorName(row.integrator),
          "--dt",
          exactNumber(row.dt),
          "-o",
          worldFileFor(worldPath, reportDir, row.integrator, exactNumber(row.dt))};
}

std::string shellWord(const std::string& word) {
  bool plain = !word.empty();
  for (char c : word) plain = plain && plainInShell(c);
  if (plain) return word;
  // A control character or a byte outside UTF-8 would break the line or reach the terminal as
  // it is, even inside quotes: such a word is written as $'...' with those bytes as \xNN.
  if (printable(word) != word) {
    std::string quoted = "$'";
    for (char c : word) {
      const unsigned char byte = static_cast<unsigned char>(c);
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", byte);
      quoted += c == '\'' || c == '\\'        ? std::string("\\") + c
                : byte < 0x20 || byte >= 0x7f ? std::string(escaped)
                                              : std::string(1, c);
    }
    return quoted + "'";
  }
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
