// graphics/viewerstate.h: the window's state (viewer.cpp) and what its parts share: the keys and
// the mouse (viewerinput.cpp) change it, the display and idle callbacks (viewer.cpp) draw and
// advance it. Not for use outside graphics/viewer*.cpp.
#pragma once

#include <GL/freeglut.h>

#include <chrono>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "analysis/stepverdict.h"
#include "app/export.h"
#include "core/threadpool.h"
#include "graphics/graphics.h"
#include "graphics/layout.h"
#include "graphics/showCube.h"
#include "solver/simulation.h"

namespace jello {

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
constexpr int kStepsBetweenClockReads = 16;       // how often a frame looks at its budget
// A frame of n steps that take longer than this is drawn with those done, the rest in the next
// frames: the window answers keys within about this long, whatever n and the integrator.
constexpr double kLongestFrameSeconds = 0.25;
constexpr double kRateSeconds = 0.5;  // steps per second are counted over this long
// While nothing runs, the idle callback naps this long: the CPU goes to a diagnosis under way
// (and to other programs), and keys are still answered well within a frame.
constexpr auto kStillNap = std::chrono::milliseconds(10);
constexpr int kEscape = 27;
constexpr float kPanelAlpha = 0.6f;  // of the panels behind the help and the messages
constexpr const char* kScreenshotPattern = "jello-window-%03d.jpg";  // in the current folder
constexpr int kMostScreenshots = 999;

inline double seconds(Clock::time_point from, Clock::time_point to) {
  return std::chrono::duration<double>(to - from).count();
}

struct PanelState;  // graphics/panelstate.h: only a build with Dear ImGui makes one

struct Viewer {
  Model model;
  State initial;
  // The threads the simulation shares its evaluations between (as many as the body's size makes
  // worth it, at most --threads); declared before the simulation, which refers to it.
  std::unique_ptr<ThreadPool> pool;
  Simulation simulation;  // of `model`, declared after it
  Tolerances tolerances;  // RK45's, for the message when they cannot be met
  State lastGood;         // the state before the current frame's steps, shown if they diverge
  int n;

  // The run's length (--steps, --time), where the window pauses once; none: it runs on.
  std::optional<long long> endStep;
  std::optional<double> endTime;  // s, with --time: endStep is counted again when dt changes
  std::string endName;            // how the command line said it: "--time 0.5 s"
  bool paused = false, diverged = false, ended = false, realTime = false;
  std::future<std::string> diagnosis;  // of the divergence, while it is under way
  // Diagnoses of a divergence the panel has since applied a change to: let run out, unread (a
  // future of std::async waits for its thread when dropped).
  std::vector<std::future<std::string>> staleDiagnoses;
  std::string divergedAt;  // "diverged at step N (t=T s): reason"

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

  // The parameter panel (graphics/panel.h); none in a build without Dear ImGui. Shared, not unique:
  // its type is complete only in graphics/panel*.cpp.
  std::shared_ptr<PanelState> panel;
  std::future<StepVerdict> verdictLeft;  // its verdict under way when it stopped (stopPanel)

  Viewer(const WorldFile& file, const RunOptions& run, const PictureOptions& pictures)
      : model(makeModel(file.world, file.state)),
        initial(file.state),
        simulation(model, file.state, file.run, run.tolerances),
        tolerances(run.tolerances),
        lastGood(file.state),
        n(file.run.n),
        pictures(pictures),
        worldPath(run.worldPath),
        stem(worldStem(run.worldPath)),
        clock(pictures.fps, file.run.n, file.run.dt),
        camera(cameraFor(model, pictures.camera)),
        width(pictures.width),
        height(pictures.height) {
    draw.colouring = static_cast<Colouring>(pictures.colouring);
    pool = std::make_unique<ThreadPool>(threadsFor(model, run.threads));
    simulation.setPool(pool.get());
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

// The window's viewer, from freeglut's per-window data.
inline Viewer& viewer() { return *static_cast<Viewer*>(glutGetWindowData()); }

// Starts or stops saving frames (the space key; --frames starts it at once).
void toggleSaving(Viewer& v);

// p, r and the panel's run section: pause or run on; real-time pacing on or off (viewerinput.cpp).
void togglePause(Viewer& v);
void toggleRealTime(Viewer& v);
// One drawn frame's steps (n) of a paused run (the panel's "step a frame"; viewer.cpp).
void stepFrame(Viewer& v);

// The GLUT callbacks of keys and the mouse (viewerinput.cpp).
void keyboard(unsigned char key, int x, int y);
void keyboardUp(unsigned char key, int x, int y);
void special(int key, int x, int y);
void specialUp(int key, int x, int y);
void mouse(int button, int state, int x, int y);
void motion(int x, int y);
void passiveMotion(int x, int y);
void wheel(int wheel, int direction, int x, int y);

}  // namespace jello
