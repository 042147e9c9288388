// graphics/viewerinput.cpp: the window's keys and mouse (README: The viewer): the camera, pause,
// recording and screenshots, colourings, the push and jump keys, and the left-drag pull.

#include <GL/freeglut.h>
#include <GL/glu.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "graphics/panel.h"
#include "graphics/viewerstate.h"

namespace jello {

void togglePause(Viewer& v) {
  if (v.diverged) {
    v.say("a diverged run stays paused: ESC quits");
    return;
  }
  if (v.ended) {  // p after the end runs on without one
    v.ended = false;
    v.endStep.reset();
    v.endTime.reset();
    v.standing.clear();
  }
  v.paused = !v.paused;
  v.realTimeStart = Clock::now();
  v.realTimeStartSim = v.time();
  v.rateSteps = 0;
  v.rateStart = Clock::now();
}

void toggleRealTime(Viewer& v) {
  v.realTime = !v.realTime;
  v.realTimeStart = Clock::now();
  v.realTimeStartSim = v.time();
}

namespace {

void toggleColourHold(Viewer& v) {
  if (v.draw.colouring == Colouring::Plain) {
    v.say("f holds the scale of a coloured surface: c colours it first");
  } else if (v.draw.colouring == Colouring::Friction) {
    v.say("the friction colouring has no scale to hold: its colours are states");
  } else if (v.draw.colourScale > 0) {
    v.draw.colourScale = 0;
    v.say("the colour scale fits each frame again");
  } else {
    v.draw.colourScale = fittedColourScale(v.model, v.state(), v.draw.colouring);
    v.say(textf("colour scale held at %g: a colour means the same value in every frame",
                v.draw.colourScale));
  }
}

// The next colouring in the order of Colouring, skipping Stress when no jelly is made of
// elements (a world of springs has no stress to show).
void nextColouring(Viewer& v) {
  Colouring next = v.draw.colouring;
  do {
    next = static_cast<Colouring>((static_cast<int>(next) + 1) % kColouringKinds);
  } while (next == Colouring::Stress && !v.model.forces.elements);
  v.draw.colouring = next;
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

// z, x and e: zoom in, out, and the camera as the window started.
void cameraKey(Viewer& v, unsigned char key) {
  if (key == 'z') v.camera.radius = std::max(kMinRadius, v.camera.radius - kZoomStep);
  if (key == 'x') v.camera.radius += kZoomStep;
  if (key == 'e') v.camera = cameraFor(v.model, v.pictures.camera);
}

}  // namespace

void special(int key, int x, int y) {
  Viewer& v = viewer();
  if (panelSpecial(v, key, x, y)) return;
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

void keyboard(unsigned char key, int x, int y) {
  Viewer& v = viewer();
  if (panelKeyboard(v, key, x, y)) return;  // typed into the panel
  switch (key) {
    case kEscape:
      stopPanel(v);  // while its GL context is current
      glutLeaveMainLoop();
      break;
    case 'z':
    case 'x':
    case 'e':
      cameraKey(v, key);
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
      toggleRealTime(v);
      break;
    case 'g':
      togglePanel(v);
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

void keyboardUp(unsigned char key, int x, int y) { panelKeyboardUp(viewer(), key, x, y); }

void specialUp(int key, int x, int y) { panelSpecialUp(viewer(), key, x, y); }

void mouse(int button, int buttonState, int x, int y) {
  Viewer& v = viewer();
  if (panelMouse(v, button, buttonState, x, y)) return;
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
  if (panelMotion(v, x, y)) return;
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

void passiveMotion(int x, int y) { panelMotion(viewer(), x, y); }

void wheel(int wheel, int direction, int x, int y) { panelWheel(viewer(), wheel, direction, x, y); }

}  // namespace jello
