// headless.h: a simulation run without a window (SPEC.md section 4).
#pragma once

#include <optional>
#include <string>

#include "world.h"

namespace jello {

// What the command line asks of a headless run; unset values come from the world file.
struct RunOptions {
  std::string worldPath;
  std::optional<long long> steps;  // --steps N
  std::optional<double> time;      // --time T, seconds
  std::optional<Integrator> integrator;
  std::optional<double> dt;  // s
  std::optional<int> n;
  std::string dumpPath;  // empty: no dump
};

// Exit statuses of SPEC.md section 4.
constexpr int kExitOk = 0;
constexpr int kExitDiverged = 1;
constexpr int kExitBadInput = 2;

// The default length of a headless run: 300 drawn frames of n steps each.
constexpr long long kDefaultFrames = 300;

// Number of steps that --time T asks for at step dt: the fewest that reach T (a relative slack
// of 1e-9 keeps T = 1, dt = 0.001 at 1000 steps despite rounding).
long long stepsForTime(double time, double dt);

// Loads the world, runs it, prints the summary line on stdout (errors on stderr, one line each)
// and returns the exit status.
int runHeadless(const RunOptions& options);

}  // namespace jello
