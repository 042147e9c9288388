// progress.cpp: see progress.h.

#include "core/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace jello {

Progress::Progress() : enabled_(::isatty(STDERR_FILENO) == 1) {}

Progress::~Progress() { finish(); }

void Progress::finish() {
  if (width_ > 0) std::fputc('\n', stderr);
  width_ = 0;
}

void Progress::show(const std::string& line) {
  if (!enabled_) return;
  // Spaces after a line shorter than the last one wipe what would be left of that one.
  const int padding = static_cast<int>(width_ > line.size() ? width_ - line.size() : 0);
  std::fprintf(stderr, "\r%s%*s", line.c_str(), padding, "");
  std::fflush(stderr);
  width_ = std::max(width_, line.size());
}

}  // namespace jello
