// app/pictures.h: what a command asks of pictures (--frames, --size, --max-frames,
// --overwrite), apart from how they are made (graphics/, a library loaded only when needed).
#pragma once

#include <string>

namespace jello {

constexpr int kMinPictureSize = 16;  // pixels a side
constexpr int kMaxPictureSize = 8192;
constexpr int kDefaultMaxFrames = 300;
constexpr int kFrameDigits = 4;
constexpr int kMaxFrames = 10000;  // what four digits can number

// How pictures are made and kept.
struct PictureOptions {
  std::string framesDir;  // where frames go
  int maxFrames = kDefaultMaxFrames;
  bool overwrite = false;
  bool saveFromStart = false;  // the window saves from its first frame (--frames was given)
  int width = 640, height = 480;
};

}  // namespace jello
