// cli.h: CLI11 validators shared by jello and createWorld.
//
// Numbers on the command line follow the world files' grammar (parseWorldNumber): CLI11's own
// conversion takes hex, "inf" and "nan", clamps whole numbers that are too large, and reads a
// double through long double, which can round differently from the file reader. So every
// number option is a `transform`: the text is read with the world's grammar and handed on to
// CLI11 in a form it converts exactly (a hexadecimal double, or canonical decimal digits).
#pragma once

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/nearest.h"
#include "core/outcome.h"
#include "core/output.h"
#include "io/input.h"
#include "model/world.h"

namespace jello {

// A validator for finite numbers that also pass `accept`, described by `rule` ("> 0").
// Attach with ->transform(), not ->check(): it rewrites the text.
template <class Accept>
CLI::Validator finiteNumber(const std::string& rule, Accept accept) {
  return CLI::Validator(
      [rule, accept](std::string& text) -> std::string {
        double value = 0;
        std::string why;
        if (!parseWorldNumber(text, &value, &why)) return "'" + text + "' " + why;
        if (!accept(value)) return "must be " + rule + ", got " + text;
        char exact[40];
        std::snprintf(exact, sizeof exact, "%a", value);  // strtold reads it back exactly
        text = exact;
        return {};
      },
      rule.empty() ? "NUMBER" : "NUMBER " + rule);
}

inline const CLI::Validator kFinite = finiteNumber("", [](double) { return true; });
inline const CLI::Validator kPositive = finiteNumber("> 0", [](double v) { return v > 0; });
inline const CLI::Validator kNonNegative = finiteNumber(">= 0", [](double v) { return v >= 0; });

// A whole number from `lowest` to `highest`. Attach with ->transform().
inline CLI::Validator wholeNumber(long long lowest, long long highest) {
  const std::string rule = "from " + std::to_string(lowest) + " to " + std::to_string(highest);
  return CLI::Validator(
      [lowest, highest, rule](std::string& text) -> std::string {
        long long value = 0;
        std::string why;
        if (!parseWorldInteger(text, &value, &why)) return "'" + text + "' " + why;
        if (value < lowest || value > highest)
          return "must be a whole number " + rule + ", got " + text;
        text = std::to_string(value);
        return {};
      },
      "INTEGER " + rule);
}

// A non-empty text (a file or folder name): an empty name is refused, not ignored.
inline const CLI::Validator kNonEmpty = CLI::Validator(
    [](std::string& text) -> std::string { return text.empty() ? "an empty name" : std::string(); },
    "");

// The option of `app` a mistyped `name` most likely meant ("--step" -> "--steps"), or ""
// (core/nearest.h).
inline std::string nearestOption(const CLI::App& app, const std::string& name) {
  std::vector<std::string> names;
  for (const CLI::Option* option : app.get_options())
    for (const std::string& longName : option->get_lnames()) names.push_back("--" + longName);
  return nearestName(name, names);
}

// The line for arguments nobody asked for: an unknown option is named, with the option it most
// likely meant; anything else is CLI11's own line.
inline std::string extrasMessage(const CLI::App& app, const CLI::ExtrasError& e) {
  for (const std::string& extra : app.remaining()) {
    if (extra.size() < 2 || extra[0] != '-') continue;
    const std::string name = extra.substr(0, extra.find('='));
    const std::string meant = nearestOption(app, name);
    return name + ": no such option" +
           (meant.empty() ? std::string() : "; did you mean " + meant + "?");
  }
  return e.what();
}

// The words that say --help or --version was answered: parseCommandLine's outcome then.
constexpr const char* kAnswered = "answered";

// Parses the command line: succeeded() (no message) when the program should go on; after
// printing --help or --version on stdout, succeeded(kAnswered); on an error, failed with one line
// "what (see NAME --help)" for the caller to print.
inline Outcome parseCommandLine(CLI::App& app, int argc, const char* const* argv) {
  try {
    app.parse(argc, argv);
    return succeeded();
  } catch (const CLI::CallForHelp& e) {
    app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    app.exit(e);
  } catch (const CLI::ExtrasError& e) {
    return failed(extrasMessage(app, e) + " (see " + app.get_name() + " --help)");
  } catch (const CLI::ParseError& e) {
    return failed(std::string(e.what()) + " (see " + app.get_name() + " --help)");
  }
  return succeeded(kAnswered);
}

}  // namespace jello
