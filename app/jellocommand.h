// app/jellocommand.h: the jello program's commands (README: Running): a run in the window or
// headless, --check (and --map), --report and --bench, each saying how it went as an Outcome.
#pragma once

#include "app/commandline.h"
#include "core/outcome.h"

namespace jello {

// Does what `command` says. Results go to stdout (and the files asked for); a failure's line is
// the outcome's, for the caller to print.
Outcome runJelloCommand(const JelloCommand& command);

// Parses argv (commandline.h) and runs the command, or answers --help and --version.
Outcome jelloCommand(int argc, const char* const* argv);

}  // namespace jello
