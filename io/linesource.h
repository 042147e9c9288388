// io/linesource.h: the lines of a world file, from a text in memory or from a file descriptor
// read a block at a time (io/worldparser.cpp reads them).
#pragma once

#include <algorithm>
#include <cstddef>
#include <string>
#include <string_view>

namespace jello {

// How long an input that is not a regular file (a FIFO, a pipe, a terminal) may keep the reader
// waiting for a writer's first bytes, and then for each next block: a writer that has stopped
// sending is reported, not waited for forever. A slow writer that keeps sending is read.
constexpr int kInputWaitSeconds = 5;

// Where the reader's lines come from: a text in memory, or a file read a block at a time, so
// that reading stops at the first line that cannot belong to a world (a binary file, a device
// that never ends, a line with no end) instead of after the whole input.
class LineSource {
 public:
  explicit LineSource(std::string_view text) : memory_(text), remaining_(text.size()) {}
  // `size`: the file's size when it is a regular file, -1 when unknown (a pipe, a device).
  LineSource(int fd, long long size)
      : fd_(fd), sizeKnown_(size >= 0), remaining_(size >= 0 ? size : 0) {}

  enum class Status { Line, End, TooLong };
  // Thrown by next() when an input of unknown size sent nothing for kInputWaitSeconds.
  struct Stalled {};

  // The next line without its '\n', valid until the next call (for TooLong, its start).
  Status next(std::string_view* line);

  // Bytes not yet consumed, when the input's size is known.
  bool remainingKnown() const { return fd_ < 0 || sizeKnown_; }
  std::size_t remainingBytes() const { return remaining_; }

  static constexpr std::size_t kMaxLineLength = 4096;  // far beyond any record of a world

 private:
  static constexpr std::size_t kBlock = 1 << 16;
  void consumed(std::size_t bytes) { remaining_ -= std::min(remaining_, bytes); }

  // Waits until read() will not block (data, end of input or an error to report).
  void waitForData();

  std::string_view memory_;
  std::size_t pos_ = 0;
  int fd_ = -1;
  bool sizeKnown_ = false;
  std::string buffer_;
  std::size_t begin_ = 0, end_ = 0;
  bool eof_ = false;
  std::size_t remaining_ = 0;
};
}  // namespace jello
