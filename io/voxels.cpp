// io/voxels.cpp: OBJ meshes read with tinyobjloader, and meshes and balls made into voxels.
//
// Inside or outside: a voxel is filled when a ray from its centre crosses the mesh an odd number
// of times. The rays go up (+z), one vertical line through each column of voxel centres, so that
// each triangle is tested only against the columns under it and each column's crossings, sorted
// once, fill the whole column. A ray through an edge or a vertex would be counted by two
// triangles or none, so the test is exact and symbolically perturbed:
//  - the mesh's x and y are rounded to integers, 2^20 to a voxel's edge, measured from the grid's
//    corner (a vertex moves by at most 2^-21 voxel; shared vertices stay shared), and a voxel
//    centre is an integer point too, so the orientation of a point against an edge is computed
//    exactly in 64-bit integers: two triangles sharing an edge see the ray on opposite sides;
//  - a ray exactly on an edge's line is taken as moved by (e, e^2) for an infinitesimal e > 0,
//    which leaves it off every edge's line, on one side of each (the "simulation of simplicity"
//    rule). The count is then exactly the crossings of a real
//    line next to the centre, which for a closed mesh is even in total and odd above any point
//    inside. A ray in a slightly skewed floating-point direction only makes the bad cases rare;
//    the generalized winding number is robust too but costs every triangle at every voxel.

#include "io/voxels.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <istream>
#include <streambuf>
#include <string_view>
#include <utility>

#include "core/readfile.h"

