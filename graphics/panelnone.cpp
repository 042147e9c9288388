// graphics/panelnone.cpp: the panel of a build without Dear ImGui (panel.h): none; `g` says so.

#include "graphics/panel.h"
#include "graphics/viewerstate.h"

namespace jello {

bool panelBuilt() { return false; }
void startPanel(Viewer&) {}
void stopPanel(Viewer&) {}
void togglePanel(Viewer& v) {
  v.say(
      "this jello was built without the panel (it needs Dear ImGui, libimgui-dev; "
      "cmake -DJELLO_PANEL=OFF leaves it out)");
}
void drawPanel(Viewer&) {}
void pollPanel(Viewer&) {}
bool panelKeyboard(Viewer&, unsigned char, int, int) { return false; }
void panelKeyboardUp(Viewer&, unsigned char, int, int) {}
bool panelSpecial(Viewer&, int, int, int) { return false; }
void panelSpecialUp(Viewer&, int, int, int) {}
bool panelMouse(Viewer&, int, int, int, int) { return false; }
bool panelMotion(Viewer&, int, int) { return false; }
void panelWheel(Viewer&, int, int, int, int) {}

}  // namespace jello
