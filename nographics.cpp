// nographics.cpp: the pictures of a build without GL: none, said plainly.

#include <stdexcept>

#include "graphics.h"

namespace jello {

bool graphicsBuilt() { return false; }

bool displayAvailable(std::string* why) {
  *why = "this build of jello has no GL";
  return false;
}

std::unique_ptr<FrameObserver> makeOffscreenFrames(const PictureOptions&) {
  throw std::runtime_error("this build of jello has no GL, so it cannot render frames");
}

int runViewer(const RunOptions&, const PictureOptions&) { return kExitBadInput; }

}  // namespace jello
