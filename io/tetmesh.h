// io/tetmesh.h: a tetrahedral mesh from TetGen's files (docs/scenes.md, "Finite elements"):
// FILE.node (the points) and FILE.ele beside it (the tetrahedra), read as a body of no grid
// (model/body.h Body::rest, meshTets).
//
// Units: metres, as the file's coordinates are. Bad input throws InputError, one line:
// "FILE:LINE: what is wrong (field)".
#pragma once

#include <string>

#include "model/body.h"

namespace jello {

// The .ele file that goes with a .node file: "x.1.node" -> "x.1.ele". The caller has checked that
// `nodePath` ends in ".node".
std::string elementFileOf(const std::string& nodePath);

// Reads `nodePath` and its .ele file (each a regular file of at most kMostTetMeshBytes): every
// point a point of the body, every tetrahedron an element, reoriented where its volume is
// negative. The points are numbered from the file's first (0 or 1, as TetGen may) in order; the
// body's rest positions are the file's coordinates, its spacing its tetrahedra's mean edge, its
// surface the faces that belong to one tetrahedron alone (wound counter-clockwise seen from
// outside), its springs (for a jelly of springs) one of kind structural along every edge.
// Refused: a header that is not TetGen's (the count, dimension 3, attribute and marker counts), a
// line that is not whole numbers and finite coordinates of at most kLargestMeshCoordinate, points
// numbered out of order, fewer lines than the header says or more, more points than
// kMostScenePoints or tetrahedra than kMostMeshTetrahedra, tetrahedra of other than 4 nodes (a
// quadratic mesh), a node number the .node file does not have, a tetrahedron with a node twice or
// of no volume (under 1e-12 of its edges' cube), a point no tetrahedron uses, two points at one
// place, a tetrahedron given twice (its nodes in any order), two tetrahedra on the same side of
// a face they share, and a face of three or more tetrahedra. (Two tetrahedra that cross without
// sharing a face are not looked for.)
Body readTetMesh(const std::string& nodePath);
// The two files' texts alone: false with *why (one line naming the file) when either cannot be
// read (missing, not a regular file, over kMostTetMeshBytes).
bool readTetMeshFiles(const std::string& nodePath, std::string* nodeText, std::string* eleText,
                      std::string* why);
// The same from the two files' texts; the names stand for the files in messages.
Body parseTetMesh(const std::string& nodeText, const std::string& nodeName,
                  const std::string& eleText, const std::string& eleName);

}  // namespace jello
