// model/plane.cpp: the inclined plane: force, reach test, Jacobian, energy and description.

#include "model/plane.h"

#include <algorithm>
#include <cmath>

#include "model/pack.h"

namespace jello {

Plane normalisedPlane(const Plane& plane) {
  const double largest = std::max({std::fabs(plane.a), std::fabs(plane.b), std::fabs(plane.c)});
  if (largest == 0 || !std::isfinite(largest)) return plane;  // refused by the reader already
  int exponent;
  std::frexp(largest, &exponent);  // largest = m 2^exponent, m in [0.5, 1)
  return {std::ldexp(plane.a, -exponent), std::ldexp(plane.b, -exponent),
          std::ldexp(plane.c, -exponent), std::ldexp(plane.d, -exponent)};
}

std::string planeProblem(const Plane& plane) {
  if (!hasNormal(plane)) return "the plane's normal (a,b,c) is zero";
  if (!std::isfinite(normalisedPlane(plane).d)) {
    return "the plane is too far from the origin to simulate: d is more than 1e308 times the "
           "largest of |a|, |b|, |c|, beyond the range of doubles";
  }
  return "";
}

double allowedSide(const Plane& plane, const double* p, int n) {
  Vec3 centroid;
  for (int q = 0; q < n; ++q) centroid += load(p, q, n);
  centroid = (1.0 / n) * centroid;
  return planeValue(normalisedPlane(plane), centroid) >= 0 ? 1 : -1;
}

std::string planeEquation(const Plane& p) {
  std::string out;
  const double coefficient[4] = {p.a, p.b, p.c, p.d};
  const char* names[4] = {"x", "y", "z", ""};
  for (int i = 0; i < 4; ++i) {
    double c = coefficient[i];
    if (c == 0) continue;
    out += out.empty() ? (c < 0 ? "-" : "") : (c < 0 ? " - " : " + ");
    if (std::fabs(c) != 1 || i == 3) out += textf("%.9g", std::fabs(c)) + (i < 3 ? " " : "");
    out += names[i];
  }
  return out + " = 0";
}

void planeJacobian(const Plane& plane, double side, Vec3 p, const ContactSpring& spring,
                   Block3* dFdp, Block3* dFdv) {
  *dFdp = Block3{};
  *dFdv = Block3{};
  if (planeValue(plane, p) * side < 0)
    addContactJacobian(spring, {plane.a, plane.b, plane.c}, dFdp, dFdv);
}

// The margin covers the rounding by which a point's own value may differ from the corner's.
bool mayCrossPlane(const Plane& plane, double side, const Bounds& b) {
  auto lowest = [side](double coefficient, double lo, double hi) {
    return std::min(side * coefficient * lo, side * coefficient * hi);
  };
  double smallest = lowest(plane.a, b.lower.x, b.upper.x) + lowest(plane.b, b.lower.y, b.upper.y) +
                    lowest(plane.c, b.lower.z, b.upper.z) + side * plane.d;
  auto largest = [](double lo, double hi) { return std::max(std::fabs(lo), std::fabs(hi)); };
  double scale = std::fabs(plane.a) * largest(b.lower.x, b.upper.x) +
                 std::fabs(plane.b) * largest(b.lower.y, b.upper.y) +
                 std::fabs(plane.c) * largest(b.lower.z, b.upper.z) + std::fabs(plane.d);
  constexpr double kRelativeMargin = 1e-12;
  return !(smallest > kRelativeMargin * scale);
}

PlaneTerm::PlaneTerm(int points, const Plane& given, double side, const ContactSpring& spring)
    : ForceTerm(points),
      given_(given),
      plane_(normalisedPlane(given)),
      side_(side),
      spring_(spring) {}

int PlaneTerm::pointsAcross(const double* p) const {
  int across = 0;
  for (int q = 0; q < pointCount(); ++q)
    if (planeValue(plane_, at(p, q)) * side_ < 0) ++across;
  return across;
}

// Eight points at a time: where none of them is across the plane (most of the time, for most of
// the points) their forces are exactly 0.0 and only that is added; the contact springs, a square
// root and two divisions a point, are computed for the eight when one of them is across.
void PlaneTerm::addForcesOn(PointRange points, const double* p, const double* v, const Bounds*,
                            double* force) const {
  const int n = pointCount(), packed = groupedEnd(points, kPackLanes);
  for (int q = points.begin; q < packed; q += kPackLanes) {
    const Pack x = loadPack(p + q), y = loadPack(p + n + q), z = loadPack(p + 2 * n + q);
    const Pack s = planeValueAt(plane_, x, y, z);
    const Pack across = byPiece(
        [side = side_](NativePack values) {
          return values * side < 0 ? NativePack{} + 1 : NativePack{};
        },
        s);
    bool any = false;
    for (int l = 0; l < kPackLanes; ++l) any = any || across.lane(l) != 0;
    if (any) {
      for (int l = q; l < q + kPackLanes; ++l)
        addAt(force, l, planeForce(plane_, side_, at(p, l), at(v, l), spring_));
    } else {
      for (int a = 0; a < 3; ++a) storePack(force + a * n + q, loadPack(force + a * n + q) + 0.0);
    }
  }
  // A body whose count is not a multiple of 8 takes its last points one by one: where a point is
  // not across, its force is 0.0 as above.
  for (int q = packed; q < points.end; ++q)
    addAt(force, q, planeForce(plane_, side_, at(p, q), at(v, q), spring_));
}

void PlaneTerm::addJacobian(const double* p, const double*, JacobianSink* sink) const {
  Block3 dFdp, dFdv;
  for (int q = 0; q < pointCount(); ++q) {
    planeJacobian(plane_, side_, at(p, q), spring_, &dFdp, &dFdv);
    sink->addPoint(q, dFdp, dFdv);
  }
}

void PlaneTerm::addEnergy(const double* p, double* energy) const {
  const double norm2 = plane_.a * plane_.a + plane_.b * plane_.b + plane_.c * plane_.c;
  for (int q = 0; q < pointCount(); ++q) {
    double s = planeValue(plane_, at(p, q));
    if (s * side_ < 0) *energy += 0.5 * spring_.k * s * s / norm2;
  }
}

void PlaneTerm::summarise(std::vector<std::string>* kept, std::vector<std::string>*) const {
  kept->push_back("plane (when the bounding box reaches it)");
}

std::vector<TermLine> PlaneTerm::describe(const double* p) const {
  std::string text = planeEquation(given_) +
                     textf("; the cube starts on its %s side", side_ > 0 ? "positive" : "negative");
  if (int across = pointsAcross(p)) text += textf(", %d points across it", across);
  return {{"plane", text}};
}

}  // namespace jello
