// app/jellocommand.cpp: what jello does with its command line (jellocommand.h).

#include "app/jellocommand.h"

#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>

#include "analysis/bench.h"
#include "analysis/materials.h"
#include "analysis/report.h"
#include "analysis/stability.h"
#include "analysis/stabilitymap.h"
#include "app/export.h"
#include "app/graphicsapi.h"
#include "app/headless.h"
#include "core/memory.h"
#include "core/output.h"
#include "io/statefile.h"
#include "solver/statics.h"

namespace jello {

namespace {

Outcome check(const JelloCommand& c) {
  WorldFile file;
  if (Outcome loaded = loadRun(c.run, &file); !loaded.ok()) return loaded;
  if (c.mode == JelloCommand::Mode::Map)
    return writeStabilityMap(c.mapDir, c.run.worldPath, file, c.mapTime, c.pictures.overwrite);
  StabilityReport analysis = analyseStability(file.world, file.state);
  std::fputs((c.json ? stabilityJson(c.run.worldPath, file.run, analysis)
                     : stabilityText(c.run.worldPath, file.run, analysis))
                 .c_str(),
             stdout);
  return succeeded();
}

// jello --static: the body at rest, how far it moved to get there, and its state when asked.
Outcome staticRest(const JelloCommand& c) {
  WorldFile file;
  if (Outcome loaded = loadRun(c.run, &file); !loaded.ok()) return loaded;
  if (c.run.saveStatePath)
    if (const std::string why = whyNotDumpable(*c.run.saveStatePath, c.run.worldPath, file.inputs);
        !why.empty())
      return failed("--save-state " + *c.run.saveStatePath + ": " + why);
  if (findDivergedPoint(file.state) >= 0)  // as a run says it: no Newton step will do either
    return diverged(c.run.worldPath + ": " + kStartBeyondGuard);
  const Model model = makeModel(file.world, file.state);
  const StaticSolution rest = solveStatic(model, file.state);
  const int n = model.points();
  if (!rest.converged || findDivergedPoint(rest.state) >= 0)
    return diverged(c.run.worldPath + ": no rest found near the start after " +
                    std::to_string(rest.steps) + " Newton steps (largest force left " +
                    textf("%.3g", rest.largestForce) +
                    " N): --static looks for a rest from where the body starts; one that must "
                    "fall or swing far to reach it (not yet touching what will hold it) has "
                    "none it can find: run it instead");
  int farthest = 0;
  double moved = 0;
  Vec3 mean;
  for (int q = 0; q < n; ++q) {
    const Vec3 d = load(rest.state.p(), q, n) - load(file.state.p(), q, n);
    mean += (1.0 / n) * d;
    if (length(d) > moved) moved = length(d), farthest = q;
  }
  const Vec3 d = load(rest.state.p(), farthest, n) - load(file.state.p(), farthest, n);
  std::printf("%s: at rest after %d Newton steps (largest force left %.3g N)\n",
              c.run.worldPath.c_str(), rest.steps, rest.largestForce);
  std::printf("  farthest moved: point %s, by %.6g m (%.6g, %.6g, %.6g)\n",
              model.body().label(farthest).c_str(), moved, d.x, d.y, d.z);
  std::printf("  mean displacement of the points: (%.6g, %.6g, %.6g) m\n", mean.x, mean.y, mean.z);
  if (c.run.saveStatePath) {
    writeStateFile(*c.run.saveStatePath, model.body(), rest.state);
    std::printf("  the state at rest in %s\n", c.run.saveStatePath->c_str());
  }
  return succeeded();
}

Outcome materials(const JelloCommand& c) {
  MaterialComparison comparison;
  if (Outcome done = compareMaterials(c.run, &comparison); !done.ok()) return done;
  std::fputs(materialComparisonText(c.run.worldPath, comparison).c_str(), stdout);
  return succeeded();
}

// A headless run with its observers: the frames (rendered by the pictures' library, loaded
// here when `graphics` is not yet) and the meshes of --export.
Outcome runHeadlessWithOutputs(const JelloCommand& c, const GraphicsApi* graphics) {
  std::unique_ptr<FrameObserver> frames, meshes;
  if (!c.pictures.framesDir.empty()) {
    std::string why;
    if (!graphics) graphics = loadGraphics(&why);
    if (!graphics) return failed("--frames: " + why + ", so it cannot render frames");
    frames = graphics->makeOffscreenFrames(c.pictures);
  }
  if (!c.pictures.exportDir.empty())
    meshes = makeMeshExport(c.pictures, c.run.worldPath, c.pictures.framesDir);
  std::unique_ptr<FrameObserver> both = bothObservers(std::move(frames), std::move(meshes));
  return runHeadless(c.run, both.get());
}

// Where a run without a display and without --frames makes its new frames folder.
constexpr const char* kFramesParent = "animation";

// A window where a display exists; otherwise headless, with frames where asked (or, when no
// --headless was given, into a new folder of animation/), and the meshes of --export.
Outcome simulate(JelloCommand c) {
  // The pictures' library is loaded only from here on, and only for a window or frames.
  const GraphicsApi* graphics = nullptr;
  std::string why;
  bool madeFolder = false, madeParent = false;
  if (!c.headless) {
    graphics = loadGraphics(&why);
    if (graphics && graphics->displayAvailable(&why)) {
      if (!c.framesGiven) c.pictures.framesDir = "animation";
      c.pictures.framesNamed = c.framesGiven;
      // --export records from the start as --frames does: the user named a folder to fill.
      c.pictures.saveFromStart = c.framesGiven || !c.pictures.exportDir.empty();
      return graphics->runViewer(c.run, c.pictures);
    }
    if (!graphics) {
      printError(why + "; running headless");
      c.pictures.framesDir.clear();  // no frames without the library; the meshes need none
      return runHeadlessWithOutputs(c, nullptr);
    }
    if (!c.framesGiven) {
      madeParent = ::access(kFramesParent, F_OK) != 0;
      c.pictures.framesDir = makeNewFolder(kFramesParent, worldStem(c.run.worldPath));
      madeFolder = true;
    }
    printError("no display (" + why + "); running headless, writing frames into " +
               c.pictures.framesDir + "/");
  }
  const Outcome outcome = runHeadlessWithOutputs(c, graphics);
  // A run refused before its first frame (a malformed world, say) leaves no empty folder of this
  // run's making behind: rmdir removes a folder only when it is empty.
  if (madeFolder && outcome.status == Ending::Failed) {
    ::rmdir(c.pictures.framesDir.c_str());
    if (madeParent) ::rmdir(kFramesParent);
  }
  return outcome;
}

}  // namespace

Outcome runJelloCommand(const JelloCommand& command) {
  constexpr double kBytesPerGB = 1e9, kMostBytes = 1e18;
  if (command.maxMemoryGB > 0)
    setMemoryLimit(
        static_cast<std::uint64_t>(std::min(command.maxMemoryGB * kBytesPerGB, kMostBytes)));
  // --bench and --map hold two models of the world at once.
  if (command.mode == JelloCommand::Mode::Bench || command.mode == JelloCommand::Mode::Map)
    setWorldUse(WorldUse::Bench);
  switch (command.mode) {
    case JelloCommand::Mode::Bench:
      return runBench(command.run);
    case JelloCommand::Mode::Check:
    case JelloCommand::Mode::Map:
      return check(command);
    case JelloCommand::Mode::Report:
      return runReport(command.run, command.report);
    case JelloCommand::Mode::Static:
      return staticRest(command);
    case JelloCommand::Mode::Materials:
      return materials(command);
    case JelloCommand::Mode::Run:
      return simulate(command);
  }
  return failed("no such command");  // not reached: every mode is handled above
}

Outcome jelloCommand(int argc, const char* const* argv) {
  JelloCommand command;
  const ParsedCommand parsed = parseJelloCommandLine(argc, argv, &command);
  return parsed.goOn ? runJelloCommand(command) : parsed.outcome;
}

}  // namespace jello
