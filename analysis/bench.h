// bench.h: `jello --bench WORLD`: what a step costs on this machine, for every integrator, with
// the force kernel specialised for the world's scene and with the general one.
#pragma once

#include "solver/run.h"

namespace jello {

// Times force evaluations and steps from the world's initial state at its dt (or the run's
// overrides); prints a table on stdout and says how it went (outcome.h). With run.steps set, every
// timing runs that many steps (or evaluations) instead of about kBenchSeconds' worth.
Outcome runBench(const RunOptions& run);

constexpr double kBenchSeconds = 0.03;  // per timed repeat
constexpr int kBenchRepeats = 7;        // the median of these is reported

// "Intel(R) Xeon(R) Processor, 2 cores, g++ 12.2.0": where a figure was measured.
std::string machineDescription();

}  // namespace jello
