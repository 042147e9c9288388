// model/term.cpp: what the terms share: the positions' bounds and the description's printf.

#include "model/term.h"

#include <algorithm>
#include <cstdarg>
#include <cstdio>

#include "core/assert.h"
#include "model/pack.h"

namespace jello {

// Eight running bounds side by side (one Pack), not one: an element-wise min, where a single
// running min is a reduction the compiler may not reorder. (Written as arrays of 8 lanes, GCC
// left it scalar: 0.43 us, 4% of a force evaluation; as Packs 0.1 us.)
// A body whose count is not a multiple of 8 takes its last points one by one, with the same
// comparisons.
Bounds boundsOf(const double* p, int n, PointRange r) {
  JELLO_ASSERT(0 <= r.begin && r.begin < r.end && r.end <= n);
  const int packed = r.end - r.begin >= kPackLanes ? groupedEnd(r, kPackLanes) : r.begin;
  double lower[3], upper[3];
  for (int axis = 0; axis < 3; ++axis) {
    const double* c = p + axis * n;
    lower[axis] = upper[axis] = c[r.begin];
    if (packed > r.begin) {
      Pack lo = loadPack(c + r.begin), hi = lo;
      for (int q = r.begin + kPackLanes; q < packed; q += kPackLanes) {
        const Pack x = loadPack(c + q);
        lo = byPiece([](NativePack xs, NativePack low) { return xs < low ? xs : low; }, x, lo);
        hi = byPiece([](NativePack xs, NativePack high) { return xs > high ? xs : high; }, x, hi);
      }
      double lows[kPackLanes], highs[kPackLanes];
      storePack(lows, lo);
      storePack(highs, hi);
      lower[axis] = *std::min_element(lows, lows + kPackLanes);
      upper[axis] = *std::max_element(highs, highs + kPackLanes);
    }
    for (int q = packed; q < r.end; ++q) {
      lower[axis] = c[q] < lower[axis] ? c[q] : lower[axis];
      upper[axis] = c[q] > upper[axis] ? c[q] : upper[axis];
    }
  }
  return {{lower[0], lower[1], lower[2]}, {upper[0], upper[1], upper[2]}};
}

Bounds boundsOf(const double* p, int n) { return boundsOf(p, n, {0, n}); }

std::string textf(const char* pattern, ...) {
  char text[512];
  va_list args;
  va_start(args, pattern);
  std::vsnprintf(text, sizeof text, pattern, args);
  va_end(args);
  return text;
}

}  // namespace jello
