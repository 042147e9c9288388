// progress.cpp: see progress.h.

#include "core/progress.h"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace jello {

Progress::Progress() : enabled_(::isatty(STDERR_FILENO) == 1) {}

Progress::~Progress() { finish(); }

namespace {

// The characters a line may have: one less than the terminal's width (the cursor stays on the
// row), or no limit when the terminal does not say.
std::size_t lineLimit() {
  winsize size{};
  if (::ioctl(STDERR_FILENO, TIOCGWINSZ, &size) != 0 || size.ws_col < 2) return std::string::npos;
  return size.ws_col - 1u;
}

}  // namespace

void Progress::finish() {
  const std::size_t blank = std::min(width_, lineLimit());
  if (blank > 0) std::fprintf(stderr, "\r%*s\r", static_cast<int>(blank), "");
  width_ = 0;
}

void Progress::finish(const std::string& lastLine) {
  if (!enabled_) return;
  show(lastLine);
  std::fputc('\n', stderr);
  width_ = 0;
}

void Progress::show(const std::string& text) {
  if (!enabled_) return;
  const std::size_t limit = lineLimit();
  const std::string line = text.substr(0, limit);
  // Spaces after a line shorter than the last one wipe what would be left of that one.
  const std::size_t blank = std::min(width_, limit);
  const int padding = static_cast<int>(blank > line.size() ? blank - line.size() : 0);
  std::fprintf(stderr, "\r%s%*s", line.c_str(), padding, "");
  std::fflush(stderr);
  width_ = std::max(width_, line.size());
}

}  // namespace jello
