// jello.cpp: the command line of the simulator (SPEC.md section 4).

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <string>

#include "bench.h"
#include "cli.h"
#include "graphics.h"
#include "headless.h"
#include "report.h"
#include "stability.h"
#include "world.h"

namespace {

constexpr const char* kVersion = "jello 0.1.0";
constexpr const char* kDefaultWorld = "world/rotate.w";

// "WxH" within the renderer's limits.
bool parseSize(const std::string& text, int* width, int* height) {
  int w = 0, h = 0;
  char x = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X')) return false;
  if (w < jello::kMinPictureSize || h < jello::kMinPictureSize || w > jello::kMaxPictureSize ||
      h > jello::kMaxPictureSize)
    return false;
  *width = w;
  *height = h;
  return true;
}

// "world/rotate.w" -> "rotate"
std::string worldStem(const std::string& path) {
  std::size_t slash = path.find_last_of('/');
  std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  std::size_t dot = name.rfind('.');
  return dot == std::string::npos || dot == 0 ? name : name.substr(0, dot);
}

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
  auto* timeOption = app.add_option("--time", time, "simulated seconds to run headless")->check(jello::kPositive);
  stepsOption->excludes(timeOption);
  auto* integratorOption = app.add_option("--integrator", integrator, "EULER, RK4, MIDPOINT, SYMPLECTIC, VERLET, RK45 or IMPLICIT, any case (overrides the world file)");
  auto* dtOption = app.add_option("--dt", dt, "time step in seconds (overrides the world file)")->check(jello::kPositive);
  auto* nOption = app.add_option("--n", n, "steps per drawn frame (overrides the world file)")
                      ->check(CLI::Range(1, std::numeric_limits<int>::max()));
  app.add_option("--dump", run.dumpPath, "write the final state as a world file");
  std::string kernel;
  auto* kernelOption = app.add_option("--kernel", kernel, "the force kernel of a headless run: specialised (default: "
                                                          "only what the world needs) or general (every term at "
                                                          "every point, for checking and timing)")
                           ->check(CLI::IsMember({"specialised", "general"}));

  jello::PictureOptions pictures;
  std::string size;
  auto* framesOption = app.add_option("--frames", pictures.framesDir,
                                      "save JPEG frames DIR/0000.jpg, 0001.jpg, ... one per drawn frame");
  app.add_option("--max-frames", pictures.maxFrames, "save at most this many frames (default 300)")
      ->check(CLI::Range(1, jello::kMaxFrames));
  auto* sizeOption = app.add_option("--size", size, "picture size WxH (default 640x480)");
  app.add_flag("--overwrite", pictures.overwrite, "replace the frames (or the report) a folder already holds");

  jello::ReportOptions report;
  std::string integratorList;
  auto* reportOption =
      app.add_option("--report", report.dir, "error against run time for the world into DIR (CSV, plot, summary), then exit")
          ->type_name("DIR");
  auto* integratorsOption =
      app.add_option("--integrators", integratorList, "with --report: the integrators to study, e.g. EULER,RK4 (default all)")
          ->type_name("LIST");
  app.add_option("--tolerance", report.visualTolerance, "with --report: the visual tolerance, m RMS (default 1e-4)")
      ->check(jello::kPositive);
  app.add_option("--rtol", run.tolerances.rtol, "RK45's relative tolerance (default 1e-6)")->check(jello::kPositive);
  app.add_option("--atol", run.tolerances.atol, "RK45's absolute tolerance (default 1e-9)")->check(jello::kPositive);

  bool json = false;
  auto* checkOption = app.add_flag("--check", "stability analysis: the largest stable dt of every integrator, and "
                                              "a verdict on the world's own; then exit");
  app.add_flag("--json", json, "with --check: print the analysis as one JSON object");
  std::string mapDir;
  auto* mapOption = app.add_option("--map", mapDir, "with --check: kElastic against dt, predicted and observed "
                                                    "stable regions, into DIR (CSV, plot)")
                        ->type_name("DIR");

  auto* benchOption = app.add_flag("--bench", "microseconds per step of every integrator and force evaluations per "
                                              "second, with the kernel specialised for the world and the general "
                                              "one; then exit (--steps N: time N steps, not ~30 ms' worth)");

