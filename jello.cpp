// jello.cpp: the command line of the simulator (SPEC.md section 4).

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "headless.h"
#include "world.h"

namespace {

constexpr const char* kVersion = "jello 0.1.0";
constexpr const char* kDefaultWorld = "world/rotate.w";

// CLI11's PositiveNumber lets "inf" through; a step or a duration must be finite.
const CLI::Validator kFinitePositive(
    [](std::string& text) -> std::string {
      double value = 0;
      if (!CLI::detail::lexical_cast(text, value) || !std::isfinite(value) || !(value > 0)) {
        return "must be a finite number > 0, got " + text;
      }
      return {};
    },
    "> 0");

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"jello: the jello cube simulator. Runs WORLD (default " + std::string(kDefaultWorld) +
                   ") in the viewer, or headless.",
               "jello"};
  app.set_version_flag("--version", kVersion);

  jello::RunOptions run;
  run.worldPath = kDefaultWorld;
  bool headless = false;
  std::string integrator;
  long long steps = 0;
  double time = 0, dt = 0;
  int n = 0;

  app.add_option("WORLD", run.worldPath, "world file (.w)");
  app.add_flag("--headless", headless, "run without a window");
  auto* stepsOption = app.add_option("--steps", steps, "steps to run headless (default 300 frames of n steps)")
                          ->check(CLI::Range(0LL, std::numeric_limits<long long>::max()));
  auto* timeOption = app.add_option("--time", time, "simulated seconds to run headless")->check(kFinitePositive);
  stepsOption->excludes(timeOption);
  auto* integratorOption = app.add_option("--integrator", integrator, "EULER or RK4, any case (overrides the world file)");
  auto* dtOption = app.add_option("--dt", dt, "time step in seconds (overrides the world file)")->check(kFinitePositive);
  auto* nOption = app.add_option("--n", n, "steps per drawn frame (overrides the world file)")
                      ->check(CLI::Range(1, std::numeric_limits<int>::max()));
  app.add_option("--dump", run.dumpPath, "write the final state as a world file");

  // Options of later milestones: recognised, so that a user learns they are coming.
  std::string unused;
  int unusedCount = 0;
  CLI::Option* later[] = {
      app.add_option("--frames", unused, "save JPEG frames into DIR (not available yet)"),
      app.add_option("--max-frames", unusedCount, "at most this many frames (not available yet)"),
      app.add_option("--size", unused, "picture size WxH (not available yet)"),
      app.add_flag("--check", "stability analysis (not available yet)"),
      app.add_option("--report", unused, "error against run time into DIR (not available yet)"),
      app.add_flag("--bench", "benchmark the world (not available yet)"),
  };

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "jello: %s (see jello --help)\n", e.what());
    return jello::kExitBadInput;
  }

  for (CLI::Option* option : later) {
    if (option->count() > 0) {
      std::fprintf(stderr, "jello: %s is not available yet\n", option->get_name().c_str());
      return jello::kExitBadInput;
    }
  }
  if (*integratorOption) {
    jello::Integrator chosen;
    if (!jello::parseIntegratorName(integrator, &chosen)) {
      std::fprintf(stderr, "jello: --integrator: unknown integrator '%s', expected %s\n", integrator.c_str(),
                   jello::integratorNameList().c_str());
      return jello::kExitBadInput;
    }
    run.integrator = chosen;
  }
  if (*stepsOption) run.steps = steps;
  if (*timeOption) run.time = time;
  if (*dtOption) run.dt = dt;
  if (*nOption) run.n = n;

  if (!headless) {
    std::fprintf(stderr, "jello: the viewer is not available yet; running headless\n");
  }
  return jello::runHeadless(run);
}
