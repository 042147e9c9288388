// image.h: RGB pictures and JPEG files (libjpeg-turbo). Pixels are 8-bit RGB, rows top to
// bottom, no padding.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace jello {

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // width * height * 3
};

constexpr int kJpegQuality = 90;

// Writes `image` as a JPEG whole: a temporary file beside `path`, then a rename. Throws
// std::runtime_error with a one-line message on failure, leaving nothing behind.
void writeJpeg(const std::string& path, const Image& image, int quality = kJpegQuality);

// Decodes a JPEG file into RGB. Throws std::runtime_error when it cannot.
Image readJpeg(const std::string& path);

}  // namespace jello
