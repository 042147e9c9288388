// graphics/panel.h: the window's parameter panel (README: The panel), drawn with Dear ImGui over
// the picture, never into saved frames: the run, the jelly, the world and the view, each change of
// the physics judged on a worker thread (analysis/stepverdict.h) before it is applied, and the
// setup saved as a scene (io/scenewriter.h). `g` opens and closes it.
//
// A build without Dear ImGui (libimgui-dev) has no panel: panelBuilt() is false, every input goes
// to the viewer, and `g` says why there is none (panelnone.cpp). Not for use outside
// graphics/viewer*.cpp and graphics/panel*.cpp.
#pragma once

namespace jello {

struct Viewer;

// Whether this build has the panel.
bool panelBuilt();
// After the window is made: the panel's context, open when the window is at least
// kPanelOpenWidth x kPanelOpenHeight. Before the window closes: its end.
void startPanel(Viewer& v);
void stopPanel(Viewer& v);
// `g`: opens or closes it.
void togglePanel(Viewer& v);
// In the display callback, after the frame was saved and the overlay drawn.
void drawPanel(Viewer& v);
// In the idle callback: a verdict that came in; the next one to start.
void pollPanel(Viewer& v);

// The input, given to the panel first: true when the panel takes it (a field being typed in, the
// cursor over the panel), and then it does not reach the viewer. The key and button releases
// only keep the panel's state (they do nothing in the viewer).
bool panelKeyboard(Viewer& v, unsigned char key, int x, int y);
void panelKeyboardUp(Viewer& v, unsigned char key, int x, int y);
bool panelSpecial(Viewer& v, int key, int x, int y);
void panelSpecialUp(Viewer& v, int key, int x, int y);
bool panelMouse(Viewer& v, int button, int state, int x, int y);
bool panelMotion(Viewer& v, int x, int y);
void panelWheel(Viewer& v, int wheel, int direction, int x, int y);

// The window size from which the panel starts open, pixels.
constexpr int kPanelOpenWidth = 960, kPanelOpenHeight = 600;

}  // namespace jello
