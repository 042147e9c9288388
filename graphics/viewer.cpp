// viewer.cpp: the GLUT window (README: The viewer). GLUT calls back without a user pointer, so
// the viewer's state lives in one object reached through freeglut's per-window data, not in
// globals; the physics sees it only as arguments (the model, the state, the pull).
//
// GLUT and GL are used from the main thread only. The one other thread diagnoses a divergence
// (divergenceMessage: eigen-analyses that take seconds) on copies of the world and its initial
// state, and hands its line back through a std::future that the idle callback polls, so the
// window keeps drawing and answering keys meanwhile.

#include <GL/freeglut.h>
#include <GL/glu.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <future>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include "analysis/stability.h"
#include "app/export.h"
#include "core/output.h"
#include "graphics/graphics.h"
#include "graphics/layout.h"
#include "graphics/panel.h"
#include "graphics/showCube.h"
#include "graphics/viewerstate.h"
#include "model/term.h"
#include "solver/simulation.h"

namespace jello {

namespace {

Image readWindow(int width, int height) {
  Image image;
  image.width = width;
  image.height = height;
  image.rgb.resize(static_cast<std::size_t>(width) * height * 3);
  std::vector<std::uint8_t> bottomUp(image.rgb.size());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, bottomUp.data());
  const std::size_t stride = static_cast<std::size_t>(width) * 3;
  for (int row = 0; row < height; ++row) {
    std::copy_n(bottomUp.data() + (height - 1 - row) * stride, stride,
                image.rgb.data() + row * stride);
  }
  return image;
}

// ---------------------------------------------------------------------------------------------
// The overlay.

OverlayText overlayText(const Viewer& v) {
  OverlayText text;
  text.status.push_back(textf("T=%.3f S", v.time()));
  text.status.push_back(
      textf("%s DT=%g", integratorName(v.simulation.integrator()), v.simulation.dt()));
  if (!v.paused) text.status.push_back(textf("%.0f STEPS/S", v.stepsPerSecond));
  if (v.realTime) text.status.push_back("REAL TIME");
  if (v.paused) text.status.push_back(v.diverged ? "DIVERGED" : "PAUSED");
  if (!v.help) text.status.push_back("? KEYS");
  if (v.saving)
    text.recording = textf("SAVING %d/%d INTO %s/", v.frames->written(), v.frames->maxFrames(),
                           v.frames->dir().c_str());
  if (v.draw.colouring == Colouring::Friction)
    text.colouring = "friction: sticking or sliding";
  else if (v.draw.colouring != Colouring::Plain)
    text.colouring =
        std::string(colouringName(v.draw.colouring)) +
        (v.draw.colourScale > 0 ? " SCALE HELD (F FREES)" : " SCALE FITS EACH FRAME (F HOLDS)");
  if (v.help) text.help = windowKeys();
  text.standing = v.standing;
  if (seconds(v.messageTime, Clock::now()) < kMessageSeconds) text.message = v.message;
  return text;
}

void drawOverlay(const Viewer& v) {
  const OverlayLayout layout =
      layoutOverlay(overlayText(v), v.width, v.height, v.draw.springKinds(),
                    v.draw.colouring != Colouring::Plain);
  // Dark panels behind the longer texts keep them readable over the box's white lines.
  for (const PixelRect& panel : {layout.help, layout.messages})
    if (!panel.empty()) drawPanel(panel, v.width, v.height, 0, 0, 0, kPanelAlpha);
  for (const PlacedLine& line : layout.lines) {
    float r = 1, g = 1, b = 1;  // status and help: white
    if (line.role == TextRole::Recording) g = 0.5f, b = 0.45f;
    if (line.role == TextRole::Message) b = 0.4f;
    if (line.role == TextRole::Standing && v.diverged) g = 0.45f, b = 0.4f;
    if (line.role == TextRole::Standing && !v.diverged) r = 0.5f, g = 0.9f;
    drawText(line.text, line.x, line.y, v.width, v.height, line.scale, r, g, b);
  }
}

// ---------------------------------------------------------------------------------------------
// Recording and pictures of the window.

// The folder of a new recording (README: The viewer): the one --frames named; otherwise
// animation/ while it holds no frames, else a new folder in it named after the world. After a
// recording that reached --max-frames, a new folder in the first one.
std::string newRecordingFolder(const Viewer& v) {
  const std::string& first = v.pictures.framesDir;
  const bool named = v.pictures.framesNamed;
  if (v.recordings == 0 && (named || v.pictures.overwrite || countFrames(first) == 0)) return first;
  return makeNewFolder(first, v.stem);
}

// The folder of a new recording's meshes: the frames' folder when --export names the frames'
// first folder (the names do not clash: .jpg and .obj, .ply or .vtu); otherwise --export DIR, and
// after a recording that reached --max-frames, a new folder in it, as for frames.
std::string newExportFolder(const Viewer& v, const std::string& framesFolder) {
  const std::string& first = v.pictures.exportDir;
  if (sameFile(first, v.pictures.framesDir)) return framesFolder;
  if (v.recordings == 0) return first;
  return makeNewFolder(first, v.stem);
}

// The folders a recording writes into, as its messages name them.
std::string recordingFolders(const Viewer& v) {
  std::string text = "frames into " + v.frames->dir() + "/";
  if (v.meshes) text += " and meshes into " + v.meshes->dir() + "/";
  return text;
}

// A new recording: its frames' folder and, with --export, its meshes' folder, both claimed (or
// neither, when one cannot be). Throws OutputError or FrameError, saying why not.
void startNewRecording(Viewer& v) {
  // The claims on the last recording's folders go first: makeNewFolder claims the parents.
  v.frames.reset();
  v.meshes.reset();
  auto frames = std::make_unique<FrameSequence>(newRecordingFolder(v), v.pictures.maxFrames,
                                                v.pictures.overwrite);
  frames->open();
  std::unique_ptr<MeshSequence> meshes;
  if (!v.pictures.exportDir.empty()) {
    meshes = std::make_unique<MeshSequence>(newExportFolder(v, frames->dir()),
                                            v.pictures.exportFormat, v.pictures.overwrite);
    meshes->open(frames->dir());
  }
  v.frames = std::move(frames);
  v.meshes = std::move(meshes);
  ++v.recordings;
}

// Starts or resumes saving; a recording that is full gives way to one in a new folder. Throws
// OutputError or FrameError, saying why not.
void startRecording(Viewer& v) {
  if (!v.frames || v.frames->full()) startNewRecording(v);
  v.saving = true;
  // This drawn frame is saved first, unless it already was.
  const long long step = v.simulation.step();
  v.nextFrame = step == v.savedStep ? v.clock.nextAfter(step) : step;
  v.say("saving " + recordingFolders(v) + " (space stops)");
}

// The drawn frame, read before the overlay is drawn, so that it is the picture an off-screen run
// makes of the same state.
void saveFrame(Viewer& v) {
  v.savedStep = v.simulation.step();
  v.nextFrame = v.clock.nextAfter(v.savedStep);
  const int index = v.frames->written();  // the mesh is named as its frame
  try {
    v.frames->save(readWindow(v.width, v.height));
    if (v.meshes)
      v.meshes->write(index, v.model, v.state(), MeshStamp{v.worldPath, v.savedStep, v.time()});
  } catch (const std::exception& e) {
    v.saving = false;
    v.say(e.what());
    return;
  }
  if (v.frames->full()) {
    v.saving = false;
    v.say(
        textf("saved %d frames in %s/, the most --max-frames %d allows (up to %d); space saves "
              "on into a new folder",
              v.frames->written(), v.frames->dir().c_str(), v.frames->maxFrames(), kMaxFrames));
  }
}

// The window as it is seen, overlay and all, into the first free jello-window-NNN.jpg.
void saveScreenshot(Viewer& v) {
  v.screenshotAsked = false;
  for (int i = 1; i <= kMostScreenshots; ++i) {
    const std::string path = textf(kScreenshotPattern, i);
    const WriteCheck check = checkWritable(path, Existing::Refuse);
    if (check.alreadyExists) continue;
    try {
      if (!check.writable()) throw OutputError(path + ": " + check.why);
      writeJpeg(path, readWindow(v.width, v.height));
      v.say("saved the window as " + path);
    } catch (const std::exception& e) {
      v.say(e.what());
    }
    return;
  }
  v.say(textf("the current folder holds %d pictures of the window already: none saved",
              kMostScreenshots));
}

void display() {
  Viewer& v = viewer();
  drawPicture(v.model, v.state(), v.camera, v.draw, v.width, v.height, &v.pull);
  glGetDoublev(GL_MODELVIEW_MATRIX, v.modelview);
  glGetDoublev(GL_PROJECTION_MATRIX, v.projection);
  glGetIntegerv(GL_VIEWPORT, v.viewport);
  const long long step = v.simulation.step();
  if (v.saving && step >= v.nextFrame && step != v.savedStep) saveFrame(v);
  drawOverlay(v);
  drawPanel(v);  // after the frame was saved: never in one
  if (v.screenshotAsked) saveScreenshot(v);
  glutSwapBuffers();
}

void reshape(int width, int height) {
  Viewer& v = viewer();
  v.width = width;
  v.height = height;
}

// ---------------------------------------------------------------------------------------------
// Running.

// The diagnosis's line, or why there is none.
std::string takeDiagnosis(Viewer& v) {
  try {
    return v.diagnosis.get();
  } catch (const std::exception& e) {
    return v.divergedAt + "; no advice: its diagnosis failed (" + e.what() + ")";
  }
}

// Pauses on the last sane state and starts the diagnosis on its own thread.
void diverge(Viewer& v, const RunOutcome& outcome, long long stepBefore) {
  const Integrator integrator = v.simulation.integrator();
  const double dt = v.simulation.dt();
  v.simulation.restore(v.lastGood, stepBefore);
  v.diverged = v.paused = true;
  if (outcome.kind == RunOutcome::Kind::ToleranceUnmet) {
    v.setStanding(toleranceFailure(v.tolerances, outcome.step, dt) + " (paused; ESC quits)");
    return;
  }
  v.divergedAt = textf("diverged at step %lld (t=%.6g s): %s", outcome.step, outcome.time,
                       outcome.reason.c_str());
  v.setStanding(v.divergedAt + "; diagnosing (finding the stable dt)...");
  v.diagnosis = std::async(std::launch::async,
                           [world = v.model.world, initial = v.initial, integrator, dt, outcome] {
                             return divergenceMessage(world, initial, integrator, dt, outcome.step,
                                                      outcome.time, outcome.reason);
                           });
}

void pollDiagnosis(Viewer& v) {
  auto& stale = v.staleDiagnoses;
  stale.erase(std::remove_if(stale.begin(), stale.end(),
                             [](std::future<std::string>& f) {
                               return f.wait_for(std::chrono::seconds(0)) ==
                                      std::future_status::ready;
                             }),
              stale.end());
  if (!v.diagnosis.valid() ||
      v.diagnosis.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
    return;
  v.setStanding(takeDiagnosis(v) + " (paused on the last sane state; ESC quits)");
}

void reachEnd(Viewer& v) {
  v.ended = v.paused = true;
  v.stepsPerSecond = 0;
  v.setStanding(textf("reached %s (step %lld): paused; ESC quits, p runs on", v.endName.c_str(),
                      v.simulation.step()));
}

// Steps the run may take before it must stop and be drawn: at its end, and at the next frame
// to save.
long long stepsBeforeStop(const Viewer& v) {
  long long most = std::numeric_limits<long long>::max();
  const long long step = v.simulation.step();
  if (v.endStep) most = std::min(most, *v.endStep - step);
  if (v.saving) most = std::min(most, v.nextFrame - step);
  return std::max(0LL, most);
}

// n, or in real time what the wall clock asks for.
int stepsThisFrame(const Viewer& v) {
  if (!v.realTime) return v.n;
  // Simulated time follows the wall clock when the machine keeps up; otherwise it runs as
  // fast as it can, like the course's viewer.
  double behind = v.realTimeStartSim + seconds(v.realTimeStart, Clock::now()) - v.time();
  // Compared before the conversion: a tiny dt (1e-300) asks for more steps than an int holds;
  // the frame budget stops the loop long before that many anyway.
  const double wanted = std::floor(std::min(behind, kMaxCatchUpSeconds) / v.simulation.dt());
  if (!(wanted >= 1)) return 0;
  return static_cast<int>(std::min(wanted, double(std::numeric_limits<int>::max())));
}

void runSteps(Viewer& v, int count) {
  v.lastGood = v.state();
  const long long stepBefore = v.simulation.step();
  const Pull* pull = v.pull.point >= 0 ? &v.pull : nullptr;
  const Clock::time_point start = Clock::now();
  RunOutcome outcome;
  for (int done = 0; done < count && outcome.ran();) {
    // A machine too slow for real time runs as fast as it can, but stays responsive; so does a
    // frame of many slow steps (n 10000 of IMPLICIT), drawn before its n are done.
    const double budget = v.realTime ? kFrameBudgetSeconds : kLongestFrameSeconds;
    if (done > 0 && seconds(start, Clock::now()) > budget) break;
    const int stretch = std::min(kStepsBetweenClockReads, count - done);
    outcome = v.simulation.advance(stretch, pull);
    done += stretch;
  }
  v.rateSteps += v.simulation.step() - stepBefore;
  if (!outcome.ran()) diverge(v, outcome, stepBefore);
}

void advance(Viewer& v) {
  if (v.paused) return;
  const long long count = std::min<long long>(stepsThisFrame(v), stepsBeforeStop(v));
  if (count > 0) runSteps(v, static_cast<int>(count));
  if (!v.diverged && v.endStep && v.simulation.step() >= *v.endStep) reachEnd(v);
  double elapsed = seconds(v.rateStart, Clock::now());
  if (elapsed > kRateSeconds) {
    v.stepsPerSecond = v.rateSteps / elapsed;
    v.rateSteps = 0;
    v.rateStart = Clock::now();
  }
}

void idle() {
  Viewer& v = viewer();
  pollDiagnosis(v);
  pollPanel(v);
  advance(v);
  if (v.paused) std::this_thread::sleep_for(kStillNap);
  glutPostRedisplay();
}

// After the window has closed: a diagnosis still under way is waited for, so that its advice is
// printed and no thread outlives the run.
Outcome finish(Viewer& v) {
  if (!v.diverged) return succeeded();
  // The window printed its messages as they came (say): only an unfinished diagnosis is left.
  if (!v.diagnosis.valid()) return diverged("");
  printError("the window is closed; finishing the diagnosis of the divergence (Ctrl-C skips it)");
  return diverged(takeDiagnosis(v));
}

}  // namespace

void stepFrame(Viewer& v) {
  if (!v.paused || v.diverged) return;
  const long long before = v.simulation.step();
  runSteps(v, v.n);
  v.say(
      textf("stepped %lld steps to step %lld", v.simulation.step() - before, v.simulation.step()));
}

void toggleSaving(Viewer& v) {
  if (v.saving) {
    v.saving = false;
    v.say(textf("stopped saving: %d frames in %s/ (space saves on into it)", v.frames->written(),
                v.frames->dir().c_str()));
    return;
  }
  try {
    startRecording(v);
  } catch (const std::exception& e) {
    v.say(e.what());
  }
}

Outcome runViewer(const RunOptions& run, const PictureOptions& pictures) {
  WorldFile file;
  if (Outcome loaded = loadRun(run, &file); !loaded.ok()) return loaded;
  Viewer v(file, run, pictures);
  if (run.steps) {
    v.endStep = *run.steps;
    v.endName = textf("--steps %lld", *run.steps);
  }
  if (run.time) {
    v.endStep = stepsForTime(*run.time, v.simulation.dt());
    v.endTime = *run.time;
    if (!v.endStep) return failed(tooManyStepsMessage(*run.time, v.simulation.dt()));
    v.endName = textf("--time %g s", *run.time);
  }

  int argc = 1;
  char name[] = "jello";
  char* argv[] = {name, nullptr};
  glutInit(&argc, argv);
  glutSetOption(GLUT_ACTION_ON_WINDOW_CLOSE, GLUT_ACTION_GLUTMAINLOOP_RETURNS);
  glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGBA | GLUT_DEPTH);
  glutInitWindowSize(pictures.width, pictures.height);
  glutCreateWindow("Jello cube");
  glutSetWindowData(&v);
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutIdleFunc(idle);
  glutKeyboardFunc(keyboard);
  glutKeyboardUpFunc(keyboardUp);
  glutSpecialFunc(special);
  glutSpecialUpFunc(specialUp);
  glutMouseFunc(mouse);
  glutMotionFunc(motion);
  glutPassiveMotionFunc(passiveMotion);
  glutMouseWheelFunc(wheel);                   // scrolls the panel
  glutCloseFunc([] { stopPanel(viewer()); });  // the window closed by its frame's button
  startPanel(v);
  if (pictures.saveFromStart) toggleSaving(v);
  glutMainLoop();  // returns once the window is closed (freeglut destroys it then)
  stopPanel(v);    // (done already, unless the loop ended otherwise)
  return finish(v);
}

extern "C" const GraphicsApi* jelloGraphicsApi() {
  static const GraphicsApi api{&displayAvailable, &makeOffscreenFrames, &runViewer};
  return &api;
}

}  // namespace jello
