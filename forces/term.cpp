// forces/term.cpp: what the terms share: the positions' bounds and the description's printf.

#include "forces/term.h"

#include <algorithm>
#include <cstdarg>
#include <cstdio>

namespace jello {

// Eight running bounds side by side, not one: an element-wise min the compiler vectorises,
// where a single running min is a reduction it may not reorder.
Bounds boundsOf(const double* p) {
  constexpr int kLanes = 8;
  static_assert(kNumPoints % kLanes == 0);
  double lower[3], upper[3];
  for (int axis = 0; axis < 3; ++axis) {
    const double* c = p + axis * kNumPoints;
    double lo[kLanes], hi[kLanes];
    for (int l = 0; l < kLanes; ++l) lo[l] = hi[l] = c[l];
    for (int q = kLanes; q < kNumPoints; q += kLanes)
      for (int l = 0; l < kLanes; ++l) {
        lo[l] = c[q + l] < lo[l] ? c[q + l] : lo[l];
        hi[l] = c[q + l] > hi[l] ? c[q + l] : hi[l];
      }
    lower[axis] = *std::min_element(lo, lo + kLanes);
    upper[axis] = *std::max_element(hi, hi + kLanes);
  }
  return {{lower[0], lower[1], lower[2]}, {upper[0], upper[1], upper[2]}};
}

std::string textf(const char* pattern, ...) {
  char text[512];
  va_list args;
  va_start(args, pattern);
  std::vsnprintf(text, sizeof text, pattern, args);
  va_end(args);
  return text;
}

}  // namespace jello
