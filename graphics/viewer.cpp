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
#include "graphics/showCube.h"
#include "model/term.h"
#include "solver/simulation.h"

namespace jello {

namespace {

using Clock = std::chrono::steady_clock;

constexpr double kZoomStep = 0.2;  // m per z/x key press
// The push keys' (arrows) and the jump key's (j) velocity, m/s, added to every free point: a
// push moves the jelly visibly (a tenth of its size in 0.1 s), a jump lifts it about
// v^2 / 2g = 0.46 m under the Earth's gravity.
constexpr double kPushSpeed = 1.0, kJumpSpeed = 3.0;
constexpr double kMinRadius = kMinCameraDistance;  // m
constexpr double kMaxElevation = kPi / 2 - 0.01;
constexpr int kGrabPixels = 40;            // how near the cursor a grabbed point must be
constexpr double kMinPullStiffness = 100;  // N/m
constexpr double kMessageSeconds = 4;
constexpr double kMaxCatchUpSeconds = 0.1;  // real-time pacing never steps more than this at once
constexpr double kFrameBudgetSeconds = 1.0 / 30;  // nor spends more wall time than this per frame
constexpr int kStepsBetweenClockReads = 16;       // how often real-time pacing looks at that budget
constexpr double kRateSeconds = 0.5;              // steps per second are counted over this long
// While nothing runs, the idle callback naps this long: the CPU goes to a diagnosis under way
// (and to other programs), and keys are still answered well within a frame.
constexpr auto kStillNap = std::chrono::milliseconds(10);
constexpr int kEscape = 27;
constexpr float kPanelAlpha = 0.6f;  // of the panels behind the help and the messages
constexpr const char* kScreenshotPattern = "jello-window-%03d.jpg";  // in the current folder
constexpr int kMostScreenshots = 999;

double seconds(Clock::time_point from, Clock::time_point to) {
  return std::chrono::duration<double>(to - from).count();
}

struct Viewer {
  Model model;
  State initial;
  Simulation simulation;  // of `model`, declared after it
  Tolerances tolerances;  // RK45's, for the message when they cannot be met
  State lastGood;         // the state before the current frame's steps, shown if they diverge
  int n;

  // The run's length (--steps, --time), where the window pauses once; none: it runs on.
  std::optional<long long> endStep;
  std::string endName;  // how the command line said it: "--time 0.5 s"
  bool paused = false, diverged = false, ended = false, realTime = false;
  std::future<std::string> diagnosis;  // of the divergence, while it is under way
  std::string divergedAt;              // "diverged at step N (t=T s): reason"

  // Recording (space, --frames, --export): frames at the steps of `clock`, as a headless run
  // saves them, and with --export each frame's surface mesh, numbered as the frame.
  PictureOptions pictures;
  std::string worldPath;                  // names the world in the meshes' headers
  std::string stem;                       // names new folders of recordings
  std::unique_ptr<FrameSequence> frames;  // the latest recording's
  std::unique_ptr<MeshSequence> meshes;   // its meshes, with --export
  int recordings = 0;
  FrameClock clock;
  bool saving = false;
  long long nextFrame = 0;   // the step of the next frame to save while saving
  long long savedStep = -1;  // the step of the last saved frame
  bool screenshotAsked = false;

  Camera camera;
  DrawOptions draw;
  int width, height;
  bool help = false;

  // Mouse: right-drag turns the camera, left-drag pulls the nearest surface point.
  int lastX = 0, lastY = 0;
  bool rotating = false;
  Pull pull;
  double grabDepth = 0;  // window depth of the grabbed point, for unprojecting the cursor
  GLdouble modelview[16], projection[16];
  GLint viewport[4];

  // Pacing and the overlay.
  Clock::time_point realTimeStart;
  double realTimeStartSim = 0;
  Clock::time_point rateStart = Clock::now();
  long long rateSteps = 0;
  double stepsPerSecond = 0;
  std::string message;   // passing: shown kMessageSeconds
  std::string standing;  // the run's state while it lasts: diverged, reached its end
  Clock::time_point messageTime;

