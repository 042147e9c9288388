// graphics/pixels.h: drawing in a picture's pixels (text, panels, legends): an orthographic
// projection of width x height pixels, y down, without lighting or depth test, pushed by
// beginPixels and popped by endPixels, which restores the depth test.
#pragma once

namespace jello {

void beginPixels(int width, int height);
void endPixels();

}  // namespace jello
