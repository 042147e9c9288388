// cli.h: CLI11 validators shared by jello and createWorld. CLI11's own number checks let
// "inf" and "nan" through; a world's numbers must be finite.
#pragma once

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <string>

namespace jello {

// A validator for finite numbers that also pass `accept`, described by `rule` ("> 0").
template <class Accept>
CLI::Validator finiteNumber(const std::string& rule, Accept accept) {
  return CLI::Validator(
      [rule, accept](std::string& text) -> std::string {
        double value = 0;
        if (!CLI::detail::lexical_cast(text, value) || !std::isfinite(value) || !accept(value)) {
          return "must be a finite number" + (rule.empty() ? std::string() : " " + rule) + ", got " + text;
        }
        return {};
      },
      rule.empty() ? "finite" : rule);
}

inline const CLI::Validator kFinite = finiteNumber("", [](double) { return true; });
inline const CLI::Validator kPositive = finiteNumber("> 0", [](double v) { return v > 0; });
inline const CLI::Validator kNonNegative = finiteNumber(">= 0", [](double v) { return v >= 0; });

// Parses the command line. --help and --version print and set *status to 0; an error prints
// one line "NAME: what (see NAME --help)" and sets *status to 2. Returns true when the program
// should go on.
inline bool parseCommandLine(CLI::App& app, int argc, char** argv, int* status) {
  try {
    app.parse(argc, argv);
    return true;
  } catch (const CLI::CallForHelp& e) {
    *status = app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    *status = app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "%s: %s (see %s --help)\n", app.get_name().c_str(), e.what(), app.get_name().c_str());
    *status = 2;
  }
  return false;
}

}  // namespace jello
