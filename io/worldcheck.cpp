// io/worldcheck.cpp: the rules a world in memory keeps to be written as a world file and read
// back (findWorldProblem, io/input.h): the reader's rules on values, without the text.

#include <cmath>
#include <optional>
#include <string>

#include "core/assert.h"
#include "io/input.h"
#include "model/model.h"

namespace jello {

namespace {

std::string triple(const double* v, const char* unit) {
  char text[96];
  std::snprintf(text, sizeof text, "(%g, %g, %g) %s", v[0], v[1], v[2], unit);
  return text;
}

bool finite3(const double* v) {
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

// The parameters' rules, as parseLines applies them to a file's tokens.
std::optional<WorldProblem> findParameterProblem(const World& w, const RunSettings& run) {
  using Part = WorldProblem::Part;
  auto problem = [](Part part, const std::string& what) { return WorldProblem{part, 0, what}; };
  auto number = [](double value) {
    std::string text;
    appendNumber(text, value);
    return text;
  };
  if (!(std::isfinite(run.dt) && run.dt > 0))
    return problem(Part::Parameters, "dt must be > 0 and finite, got " + number(run.dt));
  if (run.n < 1) return problem(Part::Parameters, "n must be >= 1, got " + std::to_string(run.n));
  const std::pair<const char*, double> nonNegative[] = {{"kElastic", w.kElastic},
                                                        {"dElastic", w.dElastic},
                                                        {"kCollision", w.kCollision},
                                                        {"dCollision", w.dCollision}};
  for (auto [name, value] : nonNegative) {
    if (!(std::isfinite(value) && value >= 0))
      return problem(Part::Parameters,
                     std::string(name) + " must be >= 0 and finite, got " + number(value));
  }
  if (!(std::isfinite(w.mass) && w.mass > 0))
    return problem(Part::Parameters, "mass must be > 0 and finite, got " + number(w.mass));
  if (w.hasPlane) {
    const double plane[4] = {w.plane.a, w.plane.b, w.plane.c, w.plane.d};
    if (!finite3(plane) || !std::isfinite(plane[3]))
      return problem(Part::Plane, "the plane's coefficients must be finite");
    if (!hasNormal(w.plane)) return problem(Part::Plane, "the plane's normal (a,b,c) is zero");
  }
  return std::nullopt;
}

}  // namespace

std::optional<WorldProblem> findWorldProblem(const World& w, const RunSettings& run,
                                             const State& state) {
  using Part = WorldProblem::Part;
  if (auto problem = findParameterProblem(w, run)) return problem;
  const int r = w.field.resolution;
  const std::size_t nodes = r > 0 ? static_cast<std::size_t>(r) * r * r : 0;
  if (r < 0 || r > kMaxResolution || w.field.forces.size() != 3 * nodes) {
    return WorldProblem{Part::Field, 0,
                        "the field's resolution " + std::to_string(r) + " does not match its " +
                            std::to_string(w.field.forces.size()) + " values"};
  }
  for (std::size_t n = 0; n < nodes; ++n) {
    const double* force = &w.field.forces[3 * n];
    if (finite3(force)) continue;
    const std::size_t i = n / (static_cast<std::size_t>(r) * r), j = (n / r) % r, k = n % r;
    return WorldProblem{Part::Field, n,
                        "the force at field node (" + std::to_string(i) + "," + std::to_string(j) +
                            "," + std::to_string(k) + ") is " + triple(force, "N") +
                            ", not finite"};
  }
  const std::pair<const double*, Part> arrays[] = {{state.p(), Part::Position},
                                                   {state.v(), Part::Velocity}};
  const int n = state.points();
  JELLO_ASSERT(n == bodyOf(w).count());
  for (auto [points, part] : arrays) {
    for (int q = 0; q < n; ++q) {
      const Vec3 a = load(points, q, n);
      const double value[3] = {a.x, a.y, a.z};
      if (finite3(value)) continue;
      const bool position = part == Part::Position;
      return WorldProblem{part, static_cast<std::size_t>(q),
                          std::string(position ? "the position" : "the velocity") + " of point " +
                              bodyOf(w).label(q) + " is " + triple(value, position ? "m" : "m/s") +
                              ", not finite"};
    }
  }
  return std::nullopt;
}

}  // namespace jello
