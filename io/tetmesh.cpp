// io/tetmesh.cpp: TetGen's .node and .ele files read as a body (tetmesh.h).

#include "io/tetmesh.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string_view>
#include <vector>

#include "core/limits.h"
#include "core/readfile.h"
#include "io/inputerror.h"

namespace jello {

std::string elementFileOf(const std::string& nodePath) {
  return nodePath.substr(0, nodePath.size() - 5) + ".ele";
}

namespace {

// One file's lines of words, comments ('#' to the end of the line) and blank lines skipped.
class Words {
 public:
  Words(const std::string& text, std::string name) : text_(text), name_(std::move(name)) {}
  // The next line that holds words, split; false at the end of the file.
  bool next(std::vector<std::string_view>* words) {
    while (at_ < text_.size()) {
      const std::size_t end = std::min(text_.find('\n', at_), text_.size());
      std::string_view line(text_.data() + at_, end - at_);
      at_ = end + 1;
      ++line_;
      if (const std::size_t hash = line.find('#'); hash != std::string_view::npos)
        line = line.substr(0, hash);
      words->clear();
      std::size_t i = 0;
      while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
        const std::size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
        if (i > start) words->push_back(line.substr(start, i - start));
      }
      if (!words->empty()) return true;
    }
    return false;
  }
  [[noreturn]] void fail(const std::string& what, const std::string& field) const {
    failAt(line_, what, field);
  }
  [[noreturn]] void failAt(int line, const std::string& what, const std::string& field) const {
    throw InputError(name_ + ":" + std::to_string(line) + ": " + what + " (" + field + ")");
  }
  int line() const { return line_; }
  // Word w of the line as a whole number from lowest to highest.
  long long whole(const std::vector<std::string_view>& words, std::size_t w, long long lowest,
                  long long highest, const std::string& field) const {
    if (w >= words.size()) fail("the line ends before its " + field, field);
    const std::string word(words[w]);
    char* end = nullptr;
    errno = 0;
    const long long value = std::strtoll(word.c_str(), &end, 10);
    if (word.empty() || *end != '\0' || errno != 0 || value < lowest || value > highest)
      fail("expected a whole number from " + std::to_string(lowest) + " to " +
               std::to_string(highest) + ", got '" + printable(word) + "'",
           field);
    return value;
  }
  double coordinate(const std::vector<std::string_view>& words, std::size_t w,
                    const std::string& field) const {
    if (w >= words.size()) fail("the line ends before its " + field, field);
    const std::string word(words[w]);
    char* end = nullptr;
    const double value = std::strtod(word.c_str(), &end);
    const bool plain = word.find_first_not_of("0123456789+-.eE") == std::string::npos;
    if (word.empty() || *end != '\0' || !plain || !std::isfinite(value) ||
        std::fabs(value) > kLargestMeshCoordinate)
      fail("expected a coordinate (m) of at most " + std::to_string(int(kLargestMeshCoordinate)) +
               " in magnitude, got '" + printable(word) + "'",
           field);
    return value;
  }
  void noMore(const std::vector<std::string_view>& words, std::size_t count,
              const std::string& what) const {
    if (words.size() > count)
      fail("more numbers than " + what + " (" + std::to_string(count) + ")",
           "word " + std::to_string(count + 1));
  }

 private:
  // The word shown in a message: at most 40 characters, control characters as '?'.
  static std::string printable(const std::string& word) {
    std::string out = word.substr(0, 40);
    for (char& c : out)
      if (static_cast<unsigned char>(c) < 32 || c == 127) c = '?';
    return word.size() > 40 ? out + "..." : out;
  }

