// commandline.cpp: jello's options, their rules and how they combine.

#include "app/commandline.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <vector>

#include "app/cli.h"
#include "app/export.h"
#include "core/output.h"
#include "core/threadpool.h"
#include "solver/integrators.h"
#include "solver/simulation.h"

namespace jello {

namespace {

constexpr const char* kVersion = "jello 0.1.0";

// `text` split at each `separator`.
std::vector<std::string> splitAt(const std::string& text, char separator) {
  std::vector<std::string> parts(1);
  for (char c : text) {
    if (c == separator)
      parts.emplace_back();
    else
      parts.back() += c;
  }
  return parts;
}

// "WxH" within the renderer's limits, each a whole number in the world files' grammar (no
// sign, no hexadecimal, no blank).
bool parseSize(const std::string& text, int* width, int* height) {
  std::vector<std::string> parts = splitAt(text, 'x');
  if (parts.size() != 2) parts = splitAt(text, 'X');
  long long w = 0, h = 0;
  std::string why;
  if (parts.size() != 2 || parts[0].find_first_not_of("0123456789") != std::string::npos ||
      parts[1].find_first_not_of("0123456789") != std::string::npos ||
      !parseWorldInteger(parts[0], &w, &why) || !parseWorldInteger(parts[1], &h, &why))
    return false;
  if (w < kMinPictureSize || h < kMinPictureSize || w > kMaxPictureSize || h > kMaxPictureSize)
    return false;
  *width = static_cast<int>(w);
  *height = static_cast<int>(h);
  return true;
}

// "AZ,EL" or "AZ,EL,DIST": degrees, degrees, metres, numbers in the world files' grammar,
// within the camera's range.
bool parseCamera(const std::string& text, CameraRequest* camera) {
  CameraRequest c;
  const std::vector<std::string> parts = splitAt(text, ',');
  double* values[3] = {&c.azimuth, &c.elevation, &c.distance};
  std::string why;
  if (parts.size() != 2 && parts.size() != 3) return false;
  for (std::size_t n = 0; n < parts.size(); ++n) {
    if (parts[n].empty() || parts[n][0] == '+' || !parseWorldNumber(parts[n], values[n], &why))
      return false;
  }
  if (!(std::fabs(c.elevation) <= kMostCameraElevation)) return false;
  if (parts.size() == 3 && !(c.distance >= kMinCameraDistance && c.distance <= kMaxCameraDistance))
    return false;
  *camera = c;
  return true;
}

// The index of `name` in kColouringNames, any case; -1 for none.
int colouringIndex(std::string name) {
  for (char& ch : name) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  for (int i = 0; i < kColouringCount; ++i)
    if (name == kColouringNames[i]) return i;
  return -1;
}

// The argument refused, in one line (main prints it).
Outcome refuse(const std::string& message) { return failed(message); }

}  // namespace

namespace {

// The values of the options that are checked or converted after parsing, and which were given.
struct Given {
  std::string integrator, dump, saveState, kernel, size, integrators, exportFormat, camera,
      colouring;
  long long steps = 0, threads = 1;
  double time = 0, dt = 0;
  int n = 0;
  CLI::Option* saveStateOption = nullptr;
  CLI::Option *stepsOption, *timeOption, *integratorOption, *dtOption, *nOption, *dumpOption,
      *kernelOption, *threadsOption;
  CLI::Option *framesOption, *sizeOption, *reportOption, *integratorsOption, *toleranceOption,
      *checkOption;
  CLI::Option *jsonOption, *mapOption, *benchOption, *fpsOption, *worldOption;
  CLI::Option *staticOption, *compareOption;
  CLI::Option *exportOption, *exportFormatOption, *cameraOption, *colouringOption;
};

void addRunOptions(CLI::App& app, JelloCommand* c, Given* g) {
  g->worldOption = app.add_option("WORLD", c->run.worldPath,
                                  "world file (.w), or scene file (.toml: docs/scenes.md)")
                       ->check(kNonEmpty);
  app.add_flag("--headless", c->headless, "run without a window");
  g->stepsOption =
      app.add_option("--steps", g->steps,
                     "steps to run (default: headless 300 frames of n steps, the window without "
                     "end); the window pauses there, p runs on")
          // At most kMaxSteps, as --time is: a run of 2^63 steps would never end.
          ->transform(wholeNumber(0, static_cast<long long>(kMaxSteps)));
  g->timeOption = app.add_option("--time", g->time,
                                 "simulated seconds to run; the window pauses there, p runs on")
                      ->transform(kPositive);
  g->stepsOption->excludes(g->timeOption);
  g->integratorOption = app.add_option("--integrator", g->integrator,
                                       integratorNameList() +
                                           ", any case (overrides the world file; see Integrators "
                                           "below)")
                            ->type_name("NAME");
  g->dtOption = app.add_option("--dt", g->dt, "time step in seconds (overrides the world file)")
                    ->transform(kPositive);
  g->nOption = app.add_option("--n", g->n, "steps per drawn frame (overrides the world file)")
                   ->transform(wholeNumber(1, kMostStepsPerFrame));
  g->dumpOption =
      app.add_option(
             "--dump", g->dump,
             "write the final state as a world file (creates FILE, or replaces a regular file "
             "FILE; never the world being run)")
          ->check(kNonEmpty);
  g->saveStateOption =
      app.add_option("--save-state", g->saveState,
                     "write every body's final points (positions, velocities) as a state file, "
                     "CSV, that a scene's state = \"FILE\" starts from (creates FILE, or "
                     "replaces a regular file FILE)")
          ->check(kNonEmpty);
  g->kernelOption =
      app.add_option(
             "--kernel", g->kernel,
             "the force kernel of a headless run: specialised (default: only what the world "
             "needs) or general (every term at every point, for checking and timing)")
          ->check(CLI::IsMember({"specialised", "general"}));
  g->threadsOption =
      app.add_option("--threads", g->threads,
                     "the most threads a run shares each force evaluation between (default: the "
                     "cores available); a body gets one for each " +
                         std::to_string(kPointsPerThread) +
                         " points at most, as measured faster, with the same results bit for bit")
          ->transform(wholeNumber(1, kMostThreads));
  app.add_option(
         "--max-memory", c->maxMemoryGB,
         "the memory this run may use, GB (default: the machine's, or its cgroup's limit); a world "
         "needing more is refused before it is read")
      ->type_name("GB")
      ->transform(kPositive);
  app.add_option("--rtol", c->run.tolerances.rtol, "RK45's relative tolerance (default 1e-6)")
      ->transform(kPositive);
  app.add_option("--atol", c->run.tolerances.atol, "RK45's absolute tolerance (default 1e-9)")
      ->transform(kPositive);
}

void addPictureOptions(CLI::App& app, JelloCommand* c, Given* g) {
  g->framesOption =
      app.add_option("--frames", c->pictures.framesDir,
                     "save JPEG frames DIR/0000.jpg, 0001.jpg, ... (--fps a simulated second)")
          ->check(kNonEmpty);
  g->fpsOption =
      app.add_option("--fps", c->pictures.fps,
                     "frames saved per simulated second, with --frames or the window's "
                     "recording (default 30); 0: one per drawn frame, every n steps, as the "
                     "course's viewer")
          ->transform(
              finiteNumber("from 0 to 1e6", [](double v) { return v >= 0 && v <= kMaxFps; }));
  app.add_option("--max-frames", c->pictures.maxFrames,
                 "save at most this many frames (default 300)")
      ->transform(wholeNumber(1, kMaxFrames));
  g->sizeOption = app.add_option("--size", g->size, "picture size WxH (default 640x480)");
  g->cameraOption =
      app.add_option("--camera", g->camera,
                     "where the pictures' camera starts: AZIMUTH,ELEVATION[,DISTANCE] "
                     "in degrees and metres (default 30,30,6; up is against gravity)")
          ->type_name("AZ,EL[,D]");
  g->colouringOption = app.add_option("--colouring", g->colouring,
                                      "the surface's colouring in the pictures: plain (default), "
                                      "strain, force, stress or friction (the window's c "
                                      "cycles them)")
                           ->type_name("NAME");
  app.add_flag("--overwrite", c->pictures.overwrite,
               "replace the frames, the exported meshes (or the report) a folder already holds");
  g->exportOption =
      app.add_option("--export", c->pictures.exportDir,
                     "write the cube's surface mesh with normals at every saved frame's step: "
                     "DIR/0000.obj, 0001.obj, ... numbered like the frames (metres, z up)")
          ->type_name("DIR")
          ->check(kNonEmpty);
  g->exportFormatOption =
      app.add_option("--export-format", g->exportFormat,
                     "with --export: obj (Wavefront, the default), ply (ASCII) or vtu (VTK XML "
                     "for ParaView: a jelly of elements whole, with its stress)")
          ->type_name("FORMAT");
}

void addAnalysisOptions(CLI::App& app, JelloCommand* c, Given* g) {
  g->reportOption =
      app.add_option(
             "--report", c->report.dir,
             "error against run time for the world into DIR (CSV, plot, summary), then exit")
          ->type_name("DIR")
          ->check(kNonEmpty);
  g->integratorsOption =
      app.add_option("--integrators", g->integrators,
                     "with --report: the integrators to study, e.g. EULER,RK4 (default all)")
          ->type_name("LIST");
  g->toleranceOption = app.add_option("--tolerance", c->report.visualTolerance,
                                      "with --report: the visual tolerance, m RMS (default 1e-4)")
                           ->transform(kPositive);
  g->checkOption = app.add_flag(
      "--check",
      "stability analysis: the largest stable dt of every integrator, and a verdict on "
      "the world's own; then exit");
  g->jsonOption =
      app.add_flag("--json", c->json, "with --check: print the analysis as one JSON object");
  g->mapOption =
      app.add_option(
             "--map", c->mapDir,
             "with --check: kElastic against dt, predicted and observed stable regions, into "
             "DIR (CSV, plot)")
          ->type_name("DIR")
          ->check(kNonEmpty);
  g->staticOption = app.add_flag(
      "--static",
      "the body at rest under its forces (Newton's method with the exact stiffness): how far it "
      "sags; with --save-state FILE, the state at rest; then exit");
  g->compareOption = app.add_flag(
      "--compare-materials",
      "a jelly of finite elements against the springs fitted to its material, each at the "
      "scene's spacing and at half of it, with errors against the elements at half the spacing "
      "and run times (--time T, default 1 s); then exit");
  g->benchOption = app.add_flag(
      "--bench",
      "microseconds per step of every integrator and force evaluations per second, with "
      "the kernel specialised for the world and the general one; then exit (--steps N: "
      "time N steps, not ~30 ms' worth)");
}

// The integrators of --integrators, comma-separated.
// Each at most once: a name given twice would be studied twice (RK4 given 1000 times ran on).
Outcome readIntegratorList(const std::string& list, std::vector<Integrator>* out) {
  if (list.empty()) return refuse("--integrators: an empty list (leave the option out for all)");
  std::stringstream names(list);
  for (std::string name; std::getline(names, name, ',');) {
    Integrator chosen;
    if (!parseIntegratorName(name, &chosen))
      return refuse("--integrators: unknown integrator '" + name + "', expected " +
                    integratorNameList());
    if (std::find(out->begin(), out->end(), chosen) != out->end())
      return refuse("--integrators: " + std::string(integratorName(chosen)) + " given twice");
    out->push_back(chosen);
  }
  return succeeded();
}

// At most one command; --static and --compare-materials, with what they take.
Outcome oneCommand(const Given& g, JelloCommand* c) {
  if ((*g.checkOption ? 1 : 0) + (*g.reportOption ? 1 : 0) + (*g.benchOption ? 1 : 0) +
          (*g.staticOption ? 1 : 0) + (*g.compareOption ? 1 : 0) >
      1)
    return refuse(
        "--check, --report, --bench, --static and --compare-materials are each a command of its "
        "own: give one");
  if ((*g.staticOption || *g.compareOption) && (*g.framesOption || *g.stepsOption))
    return refuse(std::string(*g.staticOption ? "--static" : "--compare-materials") +
                  " takes no --frames or --steps");
  if (*g.staticOption && *g.timeOption) return refuse("--static takes no --time: it has none");
  if (*g.staticOption) c->mode = JelloCommand::Mode::Static;
  if (*g.compareOption) c->mode = JelloCommand::Mode::Materials;
  return succeeded();
}

// The mode, from the options that choose one, and the options that go only with one mode.
Outcome chooseMode(const Given& g, JelloCommand* c) {
  if (*g.mapOption && !*g.checkOption) return refuse("--map goes with --check");
  if (*g.jsonOption && !*g.checkOption) return refuse("--json goes with --check");
  if (*g.jsonOption && *g.mapOption)
    return refuse("--json goes with --check alone, not with --map");
  if (*g.integratorsOption && !*g.reportOption) return refuse("--integrators goes with --report");
  if (*g.toleranceOption && !*g.reportOption) return refuse("--tolerance goes with --report");
  const bool analysis =
      *g.benchOption || *g.checkOption || *g.reportOption || *g.staticOption || *g.compareOption;
  if (*g.fpsOption && (analysis || (c->headless && !*g.framesOption && !*g.exportOption)))
    return refuse("--fps goes with --frames or --export (or the window, where space records)");
  if ((*g.cameraOption || *g.colouringOption) && (analysis || (c->headless && !*g.framesOption)))
    return refuse(std::string(*g.cameraOption ? "--camera" : "--colouring") +
                  " goes with --frames or the window, where pictures are drawn");
  if (*g.exportOption && analysis)
    return refuse(
        "--export goes with a run (headless or the window), not with --check, --report "
        "or --bench");
  // Each analysis writes what it names, nothing else: an option that would be ignored is
  // refused (--check --dump F, --bench --report D, --report --dump F ran and wrote nothing).
  if (*g.dumpOption && analysis)
    return refuse(
        "--dump goes with a run (headless or the window), not with --check, --report "
        "or --bench");
  if (*g.saveStateOption && analysis && !*g.staticOption)
    return refuse(
        "--save-state goes with a headless run or --static, not with --check, --report, --bench "
        "or --compare-materials");
  if (*g.saveStateOption && !c->headless && !*g.staticOption)
    return refuse("--save-state goes with --headless (the window writes no state at its end)");
  if (*g.framesOption && (*g.checkOption || *g.benchOption))
    return refuse("--frames goes with a run (headless or the window), not with --check or --bench");
  if (Outcome one = oneCommand(g, c); !one.ok()) return one;
  if (c->mode != JelloCommand::Mode::Run) return succeeded();
  if (*g.benchOption)
    c->mode = JelloCommand::Mode::Bench;
  else if (*g.checkOption)
    c->mode = *g.mapOption ? JelloCommand::Mode::Map : JelloCommand::Mode::Check;
  else if (*g.reportOption)
    c->mode = JelloCommand::Mode::Report;
  if (c->mode == JelloCommand::Mode::Report) {
    if (*g.stepsOption || *g.framesOption)
      return refuse("--report runs to --time T (default 1 s); it takes no --steps or --frames");
    if (*g.timeOption) c->report.time = g.time;
    c->report.overwrite = c->pictures.overwrite;
    return *g.integratorsOption ? readIntegratorList(g.integrators, &c->report.integrators)
                                : succeeded();  // none given: all
  }
  if (c->mode == JelloCommand::Mode::Map && *g.timeOption) c->mapTime = g.time;
  return succeeded();
}

// The pictures' camera and colouring, once parsed.
Outcome readViewOptions(const Given& g, JelloCommand* c) {
  if (*g.cameraOption) {
    CameraRequest camera;
    if (!parseCamera(g.camera, &camera))
      return refuse(
          textf("--camera: expected AZIMUTH,ELEVATION[,DISTANCE] (degrees, elevation "
                "within +-%g; metres from %g to %g), got '%s'",
                kMostCameraElevation, kMinCameraDistance, kMaxCameraDistance, g.camera.c_str()));
    c->pictures.camera = camera;
  }
  if (*g.colouringOption) {
    c->pictures.colouring = colouringIndex(g.colouring);
    if (c->pictures.colouring < 0)
      return refuse("--colouring: unknown colouring '" + g.colouring +
                    "', expected plain, strain, force, stress or friction");
  }
  return succeeded();
}

// The run's overrides, once parsed.
Outcome readRunOptions(const Given& g, JelloCommand* c) {
  RunOptions& run = c->run;
  if (*g.integratorOption) {
    Integrator chosen;
    if (!parseIntegratorName(g.integrator, &chosen))
      return refuse("--integrator: unknown integrator '" + g.integrator + "', expected " +
                    integratorNameList());
    run.integrator = chosen;
  }
  if (*g.kernelOption && g.kernel == "general") run.kernel = KernelChoice::General;
  run.threads =
      *g.threadsOption ? static_cast<int>(g.threads) : std::min(availableCores(), kMostThreads);
  if (*g.stepsOption) run.steps = g.steps;
  if (*g.timeOption) run.time = g.time;
  if (*g.dtOption) run.dt = g.dt;
  if (*g.nOption) run.n = g.n;
  if (*g.dumpOption) run.dumpPath = g.dump;
  if (*g.saveStateOption) run.saveStatePath = g.saveState;
  run.worldDefaulted = g.worldOption->count() == 0;
  c->framesGiven = g.framesOption->count() > 0;
  if (*g.exportFormatOption && !*g.exportOption)
    return refuse("--export-format goes with --export DIR");
  if (*g.exportFormatOption && !parseMeshFormat(g.exportFormat, &c->pictures.exportFormat))
    return refuse("--export-format: unknown format '" + g.exportFormat +
                  "', expected obj, ply or vtu");
  if (*g.sizeOption && !parseSize(g.size, &c->pictures.width, &c->pictures.height))
    return refuse("--size: expected WxH with sides from " + std::to_string(kMinPictureSize) +
                  " to " + std::to_string(kMaxPictureSize) + " pixels, got '" + g.size + "'");
  return readViewOptions(g, c);
}

}  // namespace

ParsedCommand parseJelloCommandLine(int argc, const char* const* argv, JelloCommand* command) {
  *command = JelloCommand{};
  command->run.worldPath = kDefaultWorld;
  CLI::App app{"jello: the jello cube simulator. Runs WORLD (default " +
                   std::string(kDefaultWorld) + ") in the viewer, or headless.",
               "jello"};
  app.set_version_flag("--version", kVersion);
  Given given;
  addRunOptions(app, command, &given);
  addPictureOptions(app, command, &given);
  addAnalysisOptions(app, command, &given);
  app.footer("Integrators (--integrator, --integrators, and world files):\n" + integratorHelp());
  const Outcome parsed = parseCommandLine(app, argc, argv);
  if (!parsed.ok()) return {false, parsed};
  if (parsed.message == kAnswered) return {false, succeeded()};
  Outcome read = readRunOptions(given, command);
  if (read.ok()) read = chooseMode(given, command);
  return {read.ok(), read};
}

}  // namespace jello
