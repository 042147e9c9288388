// offscreen.cpp: OSMesa renders into memory we own; that memory is the frame.

#include "graphics/offscreen.h"

#include <GL/osmesa.h>

#include <cstdint>
#include <string>
#include <vector>

#include "graphics/frames.h"

namespace jello {

struct OffscreenRenderer::Context {
  OSMesaContext context = nullptr;
  std::vector<std::uint8_t> rgba;  // OSMesa's colour buffer, rows bottom to top
};

OffscreenRenderer::OffscreenRenderer(int width, int height)
    : context_(std::make_unique<Context>()) {
  if (width < kMinPictureSize || height < kMinPictureSize || width > kMaxPictureSize ||
      height > kMaxPictureSize) {
    throw std::runtime_error("picture size " + std::to_string(width) + "x" +
                             std::to_string(height) + " is out of range (" +
                             std::to_string(kMinPictureSize) + " to " +
                             std::to_string(kMaxPictureSize) + " pixels a side)");
  }
  const int depthBits = 24, stencilBits = 0, accumBits = 0;
  context_->context =
      OSMesaCreateContextExt(OSMESA_RGBA, depthBits, stencilBits, accumBits, nullptr);
  if (!context_->context)
    throw std::runtime_error("OSMesa could not create an off-screen GL context");
  context_->rgba.resize(static_cast<std::size_t>(width) * height * 4);
  if (!OSMesaMakeCurrent(context_->context, context_->rgba.data(), GL_UNSIGNED_BYTE, width,
                         height)) {
    OSMesaDestroyContext(context_->context);
    throw std::runtime_error("OSMesa could not make its off-screen GL context current");
  }
  image_.width = width;
  image_.height = height;
  image_.rgb.resize(static_cast<std::size_t>(width) * height * 3);
}

OffscreenRenderer::~OffscreenRenderer() {
  if (context_->context) OSMesaDestroyContext(context_->context);
}

const Image& OffscreenRenderer::render(const Model& model, const State& state, const Camera& camera,
                                       const DrawOptions& options) {
  drawPicture(model, state, camera, options, image_.width, image_.height);
  glFinish();
  const int w = image_.width, h = image_.height;
  for (int row = 0; row < h; ++row) {
    const std::uint8_t* from =
        context_->rgba.data() + static_cast<std::size_t>(h - 1 - row) * w * 4;
    std::uint8_t* to = image_.rgb.data() + static_cast<std::size_t>(row) * w * 3;
    for (int x = 0; x < w; ++x) {
      to[3 * x] = from[4 * x];
      to[3 * x + 1] = from[4 * x + 1];
      to[3 * x + 2] = from[4 * x + 2];
    }
  }
  return image_;
}

}  // namespace jello

// ---------------------------------------------------------------------------------------------
// The frames of a headless run.

namespace jello {

namespace {

class OffscreenFrames : public FrameObserver {
 public:
  explicit OffscreenFrames(const PictureOptions& pictures)
      : options_(pictures),
        renderer_(pictures.width, pictures.height),
        sequence_(pictures.framesDir, pictures.maxFrames, pictures.overwrite) {
    draw_.colouring = static_cast<Colouring>(pictures.colouring);
  }

  const PictureOptions& options() const override { return options_; }
  void begin() override { sequence_.open(); }
  void frame(const Model& model, const State& state, long long, double) override {
    sequence_.save(renderer_.render(model, state, cameraFor(model, options_.camera), draw_));
  }
  bool wantsMore() const override { return !sequence_.full(); }
  int framesDone() const override { return sequence_.written(); }
  std::string describe() const override {
    return std::to_string(sequence_.written()) + " frames in " + folders();
  }
  std::string folders() const override { return sequence_.dir() + "/"; }

 private:
  PictureOptions options_;
  OffscreenRenderer renderer_;
  FrameSequence sequence_;
  DrawOptions draw_;
};

}  // namespace

std::unique_ptr<FrameObserver> makeOffscreenFrames(const PictureOptions& pictures) {
  return std::make_unique<OffscreenFrames>(pictures);
}

}  // namespace jello