  const std::string& text_;
  std::string name_;
  std::size_t at_ = 0;
  int line_ = 0;
};

struct NodeFile {
  std::vector<Vec3> points;
  long long firstNumber = 0;
};

NodeFile readNodes(const std::string& text, const std::string& name) {
  Words in(text, name);
  std::vector<std::string_view> words;
  if (!in.next(&words)) in.fail("no header: expected <points> 3 <attributes> <markers>", "header");
  const long long count = in.whole(words, 0, 4, kMostScenePoints, "number of points");
  in.whole(words, 1, 3, 3, "dimension");
  const long long attributes = words.size() > 2 ? in.whole(words, 2, 0, 64, "attributes") : 0;
  const long long markers = words.size() > 3 ? in.whole(words, 3, 0, 1, "boundary markers") : 0;
  in.noMore(words, 4, "a .node header holds");
  NodeFile out;
  std::map<std::array<double, 3>, long long> placed;  // where each point is: its number
  // Room for what the text can hold (a line is at least 8 bytes), not what the header claims.
  out.points.reserve(std::min<std::size_t>(count, text.size() / 8));
  for (long long i = 0; i < count; ++i) {
    if (!in.next(&words))
      in.fail("the file ends after " + std::to_string(i) + " of its " + std::to_string(count) +
                  " points",
              "point " + std::to_string(i + out.firstNumber));
    if (i == 0) out.firstNumber = in.whole(words, 0, 0, 1, "point number");
    const std::string field = "point " + std::to_string(i + out.firstNumber);
    in.whole(words, 0, i + out.firstNumber, i + out.firstNumber, field + " number");
    const Vec3 x{in.coordinate(words, 1, field + " x"), in.coordinate(words, 2, field + " y"),
                 in.coordinate(words, 3, field + " z")};
    in.noMore(words, 4 + attributes + markers, "the header gives a point");
    auto [at, fresh] = placed.try_emplace({x.x, x.y, x.z}, i + out.firstNumber);
    if (!fresh)
      in.fail("at the same place as point " + std::to_string(at->second) +
                  " (two points at one place: their tetrahedra would not be joined)",
              field);
    out.points.push_back(x);
  }
  if (in.next(&words)) in.fail("more points than the header's " + std::to_string(count), "header");
  return out;
}

// A tetrahedron's nodes in positive order (its third and fourth swapped where its volume is
// negative); refused when it is under kSmallestTetrahedron across or of no volume.
void orient(const Words& in, const NodeFile& nodes, const std::string& field, Tet* t) {
  const Vec3 x0 = nodes.points[(*t)[0]];
  const Vec3 e1 = nodes.points[(*t)[1]] - x0, e2 = nodes.points[(*t)[2]] - x0,
             e3 = nodes.points[(*t)[3]] - x0;
  const double volume = dot(e1, cross(e2, e3)) / 6;
  const double edge = std::max({length(e1), length(e2), length(e3)});
  if (!(edge >= kSmallestTetrahedron)) {
    char what[64];
    std::snprintf(what, sizeof what, "a tetrahedron under %g m across", kSmallestTetrahedron);
    in.fail(what, field);
  }
  if (!(std::fabs(volume) > 1e-12 * edge * edge * edge))
    in.fail("a tetrahedron of no volume (its four points lie in a plane)", field);
  if (volume < 0) std::swap((*t)[2], (*t)[3]);
}

// Two tetrahedra on one face overlap unless they lie on its two sides; a face of three or more
// overlaps too. Refused at the later tetrahedron's line.
void refuseOverlaps(const Words& in, const NodeFile& nodes, const std::vector<Tet>& tets,
                    const std::vector<int>& lines, long long firstNumber) {
  std::map<std::array<int, 3>, std::pair<int, int>> faceOf;  // a face, sorted: a tetrahedron, its
                                                             // fourth node
  for (int e = 0; e < static_cast<int>(tets.size()); ++e) {
    const Tet& t = tets[e];
    for (int opposite = 0; opposite < 4; ++opposite) {
      std::array<int, 3> face;
      for (int c = 0, f = 0; c < 4; ++c)
        if (c != opposite) face[f++] = t[c];
      std::sort(face.begin(), face.end());
      auto [at, fresh] = faceOf.try_emplace(face, e, t[opposite]);
      if (fresh) continue;
      const Vec3 a = nodes.points[face[0]],
                 normal = cross(nodes.points[face[1]] - a, nodes.points[face[2]] - a);
      const double mine = dot(normal, nodes.points[t[opposite]] - a),
                   theirs = dot(normal, nodes.points[at->second.second] - a);
      const std::string other = std::to_string(at->second.first + firstNumber);
      if (at->second.first < 0)
        in.failAt(lines[e], "a face that two other tetrahedra share already",
                  "tetrahedron " + std::to_string(e + firstNumber));
      if ((mine > 0) == (theirs > 0))
        in.failAt(lines[e],
                  "overlaps tetrahedron " + other +
                      " (both on the same side of the "
                      "face they share)",
                  "tetrahedron " + std::to_string(e + firstNumber));
      at->second.first = -1;  // taken by two: a third is refused
    }
  }
}

std::vector<Tet> readElements(const std::string& text, const std::string& name,
                              const NodeFile& nodes) {
  Words in(text, name);
  std::vector<std::string_view> words;
  if (!in.next(&words)) in.fail("no header: expected <tetrahedra> 4 <attributes>", "header");
  const long long count =
      in.whole(words, 0, 1, static_cast<long long>(kMostMeshTetrahedra), "number of tetrahedra");
  const long long corners = in.whole(words, 1, 4, 10, "nodes per tetrahedron");
  if (corners != 4)
    in.fail("only linear tetrahedra (4 nodes) are read, not " + std::to_string(corners),
            "nodes per tetrahedron");
  const long long attributes = words.size() > 2 ? in.whole(words, 2, 0, 1, "region attribute") : 0;
  in.noMore(words, 3, "an .ele header holds");
  const long long first = nodes.firstNumber;
  const long long last = first + static_cast<long long>(nodes.points.size()) - 1;
  std::vector<Tet> tets;
  std::vector<int> lines;                         // each tetrahedron's line
  std::map<std::array<int, 4>, long long> given;  // each tetrahedron's nodes, sorted: its number
  tets.reserve(std::min<std::size_t>(count, text.size() / 8));
  long long firstNumber = 0;
  for (long long i = 0; i < count; ++i) {
    if (!in.next(&words))
      in.fail("the file ends after " + std::to_string(i) + " of its " + std::to_string(count) +
                  " tetrahedra",
              "tetrahedron " + std::to_string(i + firstNumber));
    if (i == 0) firstNumber = in.whole(words, 0, 0, 1, "tetrahedron number");
    const std::string field = "tetrahedron " + std::to_string(i + firstNumber);
    in.whole(words, 0, i + firstNumber, i + firstNumber, field + " number");
    Tet t;
    for (int c = 0; c < 4; ++c)
      t[c] = static_cast<int>(
                 in.whole(words, 1 + c, first, last, field + " node " + std::to_string(c + 1))) -
             static_cast<int>(first);
    in.noMore(words, 5 + attributes, "the header gives a tetrahedron");
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
        if (t[a] == t[b]) in.fail("node " + std::to_string(t[a] + first) + " twice", field);
    orient(in, nodes, field, &t);
    std::array<int, 4> key = t;
    std::sort(key.begin(), key.end());
    if (auto [at, fresh] = given.try_emplace(key, i + firstNumber); !fresh)
      in.fail("the same four nodes as tetrahedron " + std::to_string(at->second) +
                  " (a tetrahedron given twice)",
              field);
    tets.push_back(t);
    lines.push_back(in.line());
  }
  if (in.next(&words))
    in.fail("more tetrahedra than the header's " + std::to_string(count), "header");
  refuseOverlaps(in, nodes, tets, lines, firstNumber);
  return tets;
}

// The faces that belong to one tetrahedron alone, counter-clockwise seen from outside.
std::vector<Triangle> boundaryOf(const std::vector<Tet>& tets) {
  // A positively oriented tetrahedron's faces, wound outward.
  static const int kFaces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  std::map<std::array<int, 3>, std::pair<int, Triangle>> faces;
  for (const Tet& t : tets)
    for (const auto& f : kFaces) {
      Triangle tri{t[f[0]], t[f[1]], t[f[2]]};
      std::array<int, 3> key = tri;
      std::sort(key.begin(), key.end());
      auto [it, fresh] = faces.try_emplace(key, 0, tri);
      ++it->second.first;
      (void)fresh;
    }
  std::vector<Triangle> out;
  for (const auto& [key, face] : faces)
    if (face.first == 1) out.push_back(face.second);
  return out;
}

}  // namespace

