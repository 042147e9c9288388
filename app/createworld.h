// app/createworld.h: the createWorld program's command (README: createWorld): a world built from
// a recipe and the options, checked and written, or a world described.
#pragma once

#include "core/outcome.h"

namespace jello {

// Parses argv and does what it says: writes the world (printing "wrote FILE: ..." on stdout),
// prints --describe's description, or --help. Says how it went; the caller prints a failure's
// line and chooses the exit status. Warnings about a world that will run, though perhaps not as
// meant, go to stderr as they are found, each "createWorld: warning: ...".
Outcome createWorldCommand(int argc, const char* const* argv);

}  // namespace jello
