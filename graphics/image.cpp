// image.cpp: JPEG encoding and decoding through libjpeg's classic API.
//
// libjpeg reports fatal errors by calling error_exit, which by default calls exit(); the
// handler here turns them into a longjmp back to the caller, which then throws, so that a bad
// file or a full disk is one message, not a dead process.

#include "graphics/image.h"

#include <sys/stat.h>
#include <unistd.h>

#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <stdexcept>

// jpeglib.h needs FILE and size_t declared first.
#include <jpeglib.h>

namespace jello {

namespace {

struct ErrorManager {
  jpeg_error_mgr base;
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX];
};

void onError(j_common_ptr info) {
  auto* manager = reinterpret_cast<ErrorManager*>(info->err);
  (*info->err->format_message)(info, manager->message);
  std::longjmp(manager->jump, 1);
}

void silence(j_common_ptr, int) {}

}  // namespace

namespace {
// This library holds its own copy of core/output (linked in, its symbols hidden): its list of
// temporary files is cleaned on a signal by its own handler, chained to the program's.
[[maybe_unused]] const bool kCleanupInstalled = (installSignalCleanup(), true);
}  // namespace

void writeJpeg(const std::string& path, const Image& image, int quality, Existing existing) {
  writeFileWhole(
      path,
      [&image, quality](std::FILE* file) {
        jpeg_compress_struct info;
        ErrorManager errors;
        info.err = jpeg_std_error(&errors.base);
        errors.base.error_exit = onError;
        if (setjmp(errors.jump)) {
          jpeg_destroy_compress(&info);
          throw std::runtime_error(std::string("cannot write JPEG: ") + errors.message);
        }
        jpeg_create_compress(&info);
        jpeg_stdio_dest(&info, file);
        info.image_width = static_cast<JDIMENSION>(image.width);
        info.image_height = static_cast<JDIMENSION>(image.height);
        info.input_components = 3;
        info.in_color_space = JCS_RGB;
        jpeg_set_defaults(&info);
        jpeg_set_quality(&info, quality, TRUE);
        jpeg_start_compress(&info, TRUE);
        const std::size_t stride = static_cast<std::size_t>(image.width) * 3;
        while (info.next_scanline < info.image_height) {
          JSAMPROW row = const_cast<JSAMPROW>(image.rgb.data() + info.next_scanline * stride);
          jpeg_write_scanlines(&info, &row, 1);
        }
        jpeg_finish_compress(&info);
        jpeg_destroy_compress(&info);
      },
      existing);
}

Image readJpeg(const std::string& path) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) throw std::runtime_error(path + ": cannot open: " + std::strerror(errno));
  jpeg_decompress_struct info;
  ErrorManager errors;
  info.err = jpeg_std_error(&errors.base);
  errors.base.error_exit = onError;
  errors.base.emit_message = silence;
  Image image;
  if (setjmp(errors.jump)) {
    jpeg_destroy_decompress(&info);
    std::fclose(file);
    throw std::runtime_error(path + ": not a readable JPEG: " + errors.message);
  }
  jpeg_create_decompress(&info);
  jpeg_stdio_src(&info, file);
  jpeg_read_header(&info, TRUE);
  info.out_color_space = JCS_RGB;
  jpeg_start_decompress(&info);
  image.width = static_cast<int>(info.output_width);
  image.height = static_cast<int>(info.output_height);
  image.rgb.resize(static_cast<std::size_t>(image.width) * image.height * 3);
  while (info.output_scanline < info.output_height) {
    JSAMPROW row =
        image.rgb.data() + static_cast<std::size_t>(info.output_scanline) * image.width * 3;
    jpeg_read_scanlines(&info, &row, 1);
  }
  jpeg_finish_decompress(&info);
  jpeg_destroy_decompress(&info);
  std::fclose(file);
  return image;
}

}  // namespace jello
