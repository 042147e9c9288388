// offscreen.h: pictures without a window or an X server, through OSMesa (Mesa's off-screen
// renderer) and the same drawing code as the window (showCube.h).
#pragma once

#include <memory>
#include <stdexcept>

#include "graphics/graphics.h"
#include "graphics/image.h"
#include "graphics/showCube.h"

namespace jello {

class OffscreenRenderer {
 public:
  // Creates a width x height RGBA context with a depth buffer. Throws std::runtime_error with
  // a one-line message when OSMesa cannot make one.
  OffscreenRenderer(int width, int height);
  ~OffscreenRenderer();
  OffscreenRenderer(const OffscreenRenderer&) = delete;
  OffscreenRenderer& operator=(const OffscreenRenderer&) = delete;

  // Draws the scene and returns it as an RGB picture, rows top to bottom. The reference stays
  // valid until the next call.
  const Image& render(const Model& model, const State& state, const Camera& camera,
                      const DrawOptions& options);

 private:
  struct Context;
  std::unique_ptr<Context> context_;
  Image image_;
};

}  // namespace jello
