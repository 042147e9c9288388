// display.cpp: whether a window can be opened. Apart from the viewer, and Xlib included
// last, because Xlib's macros (Success, None, ...) collide with names in Eigen.

#include <cstdlib>
#include <string>

#include "graphics/graphics.h"
// Last: its macros would rename what the headers above declare.
#include <X11/Xlib.h>

namespace jello {

bool displayAvailable(std::string* why) {
  const char* name = std::getenv("DISPLAY");
  if (!name || !*name) {
    *why = "DISPLAY is not set";
    return false;
  }
  Display* display = XOpenDisplay(nullptr);
  if (!display) {
    *why = std::string("cannot open display ") + name;
    return false;
  }
  XCloseDisplay(display);
  return true;
}

}  // namespace jello
