// body.cpp: building a body's points, springs and surface from its voxels.

#include "model/body.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/assert.h"

namespace jello {

const char* springKindName(SpringKind kind) {
  switch (kind) {
    case SpringKind::Structural:
      return "structural";
    case SpringKind::Shear:
      return "shear";
    case SpringKind::Bend:
      break;
  }
  return "bend";
}

double restLength(const SpringOffset& o, double spacing) {
  return spacing * std::sqrt(double(o.di * o.di + o.dj * o.dj + o.dk * o.dk));
}

int Body::partOf(int q) const {
  if (!joined()) return 0;
  JELLO_ASSERT(q >= 0 && q < count());
  return static_cast<int>(std::upper_bound(partFirst.begin(), partFirst.end(), q) -
                          partFirst.begin()) -
         1;
}

std::array<int, 3> Body::index(int q) const {
  if (joined()) {
    const int p = partOf(q);
    return parts[p]->index(q - partFirst[p]);
  }
  if (gridless()) return {q, 0, 0};
  const int node = nodeOf[q];
  return {node / (ny * nz), (node / nz) % ny, node % nz};
}

Vec3 Body::restPosition(int q) const {
  if (joined()) {
    const int p = partOf(q);
    return parts[p]->restPosition(q - partFirst[p]);
  }
  if (gridless()) return rest[q];
  const std::array<int, 3> i = index(q);
  return spacing * Vec3{double(i[0]), double(i[1]), double(i[2])};
}

std::string Body::label(int q) const {
  const std::array<int, 3> i = index(q);
  const Body& own = joined() ? *parts[partOf(q)] : *this;
  if (own.gridless())
    return "#" + std::to_string(i[0]) +
           (joined() ? " of jelly " + std::to_string(partOf(q) + 1) : std::string());
  return "[" + std::to_string(i[0]) + "][" + std::to_string(i[1]) + "][" + std::to_string(i[2]) +
         "]" + (joined() ? " of jelly " + std::to_string(partOf(q) + 1) : std::string());
}

int Body::pointAtIndex(int i, int j, int k) const {
  if (joined() || gridless() || i < 0 || j < 0 || k < 0 || i >= nx || j >= ny || k >= nz) return -1;
  return pointAt[node(i, j, k)];
}

namespace {

// Whether grid node (i, j, k) is a corner of a filled voxel.
bool isCorner(const VoxelMask& mask, int i, int j, int k) {
  for (int c = 0; c < 8; ++c)
    if (mask.at(i - (c >> 2 & 1), j - (c >> 1 & 1), k - (c & 1))) return true;
  return false;
}

void numberPoints(const VoxelMask& mask, Body* body) {
  body->pointAt.assign(std::size_t(body->nx) * body->ny * body->nz, -1);
  for (int i = 0; i < body->nx; ++i)
    for (int j = 0; j < body->ny; ++j)
      for (int k = 0; k < body->nz; ++k)
        if (isCorner(mask, i, j, k)) {
          const int node = body->node(i, j, k);
          body->pointAt[node] = body->count();
          body->nodeOf.push_back(node);
        }
}

// The springs by offset in table order, each offset's in the order of their end a.
void addSprings(Body* body) {
  for (const SpringOffset& o : kSpringOffsets) {
    const double rest = restLength(o, body->spacing);
    for (int a = 0; a < body->count(); ++a) {
      const std::array<int, 3> i = body->index(a);
      const int b = body->pointAtIndex(i[0] + o.di, i[1] + o.dj, i[2] + o.dk);
      if (b >= 0) body->springs.push_back({a, b, rest, o.kind});
    }
  }
}

// The face of the voxel grid normal to `axis` at node plane s, quad (u, v): whether it is on the
// surface, and on which side the body lies. cell(axis, s) is the voxel on the plane's + side.
struct FaceGrid {
  const VoxelMask& mask;
  const Body& body;
  int nodes(int axis) const { return axis == 0 ? body.nx : axis == 1 ? body.ny : body.nz; }
  // (i, j, k) with s along `axis`, u and v along the next two (cyclically).
  static std::array<int, 3> at(int axis, int s, int u, int v) {
    std::array<int, 3> c;
    c[axis] = s;
    c[(axis + 1) % 3] = u;
    c[(axis + 2) % 3] = v;
    return c;
  }
  bool cell(int axis, int s, int u, int v) const {
    const std::array<int, 3> c = at(axis, s, u, v);
    return mask.at(c[0], c[1], c[2]);
  }
  int point(int axis, int s, int u, int v) const {
    const std::array<int, 3> c = at(axis, s, u, v);
    return body.pointAtIndex(c[0], c[1], c[2]);
  }
};

// The two triangles of quad (u, v) on node plane s normal to `axis`, facing -axis (outwardIsPlus
// false) or +axis. The quad's corners a, b, c, d run counter-clockwise seen from +axis; facing
// -axis they are taken in the opposite order, so that every triangle winds counter-clockwise seen
// from outside. Quads whose centre lies on the (1, 1) diagonal's side of the grid's face centre
// are split along a-c, the others along b-d, so that on a box's face the diagonal at each of the
// face's corners passes through the corner (a corner's normal is then the diagonal's, as area
// weighting gives it, seen from every corner alike).
void addQuad(const FaceGrid& g, int axis, int s, int u, int v, bool outwardIsPlus,
             std::vector<Triangle>* out) {
  const int a = g.point(axis, s, u, v), b = g.point(axis, s, u + 1, v);
  const int c = g.point(axis, s, u + 1, v + 1), d = g.point(axis, s, u, v + 1);
  JELLO_ASSERT(a >= 0 && b >= 0 && c >= 0 && d >= 0);
  const int du = 2 * u + 1 - (g.nodes((axis + 1) % 3) - 1);
  const int dv = 2 * v + 1 - (g.nodes((axis + 2) % 3) - 1);
  const bool alongAC = du * dv >= 0;
  Triangle first = alongAC ? Triangle{a, b, c} : Triangle{a, b, d};
  Triangle second = alongAC ? Triangle{a, c, d} : Triangle{b, c, d};
  if (!outwardIsPlus) {
    std::swap(first[1], first[2]);
    std::swap(second[1], second[2]);
  }
  out->push_back(first);
  out->push_back(second);
}

// Every voxel face with a filled voxel on one side and none on the other, by axis, then facing
// -axis before +axis, then by node plane and quad: for a box, the course's order (the faces
// x = 0, x = 7, y = 0, ... in turn).
void addSurface(const VoxelMask& mask, Body* body) {
  const FaceGrid g{mask, *body};
  for (int axis = 0; axis < 3; ++axis)
    for (bool plus : {false, true})
      for (int s = 0; s < g.nodes(axis); ++s)
        for (int u = 0; u + 1 < g.nodes((axis + 1) % 3); ++u)
          for (int v = 0; v + 1 < g.nodes((axis + 2) % 3); ++v) {
            const bool above = g.cell(axis, s, u, v), below = g.cell(axis, s - 1, u, v);
            if (plus ? (below && !above) : (above && !below))
              addQuad(g, axis, s, u, v, plus, &body->surface);
          }
  std::vector<char> onSurface(body->count(), 0);
  for (const Triangle& t : body->surface)
    for (int q : t) onSurface[q] = 1;
  body->surfaceVertexOf.assign(body->count(), -1);
  for (int q = 0; q < body->count(); ++q)
    if (onSurface[q]) {
      body->surfaceVertexOf[q] = static_cast<int>(body->surfacePoints.size());
      body->surfacePoints.push_back(q);
    }
}

}  // namespace

Body voxelBody(const VoxelMask& mask, double spacing, std::string what) {
  JELLO_ASSERT(mask.nx >= 1 && mask.ny >= 1 && mask.nz >= 1);
  JELLO_ASSERT(static_cast<long long>(mask.nx + 1) * (mask.ny + 1) * (mask.nz + 1) <=
               kMostScenePoints);
  JELLO_ASSERT(spacing > 0 && std::isfinite(spacing));
  Body body;
  body.what = std::move(what);
  body.nx = mask.nx + 1;
  body.ny = mask.ny + 1;
  body.nz = mask.nz + 1;
  body.spacing = spacing;
  numberPoints(mask, &body);
  JELLO_ASSERT(body.count() > 0);
  addSprings(&body);
  addSurface(mask, &body);
  body.voxels = mask;
  return body;
}

namespace {

// A sheet: every node a point, the springs that stay in its plane, the sheet as its surface.
Body sheetBody(int nx, int ny, int nz, double spacing, std::string what) {
  Body body;
  body.what = std::move(what);
  body.nx = nx, body.ny = ny, body.nz = nz;
  body.spacing = spacing;
  JELLO_ASSERT(static_cast<long long>(nx) * ny * nz <= kMostScenePoints);
  const int nodes = nx * ny * nz;
  for (int node = 0; node < nodes; ++node) {
    body.pointAt.push_back(node);
    body.nodeOf.push_back(node);
  }
  addSprings(&body);
  const int axis = nx == 1 ? 0 : ny == 1 ? 1 : 2;
  const VoxelMask none;
  const FaceGrid g{none, body};
  for (int u = 0; u + 1 < g.nodes((axis + 1) % 3); ++u)
    for (int v = 0; v + 1 < g.nodes((axis + 2) % 3); ++v)
      addQuad(g, axis, 0, u, v, true, &body.surface);
  body.surfaceVertexOf.resize(nodes);
  for (int q = 0; q < nodes; ++q) body.surfacePoints.push_back(q), body.surfaceVertexOf[q] = q;
  return body;
}

}  // namespace

Body latticeBody(int nx, int ny, int nz, double spacing) {
  const std::string what = "the " + std::to_string(nx) + "x" + std::to_string(ny) + "x" +
                           std::to_string(nz) +
                           (nx == 1 || ny == 1 || nz == 1 ? " sheet" : " lattice");
  JELLO_ASSERT((nx == 1) + (ny == 1) + (nz == 1) <= 1);
  if (nx == 1 || ny == 1 || nz == 1) return sheetBody(nx, ny, nz, spacing, what);
  VoxelMask mask{nx - 1, ny - 1, nz - 1, {}};
  mask.filled.assign(std::size_t(mask.nx) * mask.ny * mask.nz, 1);
  Body body = voxelBody(mask, spacing, what);
  body.courseLattice =
      nx == kLatticeSize && ny == kLatticeSize && nz == kLatticeSize && spacing == kRestSpacing;
  return body;
}

bool isSheet(const Body& body) {
  return !body.joined() && (body.nx == 1 || body.ny == 1 || body.nz == 1);
}

Body joinBodies(std::vector<std::shared_ptr<const Body>> parts) {
  JELLO_ASSERT(parts.size() >= 2 && parts.size() <= std::size_t(kMostJellies));
  Body joined;
  joined.what = std::to_string(parts.size()) + " jellies";
  joined.partFirst.push_back(0);
  for (std::size_t p = 0; p < parts.size(); ++p) {
    const Body& part = *parts[p];
    JELLO_ASSERT(!part.joined());
    const int first = joined.count();
    for (int node : part.nodeOf) joined.nodeOf.push_back(node);
    for (Spring s : part.springs) {
      s.a += first, s.b += first;
      s.part = static_cast<std::uint16_t>(p);
      joined.springs.push_back(s);
    }
    for (Triangle t : part.surface)
      joined.surface.push_back({t[0] + first, t[1] + first, t[2] + first});
    joined.partFirst.push_back(joined.count());
  }
  joined.surfaceVertexOf.assign(joined.count(), -1);
  for (std::size_t p = 0; p < parts.size(); ++p)
    for (int q : parts[p]->surfacePoints) {
      const int point = q + joined.partFirst[p];
      joined.surfaceVertexOf[point] = static_cast<int>(joined.surfacePoints.size());
      joined.surfacePoints.push_back(point);
    }
  joined.spacing = parts[0]->spacing;
  joined.parts = std::move(parts);
  return joined;
}

std::vector<Tet> tetrahedraOf(const Body& body) {
  JELLO_ASSERT(!body.joined());
  if (body.gridless()) return body.meshTets;
  std::vector<Tet> tets;
  const VoxelMask& mask = body.voxels;
  // Kuhn's split: the paths from corner (0,0,0) to (1,1,1) one axis at a time, one per order of
  // the axes; a tetrahedron per path.
  static const int kOrders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2},
                                    {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int i = 0; i < mask.nx; ++i)
    for (int j = 0; j < mask.ny; ++j)
      for (int k = 0; k < mask.nz; ++k) {
        if (!mask.at(i, j, k)) continue;
        for (const auto& order : kOrders) {
          int corner[3] = {i, j, k};
          Tet t;
          t[0] = body.pointAtIndex(i, j, k);
          for (int step = 0; step < 3; ++step) {
            ++corner[order[step]];
            t[step + 1] = body.pointAtIndex(corner[0], corner[1], corner[2]);
          }
          // An odd order of the axes winds the path the other way: swap to keep volumes positive.
          const bool odd = (order[0] == 0 && order[1] == 2) || (order[0] == 1 && order[1] == 0) ||
                           (order[0] == 2 && order[1] == 1);
          if (odd) std::swap(t[2], t[3]);
          JELLO_ASSERT(t[0] >= 0 && t[1] >= 0 && t[2] >= 0 && t[3] >= 0);
          tets.push_back(t);
        }
      }
  return tets;
}

