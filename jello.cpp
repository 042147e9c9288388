// jello.cpp: the simulator's main (README: Running): parse the command line, do what it says,
// and choose the exit status. Only this file and createWorld.cpp print a verdict and pick a
// status for the whole program: the library says how a command went as an Outcome (outcome.h).

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <new>
#include <string>

#include "app/bench.h"
#include "app/commandline.h"
#include "app/export.h"
#include "app/headless.h"
#include "app/report.h"
#include "app/stability.h"
#include "core/memory.h"
#include "core/output.h"
#include "graphics/graphics.h"
#include "world.h"

namespace {

jello::Outcome check(const jello::JelloCommand& c) {
  jello::WorldFile file;
  if (jello::Outcome loaded = jello::loadRun(c.run, &file); !loaded.ok()) return loaded;
  if (c.mode == jello::JelloCommand::Mode::Map)
    return jello::writeStabilityMap(c.mapDir, c.run.worldPath, file.world, file.state, c.mapTime,
                                    c.pictures.overwrite);
  jello::StabilityReport analysis = jello::analyseStability(file.world, file.state);
  std::fputs((c.json ? jello::stabilityJson(c.run.worldPath, file.world, analysis)
                     : jello::stabilityText(c.run.worldPath, file.world, analysis))
                 .c_str(),
             stdout);
  return jello::succeeded();
}

// A headless run with its observers: the frames (rendered by the pictures' library, loaded
// here when `graphics` is not yet) and the meshes of --export.
jello::Outcome runHeadlessWithOutputs(const jello::JelloCommand& c,
                                      const jello::GraphicsApi* graphics) {
  std::unique_ptr<jello::FrameObserver> frames, meshes;
  if (!c.pictures.framesDir.empty()) {
    std::string why;
    if (!graphics) graphics = jello::loadGraphics(&why);
    if (!graphics) return jello::failed("--frames: " + why + ", so it cannot render frames");
    frames = graphics->makeOffscreenFrames(c.pictures);
  }
  if (!c.pictures.exportDir.empty())
    meshes = jello::makeMeshExport(c.pictures, c.run.worldPath, c.pictures.framesDir);
  std::unique_ptr<jello::FrameObserver> both =
      jello::bothObservers(std::move(frames), std::move(meshes));
  return jello::runHeadless(c.run, both.get());
}

// Where a run without a display and without --frames makes its new frames folder.
constexpr const char* kFramesParent = "animation";

// A window where a display exists; otherwise headless, with frames where asked (or, when no
// --headless was given, into a new folder of animation/), and the meshes of --export.
jello::Outcome simulate(jello::JelloCommand c) {
  // The pictures' library is loaded only from here on, and only for a window or frames.
  const jello::GraphicsApi* graphics = nullptr;
  std::string why;
  bool madeFolder = false, madeParent = false;
  if (!c.headless) {
    graphics = jello::loadGraphics(&why);
    if (graphics && graphics->displayAvailable(&why)) {
      if (!c.framesGiven) c.pictures.framesDir = "animation";
      c.pictures.framesNamed = c.framesGiven;
      // --export records from the start as --frames does: the user named a folder to fill.
      c.pictures.saveFromStart = c.framesGiven || !c.pictures.exportDir.empty();
      return graphics->runViewer(c.run, c.pictures);
    }
    if (!graphics) {
      jello::printError(why + "; running headless");
      c.pictures.framesDir.clear();  // no frames without the library; the meshes need none
      return runHeadlessWithOutputs(c, nullptr);
    }
    if (!c.framesGiven) {
      madeParent = ::access(kFramesParent, F_OK) != 0;
      c.pictures.framesDir = jello::makeNewFolder(kFramesParent, jello::worldStem(c.run.worldPath));
      madeFolder = true;
    }
    jello::printError("no display (" + why + "); running headless, writing frames into " +
                      c.pictures.framesDir + "/");
  }
  const jello::Outcome outcome = runHeadlessWithOutputs(c, graphics);
  // A run refused before its first frame (a malformed world, say) leaves no empty folder of this
  // run's making behind: rmdir removes a folder only when it is empty.
  if (madeFolder && outcome.status == jello::Ending::Failed) {
    ::rmdir(c.pictures.framesDir.c_str());
    if (madeParent) ::rmdir(kFramesParent);
  }
  return outcome;
}

// The exit status of an outcome, its line printed on stderr.
int exitStatus(const jello::Outcome& outcome) {
  if (!outcome.message.empty()) jello::printError(outcome.message);
  switch (outcome.status) {
    case jello::Ending::Ok:
      return jello::kExitOk;
    case jello::Ending::Diverged:
      return jello::kExitDiverged;
    case jello::Ending::Failed:
      return jello::kExitBadInput;
  }
  return jello::kExitBadInput;
}

jello::Outcome runCommand(const jello::JelloCommand& command) {
  constexpr double kBytesPerGB = 1e9, kMostBytes = 1e18;
  if (command.maxMemoryGB > 0)
    jello::setMemoryLimit(
        static_cast<std::uint64_t>(std::min(command.maxMemoryGB * kBytesPerGB, kMostBytes)));
  // --bench and --map hold two models of the world at once.
  if (command.mode == jello::JelloCommand::Mode::Bench ||
      command.mode == jello::JelloCommand::Mode::Map)
    jello::setWorldUse(jello::WorldUse::Bench);
  switch (command.mode) {
    case jello::JelloCommand::Mode::Bench:
      return jello::runBench(command.run);
    case jello::JelloCommand::Mode::Check:
    case jello::JelloCommand::Mode::Map:
      return check(command);
    case jello::JelloCommand::Mode::Report:
      return jello::runReport(command.run, command.report);
    case jello::JelloCommand::Mode::Run:
      return simulate(command);
  }
  return jello::failed("no such command");  // not reached: every mode is handled above
}

int runCommandLine(int argc, char** argv) {
  jello::JelloCommand command;
  const int status = jello::parseJelloCommandLine(argc, argv, &command);
  if (status != jello::kGoOn) return status;
  return exitStatus(runCommand(command));
}

}  // namespace

// Every exception ends here as one line and exit status 2; a result the user cannot receive
// (standard output closed or full) is a failure too, not a success.
int main(int argc, char** argv) {
  jello::setProgramName("jello");
  jello::installSignalCleanup();
  int status = jello::kExitBadInput;
  try {
    status = runCommandLine(argc, argv);
  } catch (const std::bad_alloc&) {
    jello::printError("not enough memory for this run");
  } catch (const std::exception& e) {
    jello::printError(e.what());
  }
  if (const std::string unwritten = jello::unwrittenStandardOutput(); !unwritten.empty()) {
    jello::printError(unwritten);
    if (status == jello::kExitOk) status = jello::kExitBadInput;
  }
  return status;
}
