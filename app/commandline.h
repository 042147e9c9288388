// commandline.h: jello's command line (README: Running), parsed into what the program is to do
// and checked, with no world read and nothing simulated: main() acts on the result, and the
// command-line fuzz target (fuzz/fuzz_command_line.cpp) parses arbitrary argument lists with it.
#pragma once

#include <string>

#include "app/headless.h"
#include "app/pictures.h"
#include "app/report.h"

namespace jello {

constexpr const char* kDefaultWorld = "world/rotate.w";
constexpr double kDefaultMapTime = 0.1;  // s: each observed run of --check --map

struct JelloCommand {
  enum class Mode { Run, Check, Map, Report, Bench };
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

// The exit status parseJelloCommandLine returns when the program is to go on.
constexpr int kGoOn = -1;

// Parses and checks argv. Returns kGoOn with *command filled in, or the exit status after
// printing --help or --version (0) or one error line (2).
int parseJelloCommandLine(int argc, const char* const* argv, JelloCommand* command);

}  // namespace jello
