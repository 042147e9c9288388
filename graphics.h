// graphics.h: what the command line needs of the pictures: the GLUT window, and frames rendered
// off-screen. A build without the GL development packages links nographics.cpp instead, whose
// functions say so; the physics never depends on either.
#pragma once

#include <memory>
#include <string>

#include "frames.h"
#include "headless.h"

namespace jello {

constexpr int kMinPictureSize = 16;  // pixels a side
constexpr int kMaxPictureSize = 8192;

// How pictures are made and kept.
struct PictureOptions {
  std::string framesDir;  // where frames go
  int maxFrames = kDefaultMaxFrames;
  bool overwrite = false;
  bool saveFromStart = false;  // the window saves from its first frame (--frames was given)
  int width = 640, height = 480;
};

// False when this build has no GL.
bool graphicsBuilt();

// True when a window can be opened; otherwise why not, in a few words.
bool displayAvailable(std::string* why);

// The frames of a headless run, rendered off-screen into JPEGs. Throws std::runtime_error
// with a one-line message when no off-screen context can be made.
std::unique_ptr<FrameObserver> makeOffscreenFrames(const PictureOptions& pictures);

// Opens the viewer (SPEC.md section 5) on the world of `run`; returns the exit status.
int runViewer(const RunOptions& run, const PictureOptions& pictures);

}  // namespace jello