namespace jello {

int VoxelGrid::count() const {
  return static_cast<int>(filled.size() - std::count(filled.begin(), filled.end(), 0));
}

Vec3 VoxelGrid::centre(int i, int j, int k) const {
  return origin + size * Vec3{i + 0.5, j + 0.5, k + 0.5};
}

namespace {

// Every message is one line of printable text: a file's name or the library's words may hold
// anything.
bool fail(std::string* why, const std::string& text) {
  if (why) {
    *why = text;
    for (char& c : *why)
      if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
  }
  return false;
}

std::string number(const char* format, double value) {
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

std::string lineOf(const std::string& path, std::size_t line) {
  return path + ":" + std::to_string(line) + ": ";
}

// ---- Reading an OBJ file ----------------------------------------------------------------------

// The whitespace-separated words of an OBJ line, as tinyobjloader splits them.
std::vector<std::string_view> wordsOf(std::string_view line) {
  std::vector<std::string_view> words;
  std::size_t at = 0;
  while (true) {
    at = line.find_first_not_of(" \t", at);
    if (at == std::string_view::npos) return words;
    const std::size_t end = std::min(line.find_first_of(" \t", at), line.size());
    words.push_back(line.substr(at, end - at));
    at = end;
  }
}

// A plain decimal number: [+-] digits [. digits] [e [+-] digits], a digit before or after the
// point. tinyobjloader reads anything else ("nan", "inf", "0x1p3", "x") as 0 without a word.
bool isDecimal(std::string_view word) {
  std::size_t at = 0, digits = 0;
  auto skipDigits = [&] {
    const std::size_t from = at;
    while (at < word.size() && word[at] >= '0' && word[at] <= '9') ++at;
    return at - from;
  };
  if (at < word.size() && (word[at] == '+' || word[at] == '-')) ++at;
  digits += skipDigits();
  if (at < word.size() && word[at] == '.') {
    ++at;
    digits += skipDigits();
  }
  if (digits == 0) return false;
  if (at < word.size() && (word[at] == 'e' || word[at] == 'E')) {
    ++at;
    if (at < word.size() && (word[at] == '+' || word[at] == '-')) ++at;
    if (skipDigits() == 0) return false;
  }
  return at == word.size();
}

// A `v` line's words after the "v": three coordinates that are plain numbers of at most
// kLargestMeshCoordinate in magnitude (a fourth, the weight, and colours are ignored).
bool checkVertexLine(const std::vector<std::string_view>& words, const std::string& where,
                     std::string* why) {
  if (words.size() < 4) return fail(why, where + "a vertex (v) needs three coordinates");
  for (std::size_t n = 1; n <= 3; ++n) {
    const std::string word(words[n].substr(0, 40));  // enough to recognise in a message
    if (!isDecimal(words[n]))
      return fail(why, where + "vertex coordinate '" + word + "' is not a number");
    const double value = std::strtod(std::string(words[n]).c_str(), nullptr);
    if (!(std::fabs(value) <= kLargestMeshCoordinate))
      return fail(why, where + "vertex coordinate " + word + " is beyond " +
                           number("%.0f", kLargestMeshCoordinate) + " m: not a model in metres");
  }
  return true;
}

// What an OBJ text holds, counted before tinyobjloader reads it: its `v`, `vn` and `vt` lines
// and the triangles its `f` lines make.
struct ObjCounts {
  std::size_t vertices = 0, normals = 0, textureCoordinates = 0;
  std::size_t triangles = 0;
};

// Counts one line's words into `counts`, checking a vertex's coordinates. tinyobjloader keeps
// every vertex, normal and texture coordinate: they too are counted and capped.
bool countLine(const std::vector<std::string_view>& words, const std::string& where,
               ObjCounts* counts, std::string* why) {
  constexpr std::size_t kMostPoints = 3 * kMostMeshTriangles;
  std::size_t* count = nullptr;
  if (words[0] == "v") {
    if (!checkVertexLine(words, where, why)) return false;
    count = &counts->vertices;
  } else if (words[0] == "vn") {
    count = &counts->normals;
  } else if (words[0] == "vt") {
    count = &counts->textureCoordinates;
  } else if (words[0] == "f" && words.size() >= 4) {
    // tinyobjloader reads each index as an int, without a word when it overflows: 4294967304
    // would wrap round to 8. Every index (vertex/texture/normal) is a whole number no larger
    // than the most points a model may have.
    for (std::size_t w = 1; w < words.size(); ++w) {
      std::string_view corner = words[w];
      for (std::size_t start = 0; start <= corner.size();) {
        std::size_t slash = std::min(corner.find('/', start), corner.size());
        std::string_view index = corner.substr(start, slash - start);
        std::size_t digits = index.size() - (!index.empty() && index[0] == '-');
        if (!index.empty() &&
            (digits == 0 || digits > 9 ||
             index.find_first_not_of("0123456789", index.size() - digits) !=
                 std::string_view::npos ||
             std::stoull(std::string(index.substr(index.size() - digits))) > kMostPoints))
          return fail(why, where + "face index " + std::string(index) +
                               " is not a whole number of at most " + std::to_string(kMostPoints));
        start = slash + 1;
      }
    }
    counts->triangles += words.size() - 3;  // a polygon of n corners is n - 2 triangles
    if (counts->triangles > kMostMeshTriangles)
      return fail(why, where + "more than " + std::to_string(kMostMeshTriangles) + " triangles");
  }
  if (count && ++*count > kMostPoints)
    return fail(why, where + "more than " + std::to_string(kMostPoints) + " " +
                         std::string(words[0]) + " lines");
  return true;
}

// Checks an OBJ text line by line (split as tinyobjloader splits it: at "\n", "\r\n" or "\r")
// before tinyobjloader reads it: the coordinates that it would read as 0 or as infinity without
// a word, and the counts that would make it take too much memory.
bool scanObjText(const std::string& text, const std::string& path, ObjCounts* counts,
                 std::string* why) {
  if (text.find('\0') != std::string::npos)
    return fail(why, path + ": holds a NUL byte: not a text OBJ file");
  std::size_t at = 0, line = 0;
  while (at < text.size()) {
    const std::size_t end = std::min(text.find_first_of("\r\n", at), text.size());
    ++line;
    const std::vector<std::string_view> words =
        wordsOf(std::string_view(text).substr(at, end - at));
    at = end + (text.compare(end, 2, "\r\n") == 0 ? 2 : 1);
    if (!words.empty() && !countLine(words, lineOf(path, line), counts, why)) return false;
  }
  return true;
}

// The faces of tinyobjloader's shapes as triangles, each polygon a fan from its first corner (a
// fan covers a flat polygon, convex or not, an odd number of times exactly where the polygon
// does, so the inside test's parity is unchanged).
bool collectTriangles(const std::vector<tinyobj::shape_t>& shapes, const std::string& path,
                      TriangleMesh* mesh, std::string* why) {
  const long long vertices = static_cast<long long>(mesh->vertices.size());
  for (const tinyobj::shape_t& shape : shapes) {
    std::size_t first = 0;
    std::vector<int> face;
    for (const unsigned int corners : shape.mesh.num_face_vertices) {
      face.clear();
      for (std::size_t c = 0; c < corners; ++c) {
        const int index = shape.mesh.indices.at(first + c).vertex_index;
        if (index < 0 || index >= vertices)
          return fail(why, path + ": a face (f) refers to a vertex that is not there (" +
                               std::to_string(vertices) + " vertices)");
        face.push_back(index);
      }
      first += corners;
      for (std::size_t c = 1; c + 1 < face.size(); ++c)
        mesh->triangles.push_back({face[0], face[c], face[c + 1]});
    }
  }
  return true;
}

// The vertices tinyobjloader read (double precision: the _double library), checked once more.
bool collectVertices(const std::vector<tinyobj::real_t>& v, const std::string& path,
                     std::size_t expected, TriangleMesh* mesh, std::string* why) {
  if (v.size() != 3 * expected)
    return fail(why, path + ": tinyobjloader read " + std::to_string(v.size() / 3) +
                         " vertices where the file has " + std::to_string(expected));
  for (std::size_t n = 0; n < expected; ++n) {
    const Vec3 p{v[3 * n], v[3 * n + 1], v[3 * n + 2]};
    if (!(std::fabs(p.x) <= kLargestMeshCoordinate && std::fabs(p.y) <= kLargestMeshCoordinate &&
          std::fabs(p.z) <= kLargestMeshCoordinate))
      return fail(why, path + ": vertex " + std::to_string(n + 1) + " is not finite or beyond " +
                           number("%.0f", kLargestMeshCoordinate) + " m");
    mesh->vertices.push_back(p);
  }
  return true;
}

// tinyobjloader reads from a stream: this one reads the text where it is, not from a copy.
struct TextStreamBuffer : std::streambuf {
  explicit TextStreamBuffer(std::string* text) {
    setg(text->data(), text->data(), text->data() + text->size());
  }
};

}  // namespace

bool readObjMesh(const std::string& path, TriangleMesh* mesh, std::string* why) {
  *mesh = TriangleMesh{};
  std::string text;
  std::string unread;
  if (!readRegularFile(path, kMostObjBytes, "an OBJ model",
                       std::to_string(kMostObjBytes >> 20) + " MB", &text, &unread))
    return fail(why, unread);
  return parseObjText(std::move(text), path, mesh, why);
}

bool parseObjText(std::string text, const std::string& name, TriangleMesh* mesh, std::string* why) {
  *mesh = TriangleMesh{};
  mesh->name = name;
  ObjCounts counts;
  if (text.size() > kMostObjBytes)
    return fail(why, name + ": longer than " + std::to_string(kMostObjBytes >> 20) + " MB");
  if (!scanObjText(text, name, &counts, why)) return false;
  tinyobj::attrib_t attributes;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  std::string warnings, error;
  TextStreamBuffer buffer(&text);
  std::istream stream(&buffer);
  // No material reader: no .mtl file named by the model is opened. No triangulation: the
  // polygons are cut here, for tinyobjloader's cutting skips a quad with an index out of range
  // with only a warning, and reads a larger polygon's vertices before any index is checked.
  if (!tinyobj::LoadObj(&attributes, &shapes, &materials, &warnings, &error, &stream, nullptr,
                        false, false)) {
    // The line it stopped at, in this program's words (the reader's own text is not shown).
    const std::size_t mark = error.find("line ");
    const std::string line =
        mark == std::string::npos ? "" : ":" + std::to_string(std::atol(error.c_str() + mark + 5));
    return fail(why, name + (line == ":0" ? "" : line) +
                         ": not an OBJ model this program reads (v lines of three numbers, f "
                         "lines of vertex numbers from 1, or from -1 backwards)");
  }
  text = std::string();  // its memory back before the mesh is built
  mesh->vertices.reserve(counts.vertices);
  mesh->triangles.reserve(counts.triangles);
  if (!collectVertices(attributes.vertices, name, counts.vertices, mesh, why) ||
      !collectTriangles(shapes, name, mesh, why))
    return false;
  if (mesh->triangles.empty())
    return fail(why, name + ": no faces of three or more corners (f lines): not a solid model");
  return true;
}

namespace {

// ---- Voxelising -------------------------------------------------------------------------------

// Integer coordinates per voxel edge (see the top of the file): with at most 47 voxels an axis
// every coordinate is below 2^26 in magnitude, so an orientation (a difference of two products
// of differences) is below 2^55: exact in 64 bits.
constexpr double kUnitsPerVoxel = 1 << 20;
constexpr std::int64_t kHalfVoxel = 1 << 19;

// The fewest voxels of edge `size` along an axis covering `extent` (m), as a double: it may be
// huge. A hair (1e-9 voxel) is forgiven, so that 1.05 m in voxels of 0.15 m (7.0000000000000009)
// is 7 voxels.
double voxelsAcross(double extent, double size) {
  return std::max(1.0, std::ceil(extent / size - 1e-9));
}

// The smallest voxel, rounded up to two significant digits, that fits `extent` in
// kMostBodyPoints - 1 voxels.
double smallestVoxel(double extent) {
  const double least = extent / (kMostBodyPoints - 1);
  const double step = std::pow(10.0, std::floor(std::log10(least)) - 1);
  return std::ceil(least / step) * step;
}

// Lays out the grid covering the box [lo, hi] (m), centred on it, all voxels empty. `what` names
// the shape in messages.
bool layOutGrid(Vec3 lo, Vec3 hi, double size, const std::string& what, VoxelGrid* grid,
                std::string* why) {
  const double extents[3] = {hi.x - lo.x, hi.y - lo.y, hi.z - lo.z};
  const int widest = static_cast<int>(std::max_element(extents, extents + 3) - extents);
  const double cells = voxelsAcross(extents[widest], size);
  if (cells > kMostBodyPoints - 1)
    return fail(why, what + " is " + number("%.3g", extents[widest]) + " m across (along " +
                         "xyz"[widest] + "): at voxel size " + number("%g", size) + " m that is " +
                         number(cells < 1e9 ? "%.0f" : "%.3g", cells) + " voxels, at most " +
                         std::to_string(kMostBodyPoints - 1) + "; use a voxel of at least " +
                         number("%.2g", smallestVoxel(extents[widest])) + " m");
  *grid = VoxelGrid{};
  grid->size = size;
  grid->nx = static_cast<int>(voxelsAcross(extents[0], size));
  grid->ny = static_cast<int>(voxelsAcross(extents[1], size));
  grid->nz = static_cast<int>(voxelsAcross(extents[2], size));
  const Vec3 middle = 0.5 * (lo + hi);
  grid->origin = middle - 0.5 * size * Vec3{double(grid->nx), double(grid->ny), double(grid->nz)};
  grid->filled.assign(static_cast<std::size_t>(grid->nx) * grid->ny * grid->nz, 0);
  return true;
}

bool checkSize(double size, std::string* why) {
  if (size > 0 && size <= kLargestMeshCoordinate) return true;
  return fail(why, "the voxel size " + number("%g", size) + " m is not a number > 0 and at most " +
                       number("%.0f", kLargestMeshCoordinate) + " m");
}

// A vertex in the grid's integer coordinates (x, y exact; z only compared).
struct GridPoint {
  std::int64_t x, y, z;
};

GridPoint toGrid(Vec3 p, const VoxelGrid& grid) {
  const Vec3 d = (kUnitsPerVoxel / grid.size) * (p - grid.origin);
  // Every vertex is within the grid, give or take a rounding; the clamp only keeps llround
  // defined whatever happens.
  constexpr double kFar = 1 << 30;
  return {std::llround(std::clamp(d.x, -kFar, kFar)), std::llround(std::clamp(d.y, -kFar, kFar)),
          std::llround(std::clamp(d.z, -kFar, kFar))};
}

// Twice the signed area of (a, b, q) projected on xy: > 0 when q is left of a->b. Exact.
std::int64_t orient(const GridPoint& a, const GridPoint& b, std::int64_t qx, std::int64_t qy) {
  return (b.x - a.x) * (qy - a.y) - (b.y - a.y) * (qx - a.x);
}

// The side of a->b the point (qx + e, qy + e^2) is on for an infinitesimal e > 0: +1 left,
// -1 right, 0 only when a and b coincide on xy. On the line itself, the e term decides, -(b.y -
// a.y) e, and when the edge runs along x, the e^2 term, (b.x - a.x) e^2. b->a gets the opposite.
int side(const GridPoint& a, const GridPoint& b, std::int64_t qx, std::int64_t qy) {
  const std::int64_t d = orient(a, b, qx, qy);
  if (d != 0) return d > 0 ? 1 : -1;
  if (b.y != a.y) return b.y < a.y ? 1 : -1;
  return (b.x > a.x) - (b.x < a.x);
}

// Where the vertical line through (qx, qy), moved as side() says, crosses triangle abc: writes
// the height (grid units) and returns true, or returns false when it misses.
bool crossing(const GridPoint& a, const GridPoint& b, const GridPoint& c, std::int64_t qx,
              std::int64_t qy, double* z) {
  const int s = side(a, b, qx, qy);
  if (s == 0 || side(b, c, qx, qy) != s || side(c, a, qx, qy) != s) return false;
  // Barycentric weights at the line itself (exact; the infinitesimal move changes no height).
  const double wa = static_cast<double>(orient(b, c, qx, qy));
  const double wb = static_cast<double>(orient(c, a, qx, qy));
  const double wc = static_cast<double>(orient(a, b, qx, qy));
  *z = (wa * a.z + wb * b.z + wc * c.z) / (wa + wb + wc);
  return true;
}

// The first and last column index in [0, n) whose centre (2i+1)*kHalfVoxel lies in [lo, hi].
void columnsUnder(std::int64_t lo, std::int64_t hi, int n, int* first, int* last) {
  *first = std::max(0, static_cast<int>(std::ceil((lo - kHalfVoxel) / (2.0 * kHalfVoxel))));
  *last = std::min(n - 1, static_cast<int>(std::floor((hi - kHalfVoxel) / (2.0 * kHalfVoxel))));
}

// The heights (grid units) at which each column's line crosses the mesh, column (i, j) at
// i*ny + j, unsorted.
std::vector<std::vector<double>> columnCrossings(const TriangleMesh& mesh, const VoxelGrid& grid) {
  std::vector<GridPoint> points;
  points.reserve(mesh.vertices.size());
  for (const Vec3& p : mesh.vertices) points.push_back(toGrid(p, grid));
  std::vector<std::vector<double>> columns(static_cast<std::size_t>(grid.nx) * grid.ny);
  for (const std::array<int, 3>& t : mesh.triangles) {
    const GridPoint& a = points[t[0]];
    const GridPoint& b = points[t[1]];
    const GridPoint& c = points[t[2]];
    int i0, i1, j0, j1;
    columnsUnder(std::min({a.x, b.x, c.x}), std::max({a.x, b.x, c.x}), grid.nx, &i0, &i1);
    columnsUnder(std::min({a.y, b.y, c.y}), std::max({a.y, b.y, c.y}), grid.ny, &j0, &j1);
    for (int i = i0; i <= i1; ++i)
      for (int j = j0; j <= j1; ++j) {
        double z;
        if (crossing(a, b, c, (2 * i + 1) * kHalfVoxel, (2 * j + 1) * kHalfVoxel, &z))
          columns[static_cast<std::size_t>(i) * grid.ny + j].push_back(z);
      }
  }
  return columns;
}

// Fills column (i, j) from its crossings: a centre with an odd number of crossings below it is
// inside. Returns false when the column has an odd number of crossings (the mesh has a hole).
bool fillColumn(std::vector<double>* heights, int i, int j, VoxelGrid* grid) {
  if (heights->size() % 2 != 0) return false;
  std::sort(heights->begin(), heights->end());
  std::size_t below = 0;
  for (int k = 0; k < grid->nz; ++k) {
    const double centre = static_cast<double>((2 * k + 1) * kHalfVoxel);
    while (below < heights->size() && (*heights)[below] < centre) ++below;
    grid->filled[grid->cell(i, j, k)] = below % 2;
  }
  return true;
}

// The mesh's triangles' bounding box, after checking their indices and corners.
bool triangleBounds(const TriangleMesh& mesh, const std::string& what, Vec3* lo, Vec3* hi,
                    std::string* why) {
  if (mesh.triangles.empty()) return fail(why, what + " has no triangles");
  const double big = kLargestMeshCoordinate;
  *lo = {big, big, big};
  *hi = {-big, -big, -big};
  const long long vertices = static_cast<long long>(mesh.vertices.size());
  for (const std::array<int, 3>& t : mesh.triangles)
    for (const int index : t) {
      if (index < 0 || index >= vertices)
        return fail(why, what + ": a triangle refers to vertex " + std::to_string(index) + " of " +
                             std::to_string(vertices));
      const Vec3 p = mesh.vertices[index];
      if (!(std::fabs(p.x) <= big && std::fabs(p.y) <= big && std::fabs(p.z) <= big))
        return fail(why, what + ": a vertex is not finite or beyond " + number("%.0f", big) + " m");
      *lo = {std::min(lo->x, p.x), std::min(lo->y, p.y), std::min(lo->z, p.z)};
      *hi = {std::max(hi->x, p.x), std::max(hi->y, p.y), std::max(hi->z, p.z)};
    }
  return true;
}

}  // namespace

bool voxeliseMesh(const TriangleMesh& mesh, double size, VoxelGrid* grid, std::string* why) {
  const std::string what = mesh.name.empty() ? "the mesh" : mesh.name;
  Vec3 lo, hi;
  if (!checkSize(size, why) || !triangleBounds(mesh, what, &lo, &hi, why) ||
      !layOutGrid(lo, hi, size, what, grid, why))
    return false;
  std::vector<std::vector<double>> columns = columnCrossings(mesh, *grid);
  for (int i = 0; i < grid->nx; ++i)
    for (int j = 0; j < grid->ny; ++j) {
      std::vector<double>& heights = columns[static_cast<std::size_t>(i) * grid->ny + j];
      if (!fillColumn(&heights, i, j, grid)) {
        const Vec3 at = grid->centre(i, j, 0);
        return fail(why, what + " is not closed: the vertical line through x = " +
                             number("%g", at.x) + " m, y = " + number("%g", at.y) +
                             " m crosses its surface " + std::to_string(heights.size()) +
                             " times, an odd number (a hole, or faces missing)");
      }
    }
  if (grid->count() == 0)
    return fail(why, what + ": no voxel's centre is inside it at voxel size " + number("%g", size) +
                         " m (too thin, or the voxel too large)");
  return true;
}

bool voxeliseSphere(double radius, double size, VoxelGrid* grid, std::string* why) {
  if (!(radius > 0 && radius <= kLargestMeshCoordinate))
    return fail(why, "the ball's radius " + number("%g", radius) + " m is not a number > 0 and " +
                         "at most " + number("%.0f", kLargestMeshCoordinate) + " m");
  if (!checkSize(size, why)) return false;
  const std::string what = "a ball of radius " + number("%g", radius) + " m";
  if (!layOutGrid({-radius, -radius, -radius}, {radius, radius, radius}, size, what, grid, why))
    return false;
  for (int i = 0; i < grid->nx; ++i)
    for (int j = 0; j < grid->ny; ++j)
      for (int k = 0; k < grid->nz; ++k) {
        // The centre from the middle, not the corner: the ball comes out exactly symmetric.
        const Vec3 c = size * Vec3{i + 0.5 - 0.5 * grid->nx, j + 0.5 - 0.5 * grid->ny,
                                   k + 0.5 - 0.5 * grid->nz};
        grid->filled[grid->cell(i, j, k)] = dot(c, c) <= radius * radius;
      }
  if (grid->count() == 0)
    return fail(why, what + ": no voxel's centre is inside it at voxel size " + number("%g", size) +
                         " m (the voxel is too large)");
  return true;
}

namespace {

// Labels the face-connected group of filled voxels holding `start` with `label`; returns its
// size. An explicit stack: a group may be every voxel of the grid.
int labelPiece(const VoxelGrid& grid, int start, int label, std::vector<int>* labels) {
  static const int kSteps[6][3] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                   {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
  std::vector<int> stack{start};
  (*labels)[start] = label;
  int size = 0;
  while (!stack.empty()) {
    const int at = stack.back();
    stack.pop_back();
    ++size;
    const int i = at / (grid.ny * grid.nz), j = at / grid.nz % grid.ny, k = at % grid.nz;
    for (const auto& step : kSteps) {
      const int ni = i + step[0], nj = j + step[1], nk = k + step[2];
      if (!grid.at(ni, nj, nk)) continue;
      const int next = static_cast<int>(grid.cell(ni, nj, nk));
      if ((*labels)[next] != 0) continue;
      (*labels)[next] = label;
      stack.push_back(next);
    }
  }
  return size;
}

}  // namespace

int keepLargestPiece(VoxelGrid* grid) {
  const int cells = static_cast<int>(grid->filled.size());
  std::vector<int> labels(cells, 0);  // 0: empty or not yet reached; pieces count from 1
  int pieces = 0, largest = 0, largestSize = 0, total = 0;
  for (int at = 0; at < cells; ++at) {
    if (!grid->filled[at] || labels[at] != 0) continue;
    const int size = labelPiece(*grid, at, ++pieces, &labels);
    total += size;
    if (size > largestSize) {
      largestSize = size;
      largest = pieces;
    }
  }
  for (int at = 0; at < cells; ++at)
    if (labels[at] != largest) grid->filled[at] = 0;
  return total - largestSize;
}

}  // namespace jello
