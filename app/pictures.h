// app/pictures.h: what a command asks of pictures (--frames, --size, --max-frames,
// --overwrite) and of the meshes saved with them (--export, --export-format), apart from how
// pictures are made (graphics/, a library loaded only when needed).
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "core/limits.h"

namespace jello {

// The colourings of the cube's surface by name, in the order the window's `c` cycles them
// (showCube.h's Colouring): --colouring starts a run's pictures in one of them.
constexpr const char* kColouringNames[] = {"plain", "strain", "force", "stress", "friction"};
constexpr int kColouringCount = 5;

// --camera AZIMUTH,ELEVATION[,DISTANCE]: where the camera of a run's pictures starts (README: The
// viewer), on its sphere around the origin.
constexpr double kMostCameraElevation = 89;  // degrees: short of the poles, as a right-drag stops
constexpr double kMinCameraDistance = 0.5;   // m, as near as the window's zoom goes
// m: the farthest a camera goes, half the picture's depth range (showCube.cpp draws to 100 m), so
// that a box as large again around the origin is still in the picture.
constexpr double kMaxCameraDistance = 50;
struct CameraRequest {
  double azimuth = 0;    // degrees around the up axis (+z, or against gravity), from +x with +z up
  double elevation = 0;  // degrees above the plane normal to the up axis
  double distance = 0;   // m from the origin; 0: the world's default (farther for a large box)
};

// The file format of exported surface meshes (app/export.h).
enum class MeshFormat { Obj, Ply, Vtu };

// How pictures are made and kept.
struct PictureOptions {
  std::string framesDir;  // where frames go
  std::string exportDir;  // where the surface meshes go (--export); "" for none
  MeshFormat exportFormat = MeshFormat::Obj;
  int maxFrames = kDefaultMaxFrames;
  double fps = kDefaultFps;  // saved frames per simulated second; 0: one per drawn frame (n steps)
  bool overwrite = false;
  bool framesNamed = false;    // --frames DIR was given: the window's recording goes there
  bool saveFromStart = false;  // the window saves from its first frame (--frames or --export)
  int width = 640, height = 480;
  std::optional<CameraRequest> camera;  // --camera; none: the world's default camera
  int colouring = 0;                    // --colouring, an index of kColouringNames
};

// The name new frames folders of a world are made from (makeNewFolder, core/output.h):
// "world/rotate.w" -> "rotate".
inline std::string worldStem(const std::string& worldPath) {
  const std::size_t slash = worldPath.find_last_of('/');
  std::string name = slash == std::string::npos ? worldPath : worldPath.substr(slash + 1);
  const std::size_t dot = name.rfind('.');
  return dot == std::string::npos || dot == 0 ? name : name.substr(0, dot);
}

// The steps at which frames are saved: frame k at the first step at or past k / fps simulated
// seconds (a frame of time t shows the state at the step ending nearest after t), or, with fps
// 0, every n steps (the course's: a frame per drawn frame). Never two frames of one step: when
// fps * dt > 1 the frames are as many as the steps.
class FrameClock {
 public:
  FrameClock(double fps, int n, double dt) : fps_(fps), n_(n), dt_(dt) {}
  // The same for a run whose dt changed at step `stepBase`, at `timeBase` s (the window's panel):
  // step s is at timeBase + (s - stepBase) * dt.
  FrameClock(double fps, int n, double dt, long long stepBase, double timeBase)
      : fps_(fps), n_(n), dt_(dt), stepBase_(stepBase), timeBase_(timeBase) {}

  // The step of the next frame due after `step` (step 0's frame is the first).
  long long nextAfter(long long step) const {
    if (fps_ <= 0) return (step / n_ + 1) * n_;
    if (stepBase_ > 0) {
      const double next =
          std::floor((timeBase_ + (step - stepBase_) * dt_) * fps_ * (1 + kRounding)) + 1;
      const double at = std::ceil((next / fps_ - timeBase_) / dt_ * (1 - kRounding));
      return std::max(step + 1, stepBase_ + static_cast<long long>(std::min(at, kMostSteps)));
    }
    // Frames at k / fps; the first k past step * dt * fps. The factor keeps a step that is a
    // frame's time up to rounding (0.1 s at dt 0.001 and 10 fps) that frame's step.
    const double next = std::floor(step * dt_ * fps_ * (1 + kRounding)) + 1;
    const double at = std::ceil(next / (dt_ * fps_) * (1 - kRounding));
    return std::max(step + 1, static_cast<long long>(std::min(at, kMostSteps)));
  }
  // The steps of the first `frames` frames (frame 0 at step 0): a default run's length.
  long long stepsForFrames(int frames) const {
    long long step = 0;
    for (int k = 1; k < frames; ++k) step = nextAfter(step);
    return step;
  }

 private:
  static constexpr double kRounding = 1e-12;
  static constexpr double kMostSteps = 9e18;  // below LLONG_MAX: the cast is defined
  double fps_;
  int n_;
  double dt_;
  long long stepBase_ = 0;
  double timeBase_ = 0;
};

}  // namespace jello
