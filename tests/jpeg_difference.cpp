// jpeg_difference A.jpg B.jpg [LIMIT]: prints the mean absolute difference of two pictures of
// the same size (0-255 per channel) and exits 0 when it is at most LIMIT (default 2), 1 when it
// is larger, 2 when the pictures cannot be compared.
#include <cstdio>
#include <cstdlib>
#include <exception>

#include "graphics/image.h"

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: jpeg_difference A.jpg B.jpg [LIMIT]\n");
    return 2;
  }
  try {
    jello::Image a = jello::readJpeg(argv[1]), b = jello::readJpeg(argv[2]);
    if (a.width != b.width || a.height != b.height) {
      std::fprintf(stderr, "sizes differ: %dx%d and %dx%d\n", a.width, a.height, b.width, b.height);
      return 2;
    }
    double sum = 0;
    for (std::size_t i = 0; i < a.rgb.size(); ++i) sum += std::abs(int(a.rgb[i]) - int(b.rgb[i]));
    double mean = sum / a.rgb.size(), limit = argc > 3 ? std::atof(argv[3]) : 2.0;
    std::printf("mean absolute difference %.3f (limit %.3f)\n", mean, limit);
    return mean <= limit ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
}
