// surface.h: the cube's surface as a triangle mesh, shared by the exported meshes (app/export.h)
// and the drawing (showCube.cpp). No GL: plain arithmetic on the positions.
//
// The surface is the 6 faces of the 8x8x8 lattice: its 296 boundary points (8^3 - 6^3, those
// with a lattice index 0 or 7; the points along an edge or at a corner belong to 2 or 3 faces
// and appear once), each face's 7x7 quads split into 2 triangles: 588 triangles. The topology
// never changes; only the positions do.
//
// Conventions:
// - A triangle holds point numbers (pointIndex, world.h: 0..511), not surface vertex numbers.
// - Winding: counter-clockwise seen from outside the cube at rest, so that cross(b - a, c - a)
//   points outward (the right-hand rule) and the signed volume of the rest lattice is +1 m^3.
// - Each quad is split along the diagonal that points toward its face's centre, so that the
//   surface is the same seen from every corner: a corner point lies in both triangles of its
//   quad on each of its 3 faces, and its normal at rest is (+-1, +-1, +-1)/sqrt(3) exactly as
//   area weighting gives it.
#pragma once

#include <array>
#include <vector>

#include "vec3.h"
#include "world.h"

namespace jello {

constexpr int kSurfacePoints =
    kNumPoints - (kLatticeSize - 2) * (kLatticeSize - 2) * (kLatticeSize - 2);      // 296
constexpr int kSurfaceTriangles = 6 * (kLatticeSize - 1) * (kLatticeSize - 1) * 2;  // 588

using Triangle = std::array<int, 3>;  // three point numbers, counter-clockwise from outside

// The 588 triangles, face by face (x = 0, x = 7, y = 0, y = 7, z = 0, z = 7). Built once.
const std::vector<Triangle>& surfaceTriangles();

// The 296 surface points, as point numbers in ascending order: the order the exported files
// list their vertices in.
const std::vector<int>& surfacePoints();

// The surface vertex number (0..295, its place in surfacePoints()) of each of the 512 points;
// -1 for the 216 interior points.
const std::array<int, kNumPoints>& surfaceVertexOfPoint();

// Unit normals of the surface at `positions` (a per-point array of kNumCoords doubles, metres,
// world.h), one per point: each surface point's is the sum of its triangles' cross(b - a, c - a)
// (each twice the triangle's area times its unit normal: an area-weighted average), normalised.
// Zero for interior points, and where the sum is zero (a collapsed surface).
std::vector<Vec3> surfaceNormals(const double* positions);

}  // namespace jello
