// outcome.h: what a command of the library came to (a headless run, a report, a stability map,
// a bench, the viewer), as a value. The library prints its results on stdout, but it never
// prints an error line, calls exit or chooses an exit status: the mains of jello.cpp and
// createWorld.cpp alone turn an Outcome into the line on stderr (printError, output.h) and the
// exit status (README: 0 success, 1 diverged, 2 bad input or usage).
#pragma once

#include <string>
#include <utility>

namespace jello {

// How a command ended (not named Status: X11 defines that as a macro).
enum class Ending {
  Ok,        // done as asked
  Diverged,  // the simulation the command needed diverged: exit status 1
  Failed,    // bad input or usage, or an output that cannot be written: exit status 2
};

struct Outcome {
  Ending status = Ending::Ok;
  // The one line main prints on stderr, without the program's name: why the command failed,
  // or, with Ending::Ok, what it left undone (a picture not drawn without gnuplot). "" when
  // there is nothing to say (success; a window that showed its message as it happened).
  std::string message;

  bool ok() const { return status == Ending::Ok; }
};

inline Outcome succeeded(std::string note = {}) { return {Ending::Ok, std::move(note)}; }
inline Outcome failed(std::string message) { return {Ending::Failed, std::move(message)}; }
inline Outcome diverged(std::string message) { return {Ending::Diverged, std::move(message)}; }

}  // namespace jello
