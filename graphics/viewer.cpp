// viewer.cpp: the GLUT window (README: The viewer). GLUT calls back without a user pointer, so
// the viewer's state lives in one object reached through freeglut's per-window data, not in
// globals; the physics sees it only as arguments (the model, the state, the pull).

#include <GL/freeglut.h>
#include <GL/glu.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>

#include "app/stability.h"
#include "core/output.h"
#include "graphics/graphics.h"
#include "showCube.h"
#include "solver/simulation.h"

namespace jello {

namespace {

using Clock = std::chrono::steady_clock;

constexpr double kZoomStep = 0.2;          // m per z/x key press
constexpr double kMinRadius = 0.5;         // m
constexpr double kRadiansPerPixel = 0.01;  // camera rotation per pixel dragged
constexpr double kMaxElevation = kPi / 2 - 0.01;
constexpr int kGrabPixels = 40;            // how near the cursor a grabbed point must be
constexpr double kMinPullStiffness = 100;  // N/m
constexpr double kMessageSeconds = 4;
constexpr double kMaxCatchUpSeconds = 0.1;  // real-time pacing never steps more than this at once
constexpr double kFrameBudgetSeconds = 1.0 / 30;  // nor spends more wall time than this per frame
constexpr int kStepsBetweenClockReads = 16;       // how often real-time pacing looks at that budget
constexpr int kEscape = 27;

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
  long long savedStep = -1;  // the step of the last saved frame

  Camera camera;
  DrawOptions draw;
  int width, height;
  bool paused = false, diverged = false, realTime = false, saving = false;
  FrameSequence frames;

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
  std::string message;
  Clock::time_point messageTime;

  Viewer(const WorldFile& file, const RunOptions& run, const PictureOptions& pictures)
      : model(makeModel(file.world, file.state)),
        initial(file.state),
        simulation(model, file.state, file.world.integrator, file.world.dt, run.tolerances),
        tolerances(run.tolerances),
        lastGood(file.state),
        n(file.world.n),
        width(pictures.width),
        height(pictures.height),
        frames(pictures.framesDir, pictures.maxFrames, pictures.overwrite) {}

  double time() const { return simulation.time(); }
  const State& state() const { return simulation.state(); }

