// io/statefile.cpp: state files (statefile.h).

#include "io/statefile.h"

#include <array>
#include <string_view>

#include "core/limits.h"
#include "core/output.h"
#include "core/readfile.h"
#include "io/input.h"
#include "io/inputerror.h"
#include "model/term.h"

namespace jello {

namespace {

constexpr std::string_view kHeader = "body,index,x,y,z,vx,vy,vz";
constexpr const char* kFields[] = {"body", "index", "x", "y", "z", "vx", "vy", "vz"};

// Point q's jelly (from 1) and its index in it.
std::pair<int, int> placeOf(const Body& body, int q) {
  const int part = body.partOf(q);
  return {part + 1, q - (body.joined() ? body.partFirst[part] : 0)};
}

}  // namespace

std::string formatState(const Body& body, const State& state) {
  const int n = state.points();
  std::string out(kHeader);
  out += '\n';
  for (int q = 0; q < n; ++q) {
    const auto [jelly, index] = placeOf(body, q);
    out += std::to_string(jelly) + "," + std::to_string(index);
    const Vec3 p = load(state.p(), q, n), v = load(state.v(), q, n);
    for (double x : {p.x, p.y, p.z, v.x, v.y, v.z}) {
      out += ',';
      appendNumber(out, x);
    }
    out += '\n';
  }
  return out;
}

void writeStateFile(const std::string& path, const Body& body, const State& state) {
  writeFileWhole(path, formatState(body, state), Existing::Replace);
}

State parseState(const std::string& text, const std::string& name, const Body& body) {
  const int n = body.count();
  State state(n);
  std::size_t at = 0;
  int line = 0;
  auto fail = [&](const std::string& what, const char* field) {
    throw InputError(name + ":" + std::to_string(line) + ": " + what + " (" + field + ")");
  };
  auto nextLine = [&]() -> std::string_view {
    ++line;
    const std::size_t end = text.find('\n', at);
    std::string_view out(text.data() + at, (end == std::string::npos ? text.size() : end) - at);
    at = end == std::string::npos ? text.size() : end + 1;
    if (!out.empty() && out.back() == '\r') out.remove_suffix(1);
    return out;
  };
  if (nextLine() != kHeader) fail("expected the header " + std::string(kHeader), "header");
  for (int q = 0; q < n; ++q) {
    if (at >= text.size())
      fail("ends after " + std::to_string(q) + " points; the scene's body has " + std::to_string(n),
           "body");
    const std::string_view row = nextLine();
    std::array<std::string_view, 8> cells;
    std::size_t start = 0;
    for (int c = 0; c < 8; ++c) {
      const std::size_t comma = row.find(',', start);
      if ((comma == std::string_view::npos) != (c == 7)) fail("expected 8 fields", kFields[c]);
      cells[c] = row.substr(start, (comma == std::string_view::npos ? row.size() : comma) - start);
      start = comma + 1;
    }
    double value[8];
    for (int c = 0; c < 8; ++c) {
      std::string why;
      if (!parseWorldNumber(cells[c], &value[c], &why))
        fail("'" + std::string(cells[c]) + "' " + why, kFields[c]);
    }
    const auto [jelly, index] = placeOf(body, q);
    if (value[0] != jelly) fail("expected jelly " + std::to_string(jelly) + " here", "body");
    if (value[1] != index) fail("expected point " + std::to_string(index) + " here", "index");
    const double far = value[2] * value[2] + value[3] * value[3] + value[4] * value[4];
    if (!(far <= kDivergenceRadius * kDivergenceRadius))
      fail("is more than " + textf("%g", kDivergenceRadius) +
               " m from the origin, where a run stops as diverged",
           "x");
    store(state.p(), q, n, {value[2], value[3], value[4]});
    store(state.v(), q, n, {value[5], value[6], value[7]});
  }
  // Empty lines may end the file (an editor's, a spreadsheet's); anything else is a point too many.
  while (at < text.size())
    if (!nextLine().empty())
      fail("more points than the scene's body has (" + std::to_string(n) + ")", "body");
  return state;
}

State readStateFile(const std::string& path, const Body& body) {
  std::string text, why;
  if (!readRegularFile(path, kMostStateBytes, "a state file",
                       std::to_string(kMostStateBytes) + " bytes", &text, &why))
    throw InputError(why);
  return parseState(text, path, body);
}

}  // namespace jello
