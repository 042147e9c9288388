// body.h: the jelly's points and springs: which points there are, which springs join them, and
// the triangles of its surface. The course cube is the 8x8x8 lattice; a scene (docs/scenes.md)
// may give a lattice of any size, or a body voxelised from a mesh or a sphere.
//
// A body is made of cubic voxels of edge `spacing` (m) on a grid: its points are the voxels'
// corners (shared between neighbouring voxels), numbered in the order of their grid node
// (i, j, k) ascending, i slowest. The springs are those of the course's 16 offsets (structural,
// shear, bend) wherever both ends are points, grouped by offset in the table's order and each
// group in the order of its end a: for the full 8x8x8 lattice this is the course's numbering
// and spring list exactly (world.h pointIndex, docs/physics.md).
//
// Per-point arrays of a body of n points hold 3n doubles, all x, then all y, then all z (world.h).
// A body is built once and shared (never changed) by every model of its scene.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "model/vec3.h"
#include "model/world.h"

namespace jello {

enum class SpringKind : std::uint8_t { Structural, Shear, Bend };
constexpr int kSpringKinds = 3;
const char* springKindName(SpringKind kind);  // "structural", "shear", "bend"

// One row of the table the spring list is built from: every point at grid node (i,j,k) whose
// neighbour (i+di, j+dj, k+dk) is a point too is joined to it by a spring of rest length
// spacing * |offset|.
struct SpringOffset {
  int di, dj, dk;
  SpringKind kind;
};
// 16 rows (6220 springs in the course cube); the order in which the kernel adds them.
inline constexpr std::array<SpringOffset, 16> kSpringOffsets = {{
    // structural
    {1, 0, 0, SpringKind::Structural},
    {0, 1, 0, SpringKind::Structural},
    {0, 0, 1, SpringKind::Structural},
    // face shear
    {1, 1, 0, SpringKind::Shear},
    {1, -1, 0, SpringKind::Shear},
    {1, 0, 1, SpringKind::Shear},
    {1, 0, -1, SpringKind::Shear},
    {0, 1, 1, SpringKind::Shear},
    {0, 1, -1, SpringKind::Shear},
    // body shear
    {1, 1, 1, SpringKind::Shear},
    {1, 1, -1, SpringKind::Shear},
    {1, -1, 1, SpringKind::Shear},
    {1, -1, -1, SpringKind::Shear},
    // bend
    {2, 0, 0, SpringKind::Bend},
    {0, 2, 0, SpringKind::Bend},
    {0, 0, 2, SpringKind::Bend},
}};

// The rest length of an offset's springs in a grid of `spacing` (m): spacing * |offset|, computed
// as docs/physics.md gives it for the course (spacing * sqrt(di^2 + dj^2 + dk^2)); the row kernel
// and every body's spring list take it from here, so that they agree to the bit.
double restLength(const SpringOffset& o, double spacing = kRestSpacing);

struct Spring {
  int a, b;     // point numbers
  double rest;  // m, from the ideal lattice
  SpringKind kind;
  std::uint16_t part = 0;  // the jelly it belongs to, in a scene of several (joinBodies); else 0
};

using Triangle = std::array<int, 3>;  // three point numbers, counter-clockwise from outside
// Four point numbers, ordered so that the tetrahedron's volume at rest,
// (x1 - x0) . ((x2 - x0) x (x3 - x0)) / 6, is positive.
using Tet = std::array<int, 4>;

// The most points along an edge of a voxel body's grid (io/voxels: a mesh or a ball voxelised);
// a lattice or sheet may have any number along an axis within kMostScenePoints in all.
constexpr int kMostBodyPoints = 48;
// The most jellies a scene may hold ([[jelly]], docs/scenes.md), and the most points of them all.
constexpr int kMostJellies = 64;
constexpr int kMostScenePoints = 1 << 20;

// Which voxels of an nx x ny x nz grid are filled: filled[cell(i, j, k)].
struct VoxelMask {
  int nx = 0, ny = 0, nz = 0;
  std::vector<char> filled;
  std::size_t cell(int i, int j, int k) const { return (std::size_t(i) * ny + j) * nz + k; }
  bool at(int i, int j, int k) const {
    return i >= 0 && j >= 0 && k >= 0 && i < nx && j < ny && k < nz && filled[cell(i, j, k)];
  }
};

struct Body {
  std::string what;            // "the 8x8x8 lattice", "a 16x4x4 lattice", "voxels of duck.obj", ...
  int nx = 0, ny = 0, nz = 0;  // grid nodes along x, y, z (voxels + 1)
  double spacing = 0;          // m, between neighbouring nodes
  std::vector<int> nodeOf;     // point -> grid node (node(i, j, k))
  std::vector<int> pointAt;    // grid node -> point, or -1
  std::vector<Spring> springs;
  std::vector<Triangle> surface;     // counter-clockwise seen from outside
  std::vector<int> surfacePoints;    // the points on the surface, ascending
  std::vector<int> surfaceVertexOf;  // point -> its place in surfacePoints, or -1
  bool courseLattice = false;        // the 8x8x8 lattice of spacing 1/7: the course's cube
  VoxelMask voxels;                  // a grid body's filled voxels (none for a sheet)
  // A body of no grid (a tetrahedral mesh, io/tetmesh.h): each point's rest position, m, and its
  // tetrahedra; `spacing` is then its tetrahedra's mean edge. Empty for a grid body.
  std::vector<Vec3> rest;
  std::vector<Tet> meshTets;
  // A scene's several jellies joined into one body (joinBodies): part p's points are
  // [partFirst[p], partFirst[p + 1]), numbered as in parts[p], its springs and triangles those of
  // parts[p] renumbered, in the order of the parts. Empty for one body. A joined body has no grid
  // of its own: index, restPosition and label are its part's.
  std::vector<std::shared_ptr<const Body>> parts;
  std::vector<int> partFirst;