  void say(const std::string& text) {
    message = text;
    messageTime = Clock::now();
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

void drawOverlay(Viewer& v) {
  char line[160];
  std::snprintf(line, sizeof line, "T=%.3f S  %s  DT=%g  %.0f STEPS/S%s%s", v.time(),
                integratorName(v.simulation.integrator()), v.simulation.dt(), v.stepsPerSecond,
                v.realTime ? "  REAL TIME" : "", v.paused ? "  PAUSED" : "");
  drawText(line, 8, 8, v.width, v.height, 2, 1, 1, 1);
  if (v.saving) {
    std::string mark =
        "SAVING " + std::to_string(v.frames.written()) + "/" + std::to_string(v.frames.maxFrames());
    drawText(mark, v.width - textWidth(mark, 2) - 8, 8, v.width, v.height, 2, 1, 0.25f, 0.2f);
  }
  if (v.draw.coloring != Coloring::Plain) {
    drawText(std::string("COLOUR: ") + coloringName(v.draw.coloring), 8, 26, v.width, v.height, 2,
             1, 1, 1);
  }
  bool fresh = seconds(v.messageTime, Clock::now()) < kMessageSeconds;
  if (!v.message.empty() && (fresh || v.diverged)) {
    if (v.diverged)
      drawText(v.message, 8, v.height - 24, v.width, v.height, 2, 1, 0.3f, 0.25f);
    else
      drawText(v.message, 8, v.height - 24, v.width, v.height, 2, 1, 1, 0.4f);
  }
}

void display() {
  Viewer& v = viewer();
  drawScene(v.model, v.state(), v.camera, v.draw, v.width, v.height, &v.pull);
  glGetDoublev(GL_MODELVIEW_MATRIX, v.modelview);
  glGetDoublev(GL_PROJECTION_MATRIX, v.projection);
  glGetIntegerv(GL_VIEWPORT, v.viewport);
  // The frame is read before the overlay is drawn, so that it is the picture an off-screen
  // run makes of the same state; one frame per state drawn, none while paused.
  if (v.saving && v.simulation.step() != v.savedStep) {
    v.savedStep = v.simulation.step();
    try {
      v.frames.save(readWindow(v.width, v.height));
    } catch (const std::exception& e) {
      v.saving = false;
      v.say(e.what());
    }
    if (v.frames.full()) {
      v.saving = false;
      v.say("saved " + std::to_string(v.frames.written()) + " frames in " + v.frames.dir() +
            "/ (the most allowed)");
    }
  }
  drawOverlay(v);
  glutSwapBuffers();
}

void reshape(int width, int height) {
  Viewer& v = viewer();
  v.width = width;
  v.height = height;
}

void advance() {
  Viewer& v = viewer();
  if (v.paused || v.diverged) return;
  int count = v.n;
  if (v.realTime) {
    // Simulated time follows the wall clock when the machine keeps up; otherwise it runs as
    // fast as it can, like the course's viewer.
    double behind = v.realTimeStartSim + seconds(v.realTimeStart, Clock::now()) - v.time();
    // Compared before the conversion: a tiny dt (1e-300) asks for more steps than an int holds;
    // the frame budget below stops the loop long before that many anyway.
    const double wanted = std::floor(std::min(behind, kMaxCatchUpSeconds) / v.simulation.dt());
    if (!(wanted >= 1)) return;
    count = static_cast<int>(std::min(wanted, double(std::numeric_limits<int>::max())));
  }
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
  if (!outcome.ran()) {
    World world = v.model.world;
    world.dt = v.simulation.dt();
    world.integrator = v.simulation.integrator();
    v.say((outcome.kind == RunOutcome::Kind::ToleranceUnmet
               ? toleranceFailure(v.tolerances, outcome.step, world.dt)
               : divergenceMessage(world, v.initial, outcome.step, outcome.time, outcome.reason)) +
          " (paused)");
    v.simulation.restore(v.lastGood, stepBefore);
    v.diverged = true;
    v.paused = true;
  }
  double elapsed = seconds(v.rateStart, Clock::now());
  if (elapsed > 0.5) {
    v.stepsPerSecond = v.rateSteps / elapsed;
    v.rateSteps = 0;
    v.rateStart = Clock::now();
  }
}

void idle() {
  advance();
  glutPostRedisplay();
}

void toggleSaving(Viewer& v) {
  if (v.saving) {
    v.saving = false;
    v.say("stopped saving: " + std::to_string(v.frames.written()) + " frames in " + v.frames.dir() +
          "/");
    return;
  }
  if (v.frames.full()) {
    v.say("already saved the most frames allowed (" + std::to_string(v.frames.maxFrames()) + ")");
    return;
  }
  try {
    v.frames.open();
    v.saving = true;
    v.say("saving frames into " + v.frames.dir() + "/");
  } catch (const std::exception& e) {
    v.say(e.what());
  }
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
      v.camera = Camera{};
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
      if (v.diverged) break;  // a diverged run stays paused
      v.paused = !v.paused;
      v.realTimeStart = Clock::now();
      v.realTimeStartSim = v.time();
      break;
    case ' ':
      toggleSaving(v);
      break;
    case 'c':
      v.draw.coloring = static_cast<Coloring>((static_cast<int>(v.draw.coloring) + 1) % 3);
      break;
    case 'r':
      v.realTime = !v.realTime;
      v.realTimeStart = Clock::now();
      v.realTimeStartSim = v.time();
      break;
    default:
      break;
  }
  glutPostRedisplay();
}

bool isSurfacePoint(int q) {
  int index[3] = {q / (kLatticeSize * kLatticeSize), (q / kLatticeSize) % kLatticeSize,
                  q % kLatticeSize};
  for (int c : index)
    if (c == 0 || c == kLatticeSize - 1) return true;
  return false;
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
  for (int q = 0; q < kNumPoints; ++q) {
    if (!isSurfacePoint(q)) continue;
    Vec3 p = load(v.state().p(), q);
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
  if (best < 0) return;
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
    v.camera.phi += (x - v.lastX) * kRadiansPerPixel;
    v.camera.theta = std::clamp(v.camera.theta + (y - v.lastY) * kRadiansPerPixel, -kMaxElevation,
                                kMaxElevation);
  }
  if (v.pull.point >= 0) v.pull.target = unproject(v, x, y, v.grabDepth);
  v.lastX = x;
  v.lastY = y;
  glutPostRedisplay();
}

}  // namespace

Outcome runViewer(const RunOptions& run, const PictureOptions& pictures) {
  WorldFile file;
  if (Outcome loaded = loadRun(run, &file); !loaded.ok()) return loaded;
  Viewer v(file, run, pictures);

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
  glutMouseFunc(mouse);
  glutMotionFunc(motion);
  if (pictures.saveFromStart) toggleSaving(v);
  glutMainLoop();
  // The window printed its divergence when it happened (say): nothing is left to print.
  return v.diverged ? Outcome{Ending::Diverged, ""} : succeeded();
}

extern "C" const GraphicsApi* jelloGraphicsApi() {
  static const GraphicsApi api{&displayAvailable, &makeOffscreenFrames, &runViewer};
  return &api;
}

}  // namespace jello
