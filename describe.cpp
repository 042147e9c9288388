// describe.cpp: a world in words.

#include "describe.h"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>

#include "physics.h"
#include "stability.h"

namespace jello {

namespace {

// The course's files hold six decimals: a value is "the same" within half of their last digit,
// plus a little for the rounding of the node coordinates themselves.
constexpr double kFileRounding = 1e-6;

std::string format(const char* pattern, ...) __attribute__((format(printf, 1, 2)));
std::string format(const char* pattern, ...) {
  char text[512];
  va_list args;
  va_start(args, pattern);
  std::vsnprintf(text, sizeof text, pattern, args);
  va_end(args);
  return text;
}

std::string vec(Vec3 v) { return format("(%.6g, %.6g, %.6g)", v.x, v.y, v.z); }

// "x - y - z + 4 = 0" for (1, -1, -1, 4).
std::string planeEquation(const Plane& p) {
  std::string out;
  const double coefficient[4] = {p.a, p.b, p.c, p.d};
  const char* names[4] = {"x", "y", "z", ""};
  for (int i = 0; i < 4; ++i) {
    double c = coefficient[i];
    if (c == 0) continue;
    out += out.empty() ? (c < 0 ? "-" : "") : (c < 0 ? " - " : " + ");
    if (std::fabs(c) != 1 || i == 3) out += format("%.9g", std::fabs(c)) + (i < 3 ? " " : "");
    out += names[i];
  }
  return out + " = 0";
}

Vec3 nodePosition(std::size_t node, int r) {
  std::size_t i = node / (static_cast<std::size_t>(r) * r), j = (node / r) % r, k = node % r;
  return {fieldNodeCoordinate(static_cast<int>(i), r), fieldNodeCoordinate(static_cast<int>(j), r),
          fieldNodeCoordinate(static_cast<int>(k), r)};
}

// Least-squares s of F ~ s * pattern(p) over the nodes, and whether every node fits.
bool fitsPattern(const ForceField& field, Vec3 (*pattern)(Vec3), double* strength) {
  const int r = field.resolution;
  const std::size_t nodes = field.forces.size() / 3;
  double num = 0, den = 0;
  for (std::size_t node = 0; node < nodes; ++node) {
    Vec3 g = pattern(nodePosition(node, r)), f = field.node(node);
    num += dot(f, g);
    den += dot(g, g);
  }
  if (den == 0) return false;
  *strength = num / den;
  for (std::size_t node = 0; node < nodes; ++node) {
    Vec3 g = pattern(nodePosition(node, r)), f = field.node(node);
    Vec3 misfit = f - *strength * g;
    if (std::max({std::fabs(misfit.x), std::fabs(misfit.y), std::fabs(misfit.z)}) > kFileRounding) return false;
  }
  return true;
}

Vec3 swirl(Vec3 p) { return {-p.y, p.x, 0}; }
Vec3 radial(Vec3 p) { return p; }

}  // namespace

double fieldNodeCoordinate(int index, int resolution) {
  return -kBoxHalfSize + 2 * kBoxHalfSize * index / (resolution - 1);
}

const char* fieldKindName(FieldKind kind) {
  switch (kind) {
    case FieldKind::Zero:
      return "zero";
    case FieldKind::Uniform:
      return "uniform";
    case FieldKind::Swirl:
      return "swirl";
    case FieldKind::Radial:
      return "radial";
    case FieldKind::General:
      return "general";
  }
  return "general";  // not reached: every kind is named above
}

FieldShape classifyField(const ForceField& field) {
  FieldShape shape;
  const std::vector<double>& f = field.forces;
  const std::size_t nodes = f.size() / 3;
  if (nodes == 0) return shape;
  shape.smallest = INFINITY;
  for (std::size_t node = 0; node < nodes; ++node) {
    double magnitude = length(field.node(node));
    shape.smallest = std::min(shape.smallest, magnitude);
    shape.largest = std::max(shape.largest, magnitude);
  }
  const FieldUse use = fieldUse(field);  // the exact zero and uniform tests, as the kernel's
  if (use == FieldUse::Zero) return shape;
  if (use == FieldUse::Uniform) {
    shape.kind = FieldKind::Uniform;
    shape.uniform = field.node(0);
    return shape;
  }
  if (field.resolution >= 2) {
    if (fitsPattern(field, swirl, &shape.strength)) {
      shape.kind = FieldKind::Swirl;
      return shape;
    }
    if (fitsPattern(field, radial, &shape.strength)) {
      shape.kind = FieldKind::Radial;
      return shape;
    }
  }
  shape.kind = FieldKind::General;
  return shape;
}

Extent extentOf(const State& state) {
  Extent e;
  e.lower = e.upper = load(state.p(), 0);
  for (int q = 0; q < kNumPoints; ++q) {
    Vec3 p = load(state.p(), q);
    e.lower = {std::min(e.lower.x, p.x), std::min(e.lower.y, p.y), std::min(e.lower.z, p.z)};
    e.upper = {std::max(e.upper.x, p.x), std::max(e.upper.y, p.y), std::max(e.upper.z, p.z)};
    e.centroid += p;
  }
  e.centroid = (1.0 / kNumPoints) * e.centroid;
  return e;
}

std::string describeWorld(const World& w, const State& state) {
  std::string out;
  out += format("integrator  %s, dt %.9g s, n %d (a drawn frame every %.9g s)\n", integratorName(w.integrator), w.dt,
                w.n, w.dt * w.n);
  out += format("springs     kElastic %.9g N/m, dElastic %.9g N s/m\n", w.kElastic, w.dElastic);
  out += format("collisions  kCollision %.9g N/m, dCollision %.9g N s/m\n", w.kCollision, w.dCollision);
  out += format("mass        %.9g kg a point, %.9g kg in all\n", w.mass, w.mass * kNumPoints);

  FieldShape shape = classifyField(w.field);
  std::string field = w.field.resolution == 0
                          ? std::string("field       none")
                          : format("field       R = %d, %s", w.field.resolution, fieldKindName(shape.kind));
  switch (shape.kind) {
    case FieldKind::Uniform:
      field += " F = " + vec(shape.uniform) + " N";
      break;
    case FieldKind::Swirl:
      field += format(" about z, F = %.6g (-y, x, 0) N", shape.strength);
      break;
    case FieldKind::Radial:
      field += format(", F = %.6g (x, y, z) N", shape.strength);
      break;
    case FieldKind::Zero:
    case FieldKind::General:
      break;
  }
  if (shape.kind != FieldKind::Zero) field += format("; |F| from %.6g to %.6g N", shape.smallest, shape.largest);
  out += field + "\n";

  Extent e = extentOf(state);
  out += "cube        from " + vec(e.lower) + " to " + vec(e.upper) + " m, centroid " + vec(e.centroid) + " m\n";
  bool outside = std::max({std::fabs(e.lower.x), std::fabs(e.lower.y), std::fabs(e.lower.z), std::fabs(e.upper.x),
                           std::fabs(e.upper.y), std::fabs(e.upper.z)}) > kBoxHalfSize;
  if (outside) out += "            partly outside the box [-2,2]^3\n";
  Vec3 meanVelocity;
  double fastest = 0;
  for (int q = 0; q < kNumPoints; ++q) {
    Vec3 v = load(state.v(), q);
    meanVelocity += v;
    fastest = std::max(fastest, length(v));
  }
  meanVelocity = (1.0 / kNumPoints) * meanVelocity;
  out += "velocity    mean " + vec(meanVelocity) + format(" m/s, fastest point %.6g m/s\n", fastest);

  if (w.hasPlane) {
    const Plane& pl = w.plane;
    Model model = makeModel(w, state);
    int across = pointsAcrossPlane(model, state);
    out += "plane       " + planeEquation(pl) +
           format("; the cube starts on its %s side", model.planeSide > 0 ? "positive" : "negative");
    out += across ? format(", %d points across it\n", across) : "\n";
  } else {
    out += "plane       none\n";
  }
  double limit = criticalStep(w.integrator, lineariseAtRest(w).modes);
  if (std::string beyond = beyondDoubles(w, state); !beyond.empty()) {
    out += "stability   beyond what double arithmetic can simulate: " + beyond + "\n";
  } else if (std::isfinite(limit)) {
    out += format(
        "stability   %s dt %.9g: %s (%.0f%% of its limit %.3g s at rest; see jello --check)\n",
        integratorName(w.integrator), w.dt,
        verdictName(verdictFor(w.dt, limit, stableFraction(w, state))), 100 * w.dt / limit, limit);
  } else {
    out += format("stability   %s: no step limit\n", integratorName(w.integrator));
  }
  return out;
}

}  // namespace jello
