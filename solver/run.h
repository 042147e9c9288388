// solver/run.h: a run as the command lines ask for it, and its loading: the world file or scene
// file read, the command line's overrides applied.
#pragma once

#include <optional>
#include <string>

#include "core/outcome.h"
#include "io/input.h"
#include "model/model.h"
#include "solver/integrators.h"

namespace jello {

// What the command line asks of a run; unset values come from the world file.
struct RunOptions {
  std::string worldPath;
  bool worldDefaulted = false;     // no WORLD was named: worldPath is jello's default
  std::optional<long long> steps;  // --steps N
  std::optional<double> time;      // --time T, seconds
  std::optional<Integrator> integrator;
  std::optional<double> dt;  // s
  std::optional<int> n;
  std::optional<std::string> dumpPath;              // --dump FILE
  std::optional<std::string> saveStatePath;         // --save-state FILE (io/statefile.h)
  Tolerances tolerances;                            // RK45's error control
  KernelChoice kernel = KernelChoice::Specialised;  // --kernel general: every term at every point
  int threads = 1;  // --threads N: the most threads a run shares its evaluations between
};

// Reads the world of `options` and applies its overrides. Fails, saying why, on bad input; a
// default world that is missing is said to be the default, with how to name one.
Outcome loadRun(const RunOptions& options, WorldFile* out);

}  // namespace jello