  int count() const { return static_cast<int>(nodeOf.size()); }
  int coords() const { return 3 * count(); }
  bool joined() const { return !parts.empty(); }
  bool gridless() const { return !rest.empty(); }
  // The part point q belongs to (0 for a body that is not joined).
  int partOf(int q) const;
  // Grid node (i, j, k)'s number: (i * ny + j) * nz + k.
  int node(int i, int j, int k) const { return (i * ny + j) * nz + k; }
  // The grid index of point q; (q, 0, 0) in a body of no grid.
  std::array<int, 3> index(int q) const;
  // Point q at rest, m: spacing * its grid index (node (0, 0, 0) at the origin).
  Vec3 restPosition(int q) const;
  // "[i][j][k]" for point q ("#q" in a body of no grid); in a joined body "[i][j][k] of jelly P"
  // (P from 1).
  std::string label(int q) const;
  // The point at grid node (i, j, k), or -1 (also outside the grid, and in a joined body).
  int pointAtIndex(int i, int j, int k) const;
};

// A body of every corner of the filled voxels of `mask`, spacing metres apart. The mask must hold
// at least one filled voxel; its grid's nodes are kMostScenePoints at most.
Body voxelBody(const VoxelMask& mask, double spacing, std::string what);
// The nx x ny x nz lattice (each from 2, except that one of them may be 1: a sheet, a cloth; at
// most kMostScenePoints nodes in all) of points spacing metres apart. A sheet's springs are those
// of the offsets that stay in its plane (structural, face shear and bend); its surface is the
// sheet, its triangles wound counter-clockwise seen from the + side of the thin axis.
Body latticeBody(int nx, int ny, int nz, double spacing);
// Whether the body is a sheet (one point thick along an axis).
bool isSheet(const Body& body);
// The bodies as one (Body::parts): points, springs and triangles of each in turn, each spring
// marked with its part. At least two parts.
Body joinBodies(std::vector<std::shared_ptr<const Body>> parts);
// The course's cube, built once (the 8x8x8 lattice of spacing kRestSpacing).
const Body& courseBody();

// The tetrahedra of a body that is not joined, for finite elements: each filled voxel of a grid
// body split into the 6 of Kuhn's split along its diagonal from corner (0,0,0) to (1,1,1), the
// same in every voxel so that neighbours' faces match (a conforming mesh), in voxel order; a
// mesh's own. None for a sheet.
std::vector<Tet> tetrahedraOf(const Body& body);
// The body's rest positions (restPosition) as a per-point array, m.
std::vector<double> restPositionsOf(const Body& body);
// The volume of the body's tetrahedra at rest (tetrahedraOf; a body that is not joined), m^3.
double restVolume(const Body& body);
// A tetrahedron's volume at positions p (a per-point array of n points), m^3: positive when it is
// oriented as at rest, negative when inverted.
double tetVolume(const Tet& t, const double* p, int n);

// Unit normals of the body's surface at `positions` (a per-point array of the body's), one per
// point: each surface point's is the sum of its triangles' cross(b - a, c - a) (twice the
// triangle's area times its unit normal: an area-weighted average), normalised. Zero for interior
// points, and where the sum is zero (a collapsed surface).
std::vector<Vec3> surfaceNormals(const Body& body, const double* positions);

}  // namespace jello
