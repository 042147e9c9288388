// surface.cpp: the surface mesh's fixed topology and its normals.

#include "app/surface.h"

namespace jello {

namespace {

constexpr int kLast = kLatticeSize - 1;

// Lattice point on face (axis, side) at face coordinates (u, v): index[axis] = side,
// index[axis+1] = u, index[axis+2] = v (cyclically), so that d/du x d/dv points along +axis.
int facePoint(int axis, int side, int u, int v) {
  int index[3];
  index[axis] = side;
  index[(axis + 1) % 3] = u;
  index[(axis + 2) % 3] = v;
  return pointIndex(index[0], index[1], index[2]);
}

// The two triangles of quad (u, v) of face (axis, side), appended to `out`. The quad's corners
// a, b, c, d run counter-clockwise seen from +axis; on the side facing -axis they are taken in
// the opposite order so that every triangle winds counter-clockwise seen from outside.
void addQuad(int axis, int side, int u, int v, std::vector<Triangle>* out) {
  const int a = facePoint(axis, side, u, v), b = facePoint(axis, side, u + 1, v);
  const int c = facePoint(axis, side, u + 1, v + 1), d = facePoint(axis, side, u, v + 1);
  // Twice the quad centre's offset from the face centre (3.5, 3.5): whole numbers. Quads whose
  // centre lies on the (1, 1) diagonal's side of the face are split along a-c, the others along
  // b-d, so that the diagonal at each of the face's corners passes through the corner.
  const int du = 2 * u + 1 - kLast, dv = 2 * v + 1 - kLast;
  const bool alongAC = du * dv >= 0;
  const bool outwardIsPlus = side == kLast;
  Triangle first = alongAC ? Triangle{a, b, c} : Triangle{a, b, d};
  Triangle second = alongAC ? Triangle{a, c, d} : Triangle{b, c, d};
  if (!outwardIsPlus) {
    std::swap(first[1], first[2]);
    std::swap(second[1], second[2]);
  }
  out->push_back(first);
  out->push_back(second);
}

}  // namespace

const std::vector<Triangle>& surfaceTriangles() {
  static const std::vector<Triangle> triangles = [] {
    std::vector<Triangle> t;
    t.reserve(kSurfaceTriangles);
    for (int axis = 0; axis < 3; ++axis)
      for (int side : {0, kLast})
        for (int u = 0; u < kLast; ++u)
          for (int v = 0; v < kLast; ++v) addQuad(axis, side, u, v, &t);
    return t;
  }();
  return triangles;
}

const std::vector<int>& surfacePoints() {
  static const std::vector<int> points = [] {
    std::vector<int> p;
    p.reserve(kSurfacePoints);
    for (int i = 0; i < kLatticeSize; ++i)
      for (int j = 0; j < kLatticeSize; ++j)
        for (int k = 0; k < kLatticeSize; ++k) {
          const bool boundary =
              i == 0 || i == kLast || j == 0 || j == kLast || k == 0 || k == kLast;
          if (boundary) p.push_back(pointIndex(i, j, k));  // i, j, k ascending: numbers ascend
        }
    return p;
  }();
  return points;
}

const std::array<int, kNumPoints>& surfaceVertexOfPoint() {
  static const std::array<int, kNumPoints> vertexOf = [] {
    std::array<int, kNumPoints> v;
    v.fill(-1);
    const std::vector<int>& points = surfacePoints();
    for (std::size_t n = 0; n < points.size(); ++n) v[points[n]] = static_cast<int>(n);
    return v;
  }();
  return vertexOf;
}

std::vector<Vec3> surfaceNormals(const double* positions) {
  std::vector<Vec3> normal(kNumPoints);
  for (const Triangle& t : surfaceTriangles()) {
    const Vec3 a = load(positions, t[0]), b = load(positions, t[1]), c = load(positions, t[2]);
    const Vec3 n = cross(b - a, c - a);  // its length is twice the area: area-weighted
    for (int q : t) normal[q] += n;
  }
  for (Vec3& n : normal) {
    double unused;
    n = direction(n, &unused);
  }
  return normal;
}

}  // namespace jello
