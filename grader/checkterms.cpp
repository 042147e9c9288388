// checkterms.cpp: the checks that isolate one force term each (rest, springs, dampers, walls,
// plane, field). Each compares two evaluations of computeAcceleration that differ in that term
// alone (one point moved, one velocity given, the cube moved rigidly across a wall, the field
// swapped), so that every other term, right or wrong, cancels out of the difference.
#include <array>
#include <cmath>

#include "grader/checkkit.h"
#include "solver/physics.h"

namespace jello::grader {
namespace {

using Offset = std::array<int, 3>;

const std::vector<Offset>& springOffsets(const std::string& kind) {
  static const std::vector<Offset> structural = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  static const std::vector<Offset> shear = {{1, 1, 0},  {1, -1, 0}, {1, 0, 1}, {1, 0, -1},
                                            {0, 1, 1},  {0, 1, -1}, {1, 1, 1}, {1, 1, -1},
                                            {1, -1, 1}, {1, -1, -1}};
  static const std::vector<Offset> bend = {{2, 0, 0}, {0, 2, 0}, {0, 0, 2}};
  return kind == "structural" ? structural : kind == "shear" ? shear : bend;
}

// Both directions of every offset of the kind.
std::vector<Offset> bothWays(const std::vector<Offset>& offsets) {
  std::vector<Offset> all;
  for (const Offset& o : offsets) {
    all.push_back(o);
    all.push_back({-o[0], -o[1], -o[2]});
  }
  return all;
}

const int kProbePoint = pointIndex(3, 3, 3);  // inside: every kind of neighbour on every side
int neighbour(const Offset& o) { return pointIndex(3 + o[0], 3 + o[1], 3 + o[2]); }

// Below this change of force (N) a neighbour feels nothing of the spring.
constexpr double kNoForce = 1e-7;
// Relative agreement that counts as exact (rounding only), and as near (a constant rounded).
constexpr double kExact = 1e-8;
constexpr double kRounded = 1e-4;

// One spring, measured: stiffness k and k * rest from the changes of force on the neighbour
// when the probe point moves by each of `moves` (D = k move + k rest (u - u0), least squares),
// and the part of the changes that this law does not explain.
struct SpringFit {
  double k = 0, rest = 0, unexplained = 0, largestChange = 0;
};

SpringFit fitSpring(const State& base, const std::vector<Vec3>& moves,
                    const std::vector<std::vector<double>>& answers, int r) {
  Vec3 pr = load(base.p(), r), pq = load(base.p(), kProbePoint);
  Vec3 u0 = (1 / length(pr - pq)) * (pr - pq);
  double a11 = 0, a12 = 0, a22 = 0, b1 = 0, b2 = 0, dd = 0;
  std::vector<std::array<Vec3, 3>> rows;
  for (std::size_t m = 0; m < moves.size(); ++m) {
    Vec3 d = forceChange(answers[m + 1], answers[0], r);
    Vec3 L = pr - (pq + moves[m]);
    Vec3 c2 = (1 / length(L)) * L - u0;
    a11 += dot(moves[m], moves[m]), a12 += dot(moves[m], c2), a22 += dot(c2, c2);
    b1 += dot(moves[m], d), b2 += dot(c2, d), dd += dot(d, d);
    rows.push_back({moves[m], c2, d});
  }
  SpringFit fit;
  double det = a11 * a22 - a12 * a12;
  double x = (b1 * a22 - b2 * a12) / det, y = (a11 * b2 - a12 * b1) / det;
  fit.k = x;
  fit.rest = x != 0 ? y / x : 0;
  for (const auto& row : rows) {
    Vec3 miss = row[2] - (x * row[0] + y * row[1]);
    fit.unexplained = std::fmax(fit.unexplained, length(miss));
    fit.largestChange = std::fmax(fit.largestChange, length(row[2]));
  }
  fit.unexplained /= std::fmax(fit.largestChange, 1e-300);
  return fit;
}

std::string kindOf(const Offset& o, const std::string& kind) {
  if (kind != "shear") return kind;
  return std::abs(o[0]) + std::abs(o[1]) + std::abs(o[2]) == 2 ? "face shear" : "body shear";
}

std::string restName(const Offset& o) {
  int squared = o[0] * o[0] + o[1] * o[1] + o[2] * o[2];
  return squared == 1 ? "1/7" : squared == 4 ? "2/7" : textf("sqrt(%d)/7", squared);
}

// The worst finding among the spring fits of a kind, in words.
CheckResult judgeSprings(const std::string& kind, const std::vector<Offset>& offsets,
                         const std::vector<SpringFit>& fits, double k) {
  std::string missing;
  int missingCount = 0;
  for (std::size_t n = 0; n < offsets.size(); ++n) {
    if (fits[n].largestChange >= kNoForce) continue;
    if (missingCount++ < 4) {
      missing +=
          (missing.empty() ? "" : ", ") + offsetName(offsets[n][0], offsets[n][1], offsets[n][2]);
    }
  }
  if (missingCount == static_cast<int>(offsets.size())) {
    return failed(kind, "no " + kind + " springs: moving a point changes no force on its " + kind +
                            " neighbours");
  }
  if (missingCount > 0) {
    return failed(
        kind, textf("%d of %zu %s springs missing, at offsets %s%s", missingCount, offsets.size(),
                    kind.c_str(), missing.c_str(), missingCount > 4 ? ", ..." : ""));
  }
  CheckResult worst =
      passed(kind, textf("%zu directions: stiffness and rest lengths as expected", offsets.size()));
  for (std::size_t n = 0; n < offsets.size(); ++n) {
    const Offset& o = offsets[n];
    const SpringFit& fit = fits[n];
    std::string at = kindOf(o, kind) + " spring at offset " + offsetName(o[0], o[1], o[2]);
    double expectedRest = std::sqrt(double(o[0] * o[0] + o[1] * o[1] + o[2] * o[2])) / 7;
    if (!(fit.unexplained <= 1e-6)) {  // every comparison is written to fail on a NaN
      return failed(kind,
                    "the force of the " + at + " is not a spring's: " +
                        textf("%.2g of it is not along the spring or not linear in its length",
                              fit.unexplained));
    }
    if (!(std::fabs(fit.k - k) <= kExact * k)) {
      std::string twice =
          std::fabs(fit.k - 2 * k) < 1e-3 * k ? " (each spring counted twice?)" : "";
      return failed(
          kind, textf("stiffness %.6g N/m measured on the %s, kElastic = %g N/m expected%s", fit.k,
                      at.c_str(), k, twice.c_str()) +
                    massHint(fit.k, k));
    }
    double error = std::fabs(fit.rest - expectedRest) / expectedRest;
    std::string line = textf("rest length %.9g m measured on the %s, %s = %.17g m expected",
                             fit.rest, at.c_str(), restName(o).c_str(), expectedRest);
    if (!(error <= kRounded)) return failed(kind, line);
    if (error > kExact && worst.grade == Grade::Pass) {
      worst = near(kind, line + ": a rounded constant, whose slow drift the agreement check shows");
    }
  }
  return worst;
}

}  // namespace

CheckResult checkRest(const std::string& probe) {
  World world = probeWorld();
  State still = restLattice(kCentred), turned = restLattice({0.13, -0.21, 0.08}, 0.7);
  std::string failure;
  auto answers = accelerationsAt(probe, world, {still, turned}, &failure);
  if (!failure.empty()) return failed("rest", failure + " on the cube at rest");
  // The scale of the accelerations a spring gives: kElastic * (1/7) / mass.
  double scale = world.kElastic * kRestSpacing / world.mass;
  for (std::size_t n = 0; n < 2; ++n) {
    const std::vector<double>& a = answers[n];
    if (!allUsable(a))
      return failed("rest", "NaN or infinity in the accelerations of the cube at rest");
    double most = largest(a);
    int q = 0;
    for (int p = 0; p < kNumPoints; ++p) {
      if (length(load(a.data(), p)) > length(load(a.data(), q))) q = p;
    }
    std::string line = textf(
        "%sthe cube at rest accelerates: %.3g m/s^2 at %s (a rest length or a term "
        "that should be zero at rest is off; the spring checks name it)",
        n == 0 ? "" : "turned and moved rigidly, ", most, pointName(q).c_str());
    if (!(most <= kRounded * scale)) return failed("rest", line);
    if (most > kExact * scale) return near("rest", line);
  }
  return passed("rest", "zero at rest, also turned and moved");
}

CheckResult checkSprings(const std::string& probe, const std::string& kind) {
  World world = probeWorld();
  State base = restLattice(kCentred);
  const std::vector<Vec3> moves = {
      {0.021, -0.013, 0.017}, {-0.011, 0.019, 0.008}, {0.005, 0.012, -0.023}};
  std::vector<State> states = {base};
  for (Vec3 move : moves) {
    states.push_back(base);
    store(states.back().p(), kProbePoint, load(base.p(), kProbePoint) + move);
  }
  std::string failure;
  auto answers = accelerationsAt(probe, world, states, &failure);
  if (!failure.empty()) return failed(kind, failure + " with one point moved");
  std::vector<Offset> offsets = bothWays(springOffsets(kind));
  std::vector<SpringFit> fits;
  for (const Offset& o : offsets) fits.push_back(fitSpring(base, moves, answers, neighbour(o)));
  return judgeSprings(kind, offsets, fits, world.kElastic);
}

CheckResult checkDampers(const std::string& probe) {
  World world = probeWorld();
  State base = restLattice(kCentred), moving = base, moved = base;
  const Vec3 w = {0.5, 0.2, 0.9};  // m/s: along no spring, across none
  store(moving.v(), kProbePoint, w);
  // Moved, the point shows which springs exist: a damper is looked for on those.
  store(moved.p(), kProbePoint, load(base.p(), kProbePoint) + Vec3{0.021, -0.013, 0.017});
  std::string failure;
  auto answers = accelerationsAt(probe, world, {base, moving, moved}, &failure);
  if (!failure.empty()) return failed("dampers", failure + " with one point moving");
  std::vector<Offset> offsets;
  for (const char* kind : {"structural", "shear", "bend"}) {
    for (const Offset& o : bothWays(springOffsets(kind))) offsets.push_back(o);
  }
  double d = world.dElastic;
  for (const Offset& o : offsets) {
    int r = neighbour(o);
    Vec3 u = load(base.p(), r) - load(base.p(), kProbePoint);
    u = (1 / length(u)) * u;
    // On the neighbour: -d ((v_r - v_q) . u) u = d (w . u) u.
    Vec3 change = forceChange(answers[1], answers[0], r);
    double along = dot(change, u) / dot(w, u);
    double across = length(change - dot(change, u) * u);
    std::string at = "the spring at offset " + offsetName(o[0], o[1], o[2]);
    if (across > 1e-6 * d) {
      bool whole = length(change - d * w) < 1e-6 * d;
      return failed("dampers", whole
                                   ? "the dampers act on the whole relative velocity, not only on "
                                     "its part along the spring (" +
                                         at + ")"
                                   : "the damping force of " + at + " is not along the spring");
    }
    if (length(change) < 1e-9) {
      // A missing spring has no damper either: the spring checks say so, not this one.
      if (length(forceChange(answers[2], answers[0], r)) < 1e-9) continue;
      return failed("dampers", "no damping on " + at);
    }
    if (std::fabs(along + d) < kExact * d) {
      return failed("dampers", "damping sign flipped: " + at +
                                   " speeds up the points' relative motion instead of slowing it");
    }
    if (!(std::fabs(along - d) <= kExact * d)) {
      return failed("dampers", textf("damping %.6g N s/m measured on %s, dElastic = %g expected",
                                     along, at.c_str(), d) +
                                   massHint(along, d));
    }
  }
  return passed("dampers",
                textf("%zu directions: along the spring, dElastic, slowing", offsets.size()));
}

}  // namespace jello::grader
