// image.h: RGB pictures and JPEG files (libjpeg-turbo). Pixels are 8-bit RGB, rows top to
// bottom, no padding.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/output.h"

namespace jello {

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // width * height * 3
};

constexpr int kJpegQuality = 90;

// Writes `image` as a JPEG under the rules of output.h (whole, never over something that is not
// a regular file; over a regular file only with Existing::Replace). Throws OutputError with a
// one-line message on failure, leaving nothing behind.
void writeJpeg(const std::string& path, const Image& image, int quality = kJpegQuality,
               Existing existing = Existing::Refuse);

// Decodes a JPEG file into RGB. Throws std::runtime_error when it cannot.
Image readJpeg(const std::string& path);

}  // namespace jello
