// model/winding.cpp: a point's winding number about a body's surface (winding.h).

#include "model/winding.h"

#include <cmath>

#include "core/assert.h"

namespace jello {

double windingNumber(const Body& body, int part, const double* p, Vec3 x) {
  const int n = body.count();
  const int first = body.joined() ? body.partFirst[part] : 0;
  const int end = body.joined() ? body.partFirst[part + 1] : n;
  JELLO_ASSERT(part == 0 || body.joined());
  double total = 0;
  for (const Triangle& t : body.surface) {
    if (t[0] < first || t[0] >= end) continue;
    const Vec3 a = load(p, t[0], n) - x, b = load(p, t[1], n) - x, c = load(p, t[2], n) - x;
    const double la = length(a), lb = length(b), lc = length(c);
    const double numerator = dot(a, cross(b, c));
    const double denominator = la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la;
    total += 2 * std::atan2(numerator, denominator);
  }
  return total / (4 * M_PI);
}

}  // namespace jello
