// commandline.h: jello's command line (README: Running), parsed into what the program is to do
// and checked, with no world read and nothing simulated: main() acts on the result, and the
// command-line fuzz target (fuzz/fuzz_command_line.cpp) parses arbitrary argument lists with it.
#pragma once

#include <string>

#include "analysis/report.h"
#include "app/headless.h"
#include "app/pictures.h"

namespace jello {

constexpr const char* kDefaultWorld = "world/rotate.w";
constexpr double kDefaultMapTime = 0.1;  // s: each observed run of --check --map

struct JelloCommand {
  enum class Mode { Run, Check, Map, Report, Bench, Static, Materials };
  Mode mode = Mode::Run;
  RunOptions run;            // the world, its overrides, --dump, RK45's tolerances
  PictureOptions pictures;   // --frames, --size, --max-frames, --overwrite
  bool framesGiven = false;  // --frames named a folder
  bool headless = false;
  ReportOptions report;  // Mode::Report
  bool json = false;     // Mode::Check
  std::string mapDir;    // Mode::Map
  double mapTime = kDefaultMapTime;
  double maxMemoryGB = 0;  // --max-memory: 0 for the machine's own figures
};

// What parsing came to: go on with *command filled in, or stop with `outcome`: succeeded once
// --help or --version is printed, failed with the one line that refuses an argument (which the
// caller prints: the parser prints only what was asked for, on stdout).
struct ParsedCommand {
  bool goOn = false;
  Outcome outcome;
};
ParsedCommand parseJelloCommandLine(int argc, const char* const* argv, JelloCommand* command);

}  // namespace jello
