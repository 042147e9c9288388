// io/linesource.cpp: a world file's lines (linesource.h).

#include "io/linesource.h"

#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <system_error>

namespace jello {

LineSource::Status LineSource::next(std::string_view* line) {
  if (fd_ < 0) {
    if (pos_ >= memory_.size()) return Status::End;
    std::size_t end = memory_.find('\n', pos_);
    if (end == std::string_view::npos) end = memory_.size();
    if (end - pos_ > kMaxLineLength) {  // as for a file: the same text, the same verdict
      *line = memory_.substr(pos_, kMaxLineLength);
      return Status::TooLong;
    }
    *line = memory_.substr(pos_, end - pos_);
    consumed(end + 1 - pos_);
    pos_ = end + 1;
    return Status::Line;
  }
  std::size_t searched = begin_;
  for (;;) {
    const char* start = buffer_.data() + searched;
    const void* newline = std::memchr(start, '\n', end_ - searched);
    if (newline) {
      std::size_t at = static_cast<const char*>(newline) - buffer_.data();
      if (at - begin_ > kMaxLineLength) {  // a long line that arrived whole within one block
        *line = std::string_view(buffer_.data() + begin_, kMaxLineLength);
        return Status::TooLong;
      }
      *line = std::string_view(buffer_.data() + begin_, at - begin_);
      consumed(at + 1 - begin_);
      begin_ = at + 1;
      return Status::Line;
    }
    if (end_ - begin_ > kMaxLineLength) {
      *line = std::string_view(buffer_.data() + begin_,
                               kMaxLineLength);  // the start, for the message
      return Status::TooLong;
    }
    if (eof_) {
      if (begin_ == end_) return Status::End;
      *line = std::string_view(buffer_.data() + begin_, end_ - begin_);
      consumed(end_ - begin_);
      begin_ = end_;
      return Status::Line;
    }
    // Keep the partial line, read more after it.
    std::memmove(buffer_.data(), buffer_.data() + begin_, end_ - begin_);
    end_ -= begin_;
    begin_ = 0;
    searched = end_;
    if (buffer_.size() - end_ < kBlock) buffer_.resize(end_ + kBlock);
    if (!sizeKnown_) waitForData();
    ssize_t got;
    do got = ::read(fd_, buffer_.data() + end_, kBlock);
    while (got < 0 && errno == EINTR);
    if (got < 0) throw std::system_error(errno, std::generic_category(), "cannot read");
    if (got == 0) eof_ = true;
    end_ += static_cast<std::size_t>(got);
  }
}

void LineSource::waitForData() {
  pollfd waiting{fd_, POLLIN, 0};
  int ready;
  do ready = ::poll(&waiting, 1, kInputWaitSeconds * 1000);
  while (ready < 0 && errno == EINTR);
  if (ready == 0) throw Stalled{};
}

}  // namespace jello
