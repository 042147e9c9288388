// graphics.h: what the command line needs of the pictures: the GLUT window, and frames rendered
// off-screen. They live in a shared library, libjello_graphics.so, which jello loads only when
// a run needs pictures: a headless run without --frames loads no GL, GLUT, X11 or JPEG
// library, and a build without the GL development packages has no such library at all.
#pragma once

#include <memory>
#include <string>

#include "app/graphicsapi.h"
#include "app/headless.h"
#include "app/pictures.h"
#include "graphics/frames.h"

namespace jello {

// In libjello_graphics.so, whose one exported entry point, jelloGraphicsApi (app/graphicsapi.h),
// hands these to jello:
// True when a window can be opened; otherwise why not, in a few words.
bool displayAvailable(std::string* why);

// The frames of a headless run, rendered off-screen into JPEGs. Throws std::runtime_error
// with a one-line message when no off-screen context can be made.
std::unique_ptr<FrameObserver> makeOffscreenFrames(const PictureOptions& pictures);

// Opens the viewer (README: The viewer) on the world of `run`; says how it went (outcome.h).
Outcome runViewer(const RunOptions& run, const PictureOptions& pictures);

}  // namespace jello
