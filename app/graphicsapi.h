// app/graphicsapi.h: the pictures as the command line sees them: the GLUT window and frames
// rendered off-screen, three functions behind one table. They live in a shared library,
// libjello_graphics.so (graphics/), which jello loads only when a run needs pictures: a headless
// run without --frames loads no GL, GLUT, X11 or JPEG library, and a build without the GL
// development packages has no such library at all. The table is declared here, below graphics/,
// so that the commands call up into the library only through it.
#pragma once

#include <memory>
#include <string>

#include "app/headless.h"
#include "app/pictures.h"

namespace jello {

// The library's functions, as jello finds them after loading it.
struct GraphicsApi {
  bool (*displayAvailable)(std::string* why);
  std::unique_ptr<FrameObserver> (*makeOffscreenFrames)(const PictureOptions& pictures);
  Outcome (*runViewer)(const RunOptions& run, const PictureOptions& pictures);
};
// The library's one exported entry point (graphics/viewer.cpp); its name is kGraphicsEntry.
extern "C" const GraphicsApi* jelloGraphicsApi();
constexpr const char* kGraphicsEntry = "jelloGraphicsApi";
constexpr const char* kGraphicsLibrary = "libjello_graphics.so";

// In jello: loads the library (once) from the executable's folder or the build folder. nullptr,
// with the reason in a few words in *why, when this build has none or it cannot be loaded.
const GraphicsApi* loadGraphics(std::string* why);

}  // namespace jello