Body parseTetMesh(const std::string& nodeText, const std::string& nodeName,
                  const std::string& eleText, const std::string& eleName) {
  const NodeFile nodes = readNodes(nodeText, nodeName);
  const std::vector<Tet> tets = readElements(eleText, eleName, nodes);
  const int n = static_cast<int>(nodes.points.size());
  std::vector<char> used(n, 0);
  for (const Tet& t : tets)
    for (int q : t) used[q] = 1;
  for (int q = 0; q < n; ++q)
    if (!used[q])
      throw InputError(nodeName + ": point " + std::to_string(q + nodes.firstNumber) +
                       " belongs to no tetrahedron of " + eleName + " (point " +
                       std::to_string(q + nodes.firstNumber) + ")");
  Body body;
  body.what = "the tetrahedra of " + nodeName;
  body.rest = nodes.points;
  body.meshTets = tets;
  for (int q = 0; q < n; ++q) body.nodeOf.push_back(q);
  // Every edge once, as a spring.
  std::vector<std::pair<int, int>> edges;
  for (const Tet& t : tets)
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) edges.push_back({std::min(t[a], t[b]), std::max(t[a], t[b])});
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  double total = 0;
  for (auto [a, b] : edges) {
    const double rest = length(body.rest[a] - body.rest[b]);
    body.springs.push_back({a, b, rest, SpringKind::Structural});
    total += rest;
  }
  body.spacing = total / edges.size();
  body.surface = boundaryOf(tets);
  body.surfaceVertexOf.assign(n, -1);
  std::vector<char> onSurface(n, 0);
  for (const Triangle& t : body.surface)
    for (int q : t) onSurface[q] = 1;
  for (int q = 0; q < n; ++q)
    if (onSurface[q]) {
      body.surfaceVertexOf[q] = static_cast<int>(body.surfacePoints.size());
      body.surfacePoints.push_back(q);
    }
  return body;
}

bool readTetMeshFiles(const std::string& nodePath, std::string* nodeText, std::string* eleText,
                      std::string* why) {
  const std::string limit = std::to_string(kMostTetMeshBytes >> 20) + " MB";
  return readRegularFile(nodePath, kMostTetMeshBytes, "a TetGen .node file", limit, nodeText,
                         why) &&
         readRegularFile(elementFileOf(nodePath), kMostTetMeshBytes, "a TetGen .ele file", limit,
                         eleText, why);
}

Body readTetMesh(const std::string& nodePath) {
  std::string nodeText, eleText, why;
  if (!readTetMeshFiles(nodePath, &nodeText, &eleText, &why)) throw InputError(why);
  return parseTetMesh(nodeText, nodePath, eleText, elementFileOf(nodePath));
}

}  // namespace jello