double tetVolume(const Tet& t, const double* p, int n) {
  const Vec3 x0 = load(p, t[0], n);
  return dot(load(p, t[1], n) - x0, cross(load(p, t[2], n) - x0, load(p, t[3], n) - x0)) / 6;
}

std::vector<double> restPositionsOf(const Body& body) {
  const int n = body.count();
  std::vector<double> rest(3 * std::size_t(n));
  for (int q = 0; q < n; ++q) store(rest.data(), q, n, body.restPosition(q));
  return rest;
}

double restVolume(const Body& body) {
  const std::vector<double> rest = restPositionsOf(body);
  double volume = 0;
  for (const Tet& t : tetrahedraOf(body)) volume += tetVolume(t, rest.data(), body.count());
  return volume;
}

const Body& courseBody() {
  static const Body body = latticeBody(kLatticeSize, kLatticeSize, kLatticeSize, kRestSpacing);
  return body;
}

std::vector<Vec3> surfaceNormals(const Body& body, const double* positions) {
  const int n = body.count();
  std::vector<Vec3> normal(n);
  for (const Triangle& t : body.surface) {
    const Vec3 a = load(positions, t[0], n), b = load(positions, t[1], n),
               c = load(positions, t[2], n);
    const Vec3 normalSum = cross(b - a, c - a);  // its length is twice the area: area-weighted
    for (int q : t) normal[q] += normalSum;
  }
  for (Vec3& v : normal) {
    double unused;
    v = direction(v, &unused);
  }
  return normal;
}

}  // namespace jello
