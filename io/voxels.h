// io/voxels.h: solid shapes as grids of cubic voxels, the raw material of a jelly body of any
// shape: a closed triangle mesh read from a Wavefront OBJ file (tinyobjloader), or a ball. The
// body made from a grid (elsewhere) has a point at each corner of a filled voxel.
//
// Units: metres. Every function that can fail returns false and writes one line (no newline, no
// control characters) saying why; nothing here throws for bad input.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "core/limits.h"
#include "model/body.h"
#include "model/vec3.h"

namespace jello {

// Which voxels of a grid are filled (body.h's VoxelMask: filled[(i*ny + j)*nz + k] is 1 for a
// filled voxel and 0 for an empty one; the functions below write no other value), and where the
// grid lies: voxel (i,j,k) spans origin + size*([i,i+1] x [j,j+1] x [k,k+1]).
struct VoxelGrid : VoxelMask {
  double size = 0;  // m, a voxel's edge
  Vec3 origin;      // m, the lower corner of voxel (0,0,0)

  int count() const;  // filled voxels
  // The centre of voxel (i,j,k), m.
  Vec3 centre(int i, int j, int k) const;
};

// A triangle mesh: vertices (m) and triangles as three indices into them.
struct TriangleMesh {
  std::string name;  // where it came from (the file's path), for messages; may be ""
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> triangles;
};

// Reads a Wavefront OBJ file (a regular file of at most kMostObjBytes) with tinyobjloader: its
// vertices (`v` lines) and faces (`f`), every object and group together, each polygon cut into
// triangles as a fan from its first corner; a face of fewer than three corners is skipped.
// Normals, texture coordinates, materials (no .mtl file is opened), lines and points are
// ignored. Returns false with *why naming the file when it cannot be read, is not an OBJ file
// tinyobjloader accepts, has no triangles or more than kMostMeshTriangles (or more than 3 million
// `v`, `vn` or `vt` lines), a vertex without three plain decimal coordinates (tinyobjloader would
// read "nan" or "x" as 0) of at most kLargestMeshCoordinate in magnitude, or a face with a vertex
// index out of range.
bool readObjMesh(const std::string& path, TriangleMesh* mesh, std::string* why);
// The same from the file's text (at most kMostObjBytes); `name` stands for the file in messages.
bool parseObjText(std::string text, const std::string& name, TriangleMesh* mesh, std::string* why);

// Voxelises a closed mesh in its own coordinates (the caller places the result): a voxel is
// filled when its centre is inside the mesh (an odd number of crossings of the mesh by a ray
// from the centre; voxels.cpp says how rays through edges and vertices are counted). The grid is
// the fewest voxels of edge `size` (m) along each axis that cover the bounding box of the
// mesh's triangles (unused vertices do not count), centred on it. Returns false with *why (naming
// mesh.name when it is not empty) when size is not > 0 and at most kLargestMeshCoordinate, when a
// triangle's index or corner is bad, when an axis would need more than kMostBodyPoints - 1 voxels,
// when the mesh is not closed (a vertical line through a column of voxel centres crosses it an odd
// number of times; a hole no such line passes through changes nothing), or when no voxel is
// filled.
bool voxeliseMesh(const TriangleMesh& mesh, double size, VoxelGrid* grid, std::string* why);

// A ball of radius `radius` (m) centred on the origin: the voxels whose centre lies within the
// radius, in the fewest voxels of edge `size` (m) along each axis that cover [-r, r]^3, centred
// on the origin. Returns false with *why when radius or size is not finite and > 0, either is
// larger than kLargestMeshCoordinate, an axis would need more than kMostBodyPoints - 1 voxels,
// or no voxel is filled.
bool voxeliseSphere(double radius, double size, VoxelGrid* grid, std::string* why);

// Keeps only the largest group of filled voxels joined through faces (a body must hold
// together: two separate lumps would be two bodies; an edge or a corner is too weak a joint);
// of equal groups, the one holding the first filled voxel in storage order. Returns how many
// voxels were emptied.
int keepLargestPiece(VoxelGrid* grid);

}  // namespace jello