  int status = 0;
  if (!jello::parseCommandLine(app, argc, argv, &status)) return status;

  if (*integratorOption) {
    jello::Integrator chosen;
    if (!jello::parseIntegratorName(integrator, &chosen)) {
      std::fprintf(stderr, "jello: --integrator: unknown integrator '%s', expected %s\n", integrator.c_str(),
                   jello::integratorNameList().c_str());
      return jello::kExitBadInput;
    }
    run.integrator = chosen;
  }
  if (*kernelOption && kernel == "general") run.kernel = jello::KernelChoice::General;
  if (*stepsOption) run.steps = steps;
  if (*timeOption) run.time = time;
  if (*dtOption) run.dt = dt;
  if (*nOption) run.n = n;

  if (*benchOption) return jello::runBench(run);
  if (*checkOption) {
    jello::WorldFile file;
    if (!jello::loadRun(run, &file)) return jello::kExitBadInput;
    if (*mapOption) {
      return jello::writeStabilityMap(mapDir, run.worldPath, file.world, file.state, *timeOption ? time : 0.1,
                                      pictures.overwrite);
    }
    jello::StabilityReport analysis = jello::analyseStability(file.world, file.state);
    std::fputs((json ? jello::stabilityJson(run.worldPath, file.world, analysis)
                     : jello::stabilityText(run.worldPath, file.world, analysis))
                   .c_str(),
               stdout);
    return jello::kExitOk;
  }

  if (*mapOption && !*checkOption) {
    std::fprintf(stderr, "jello: --map goes with --check\n");
    return jello::kExitBadInput;
  }
  if (*reportOption) {
    if (*stepsOption || *framesOption) {
      std::fprintf(stderr, "jello: --report runs to --time T (default 1 s); it takes no --steps or --frames\n");
      return jello::kExitBadInput;
    }
    if (*timeOption) report.time = time;
    report.overwrite = pictures.overwrite;
    std::stringstream names(integratorList);
    for (std::string name; std::getline(names, name, ',');) {
      jello::Integrator chosen;
      if (!jello::parseIntegratorName(name, &chosen)) {
        std::fprintf(stderr, "jello: --integrators: unknown integrator '%s', expected %s\n", name.c_str(),
                     jello::integratorNameList().c_str());
        return jello::kExitBadInput;
      }
      report.integrators.push_back(chosen);
    }
    return jello::runReport(run, report);
  }
  if (*integratorsOption) {
    std::fprintf(stderr, "jello: --integrators goes with --report\n");
    return jello::kExitBadInput;
  }

  if (*sizeOption && !parseSize(size, &pictures.width, &pictures.height)) {
    std::fprintf(stderr, "jello: --size: expected WxH with sides from %d to %d pixels, got '%s'\n",
                 jello::kMinPictureSize, jello::kMaxPictureSize, size.c_str());
    return jello::kExitBadInput;
  }

  // The pictures' library is loaded only from here on, and only for a window or frames.
  const jello::GraphicsApi* graphics = nullptr;
  std::string why;
  if (!headless) {
    graphics = jello::loadGraphics(&why);
    if (graphics && graphics->displayAvailable(&why)) {
      if (!*framesOption) pictures.framesDir = "animation";
      pictures.saveFromStart = framesOption->count() > 0;
      return graphics->runViewer(run, pictures);
    }
    if (!graphics) {
      std::fprintf(stderr, "jello: %s; running headless\n", why.c_str());
      return jello::runHeadless(run);
    }
    if (!*framesOption) pictures.framesDir = jello::newFramesDir("animation", worldStem(run.worldPath));
    std::fprintf(stderr, "jello: no display (%s); running headless, writing frames into %s/\n", why.c_str(),
                 pictures.framesDir.c_str());
  }
  std::unique_ptr<jello::FrameObserver> frames;
  if (!pictures.framesDir.empty()) {
    if (!graphics) graphics = jello::loadGraphics(&why);
    if (!graphics) {
      std::fprintf(stderr, "jello: --frames: %s, so it cannot render frames\n", why.c_str());
      return jello::kExitBadInput;
    }
    try {
      frames = graphics->makeOffscreenFrames(pictures);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "jello: %s\n", e.what());
      return jello::kExitBadInput;
    }
  }
  return jello::runHeadless(run, frames.get());
}