  Viewer(const WorldFile& file, const RunOptions& run, const PictureOptions& pictures)
      : model(makeModel(file.world, file.state)),
        initial(file.state),
        simulation(model, file.state, file.world.integrator, file.world.dt, run.tolerances),
        tolerances(run.tolerances),
        lastGood(file.state),
        n(file.world.n),
        pictures(pictures),
        worldPath(run.worldPath),
        stem(worldStem(run.worldPath)),
        clock(pictures.fps, file.world.n, file.world.dt),
        camera(cameraFor(model, pictures.camera)),
        width(pictures.width),
        height(pictures.height) {
    draw.coloring = static_cast<Coloring>(pictures.colouring);
  }

  double time() const { return simulation.time(); }
  const State& state() const { return simulation.state(); }

  // Every message the window shows is echoed on stderr, whole.
  void say(const std::string& text) {
    message = text;
    messageTime = Clock::now();
    printError(text);
  }
  void setStanding(const std::string& text) {
    standing = text;
    printError(text);
  }
};

Viewer& viewer() { return *static_cast<Viewer*>(glutGetWindowData()); }

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
  if (v.draw.coloring == Coloring::Friction)
    text.colouring = "friction: sticking or sliding";
  else if (v.draw.coloring != Coloring::Plain)
    text.colouring =
        std::string(coloringName(v.draw.coloring)) +
        (v.draw.colourScale > 0 ? " SCALE HELD (F FREES)" : " SCALE FITS EACH FRAME (F HOLDS)");
  if (v.help) text.help = windowKeys();
  text.standing = v.standing;
  if (seconds(v.messageTime, Clock::now()) < kMessageSeconds) text.message = v.message;
  return text;
}

void drawOverlay(const Viewer& v) {
  const OverlayLayout layout = layoutOverlay(
      overlayText(v), v.width, v.height, v.draw.springKinds(), v.draw.coloring != Coloring::Plain);
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
// first folder (the names do not clash: .jpg and .obj or .ply); otherwise --export DIR, and
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

// The drawn frame, read before the overlay is drawn, so that it is the picture an off-screen run
// makes of the same state.
void saveFrame(Viewer& v) {
  v.savedStep = v.simulation.step();
  v.nextFrame = v.clock.nextAfter(v.savedStep);
  const int index = v.frames->written();  // the mesh is named as its frame
  try {
    v.frames->save(readWindow(v.width, v.height));
    if (v.meshes)
      v.meshes->write(index, v.model.body(), v.state().p(),
                      MeshStamp{v.worldPath, v.savedStep, v.time()});
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
  drawScene(v.model, v.state(), v.camera, v.draw, v.width, v.height, &v.pull);
  glGetDoublev(GL_MODELVIEW_MATRIX, v.modelview);
  glGetDoublev(GL_PROJECTION_MATRIX, v.projection);
  glGetIntegerv(GL_VIEWPORT, v.viewport);
  const long long step = v.simulation.step();
  if (v.saving && step >= v.nextFrame && step != v.savedStep) saveFrame(v);
  drawOverlay(v);
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
  World world = v.model.world;
  world.dt = v.simulation.dt();
  world.integrator = v.simulation.integrator();
  v.simulation.restore(v.lastGood, stepBefore);
  v.diverged = v.paused = true;
  if (outcome.kind == RunOutcome::Kind::ToleranceUnmet) {
    v.setStanding(toleranceFailure(v.tolerances, outcome.step, world.dt) + " (paused; ESC quits)");
    return;
  }
  v.divergedAt = textf("diverged at step %lld (t=%.6g s): %s", outcome.step, outcome.time,
                       outcome.reason.c_str());
  v.setStanding(v.divergedAt + "; diagnosing (finding the stable dt)...");
  v.diagnosis = std::async(std::launch::async, [world, initial = v.initial, outcome] {
    return divergenceMessage(world, initial, outcome.step, outcome.time, outcome.reason);
  });
}

void pollDiagnosis(Viewer& v) {
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
    // A machine too slow for real time runs as fast as it can, but stays responsive.
    if (v.realTime && done > 0 && seconds(start, Clock::now()) > kFrameBudgetSeconds) break;
    const int stretch = v.realTime ? std::min(kStepsBetweenClockReads, count - done) : count - done;
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
  advance(v);
  if (v.paused) std::this_thread::sleep_for(kStillNap);
  glutPostRedisplay();
}

// ---------------------------------------------------------------------------------------------
// Keys and the mouse.

void togglePause(Viewer& v) {
  if (v.diverged) {
    v.say("a diverged run stays paused: ESC quits");
    return;
  }
  if (v.ended) {  // p after the end runs on without one
    v.ended = false;
    v.endStep.reset();
    v.standing.clear();
  }
  v.paused = !v.paused;
  v.realTimeStart = Clock::now();
  v.realTimeStartSim = v.time();
  v.rateSteps = 0;
  v.rateStart = Clock::now();
}

void toggleColourHold(Viewer& v) {
  if (v.draw.coloring == Coloring::Plain) {
    v.say("f holds the scale of a coloured surface: c colours it first");
  } else if (v.draw.coloring == Coloring::Friction) {
    v.say("the friction colouring has no scale to hold: its colours are states");
  } else if (v.draw.colourScale > 0) {
    v.draw.colourScale = 0;
    v.say("the colour scale fits each frame again");
  } else {
    v.draw.colourScale = fittedColourScale(v.model, v.state(), v.draw.coloring);
    v.say(textf("colour scale held at %g: a colour means the same value in every frame",
                v.draw.colourScale));
  }
}

void nextColouring(Viewer& v) {
  v.draw.coloring = static_cast<Coloring>((static_cast<int>(v.draw.coloring) + 1) % kColoringCount);
  v.draw.colourScale = 0;  // a held scale belongs to the colouring it was held for
}

// Adds `dv` to every free point's velocity (Simulation::addVelocity: pinned points stay).
void kick(Viewer& v, Vec3 dv, const char* what) {
  if (v.diverged) {
    v.say("a diverged run stays paused: ESC quits");
    return;
  }
  v.simulation.addVelocity(dv);
  v.say(textf("%s: %g m/s added to every free point%s", what, length(dv),
              v.paused ? " (paused: p runs on)" : ""));
}

// The arrow keys push the jelly horizontally as the camera sees it: up away from the camera,
// down toward it, left and right to the window's left and right.
void special(int key, int, int) {
  Viewer& v = viewer();
  const Camera& c = v.camera;
  switch (key) {
    case GLUT_KEY_UP:
      kick(v, kPushSpeed * c.away(), "push away");
      break;
    case GLUT_KEY_DOWN:
      kick(v, (-kPushSpeed) * c.away(), "push toward the camera");
      break;
    case GLUT_KEY_LEFT:
      kick(v, (-kPushSpeed) * c.right(), "push left");
      break;
    case GLUT_KEY_RIGHT:
      kick(v, kPushSpeed * c.right(), "push right");
      break;
    default:
      break;
  }
  glutPostRedisplay();
}

void keyboard(unsigned char key, int, int) {
  Viewer& v = viewer();
  switch (key) {
    case kEscape:
      glutLeaveMainLoop();
      break;
    case 'z':
      v.camera.radius = std::max(kMinRadius, v.camera.radius - kZoomStep);
      break;
    case 'x':
      v.camera.radius += kZoomStep;
      break;
    case 'e':
      v.camera = cameraFor(v.model, v.pictures.camera);
      break;
    case 'v':
      v.draw.wireframe = !v.draw.wireframe;
      break;
    case 's':
      v.draw.structural = !v.draw.structural;
      break;
    case 'h':
      v.draw.shear = !v.draw.shear;
      break;
    case 'b':
      v.draw.bend = !v.draw.bend;
      break;
    case 'p':
      togglePause(v);
      break;
    case ' ':
      toggleSaving(v);
      break;
    case 'c':
      nextColouring(v);
      break;
    case 'f':
      toggleColourHold(v);
      break;
    case 'r':
      v.realTime = !v.realTime;
      v.realTimeStart = Clock::now();
      v.realTimeStartSim = v.time();
      break;
    case '?':
    case 'k':
      v.help = !v.help;
      break;
    case 'w':
      v.screenshotAsked = true;
      break;
    case 'j':
      kick(v, kJumpSpeed * v.camera.up, "jump");  // against gravity (cameraFor), or +z
      break;
    default:
      break;
  }
  glutPostRedisplay();
}

// The cursor at window depth `depth`, in world coordinates.
Vec3 unproject(const Viewer& v, int x, int y, double depth) {
  GLdouble wx, wy, wz;
  gluUnProject(x, v.height - y, depth, v.modelview, v.projection, v.viewport, &wx, &wy, &wz);
  return {wx, wy, wz};
}

void grab(Viewer& v, int x, int y) {
  int best = -1;
  double bestDistance = kGrabPixels, bestDepth = 0;
  const int n = v.model.points();
  for (int q : v.model.body().surfacePoints) {
    Vec3 p = load(v.state().p(), q, n);
    GLdouble sx, sy, sz;
    if (!gluProject(p.x, p.y, p.z, v.modelview, v.projection, v.viewport, &sx, &sy, &sz)) continue;
    double d = std::hypot(sx - x, sy - (v.height - y));
    // Of points equally near the cursor, the one nearest the camera.
    if (d < bestDistance - 1e-9 ||
        (best >= 0 && std::fabs(d - bestDistance) < 2 && sz < bestDepth)) {
      best = q;
      bestDistance = d;
      bestDepth = sz;
    }
  }
  if (best < 0) {
    v.say("no point of the jelly near the cursor: left-drag from the jelly's surface to pull it");
    return;
  }
  v.grabDepth = bestDepth;
  v.pull.point = best;
  v.pull.stiffness = std::max(kMinPullStiffness, v.model.world.kElastic);
  v.pull.target = unproject(v, x, y, v.grabDepth);
}

void mouse(int button, int buttonState, int x, int y) {
  Viewer& v = viewer();
  v.lastX = x;
  v.lastY = y;
  if (button == GLUT_RIGHT_BUTTON) v.rotating = buttonState == GLUT_DOWN;
  if (button == GLUT_LEFT_BUTTON) {
    if (buttonState == GLUT_DOWN) {
      grab(v, x, y);
    } else if (v.pull.point >= 0) {
      v.pull.point = -1;  // the simulation's next step, without a pull, restarts the energy bound
    }
  }
}

void motion(int x, int y) {
  Viewer& v = viewer();
  if (v.rotating) {
    const double perPixel = radiansPerPixel(v.width, v.height);
    v.camera.phi += (x - v.lastX) * perPixel;
    v.camera.theta =
        std::clamp(v.camera.theta + (y - v.lastY) * perPixel, -kMaxElevation, kMaxElevation);
  }
  if (v.pull.point >= 0) v.pull.target = unproject(v, x, y, v.grabDepth);
  v.lastX = x;
  v.lastY = y;
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

Outcome runViewer(const RunOptions& run, const PictureOptions& pictures) {
  WorldFile file;
  if (Outcome loaded = loadRun(run, &file); !loaded.ok()) return loaded;
  Viewer v(file, run, pictures);
  if (run.steps) {
    v.endStep = *run.steps;
    v.endName = textf("--steps %lld", *run.steps);
  }
  if (run.time) {
    v.endStep = stepsForTime(*run.time, file.world.dt);
    if (!v.endStep) return failed(tooManyStepsMessage(*run.time, file.world.dt));
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
  glutSpecialFunc(special);
  glutMouseFunc(mouse);
  glutMotionFunc(motion);
  if (pictures.saveFromStart) toggleSaving(v);
  glutMainLoop();  // returns once the window is closed (freeglut destroys it then)
  return finish(v);
}

extern "C" const GraphicsApi* jelloGraphicsApi() {
  static const GraphicsApi api{&displayAvailable, &makeOffscreenFrames, &runViewer};
  return &api;
}

}  // namespace jello
