// The surface mesh (app/surface.h): a closed, consistently wound surface of the right volume,
// with the right normals on the rest lattice. No GL.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <vector>

#include "app/surface.h"
#include "test_support.h"

namespace jello {
namespace {

constexpr int kLast = kLatticeSize - 1;

// Volume enclosed by the surface at `positions` (divergence theorem): the sum over triangles of
// a . (b x c) / 6. Positive when the triangles wind counter-clockwise seen from outside.
double signedVolume(const double* positions) {
  double sixTimes = 0;
  for (const Triangle& t : surfaceTriangles())
    sixTimes += dot(load(positions, t[0]), cross(load(positions, t[1]), load(positions, t[2])));
  return sixTimes / 6;
}

bool onSurface(int i, int j, int k) {
  return i == 0 || i == kLast || j == 0 || j == kLast || k == 0 || k == kLast;
}

TEST(Surface, Has296VerticesAnd588TrianglesOnTheBoundaryPoints) {
  const std::vector<int>& points = surfacePoints();
  ASSERT_EQ(points.size(), 296u);
  EXPECT_EQ(kSurfacePoints, 296);
  EXPECT_TRUE(std::is_sorted(points.begin(), points.end()));
  int boundary = 0;
  for (int i = 0; i < kLatticeSize; ++i)
    for (int j = 0; j < kLatticeSize; ++j)
      for (int k = 0; k < kLatticeSize; ++k) {
        const int q = pointIndex(i, j, k);
        const bool listed = std::binary_search(points.begin(), points.end(), q);
        EXPECT_EQ(listed, onSurface(i, j, k)) << latticeLabel(q);
        EXPECT_EQ(surfaceVertexOfPoint()[q] >= 0, onSurface(i, j, k)) << latticeLabel(q);
        boundary += onSurface(i, j, k);
      }
  EXPECT_EQ(boundary, 296);
  for (std::size_t n = 0; n < points.size(); ++n)
    EXPECT_EQ(surfaceVertexOfPoint()[points[n]], static_cast<int>(n));

  const std::vector<Triangle>& triangles = surfaceTriangles();
  ASSERT_EQ(triangles.size(), 588u);
  std::set<int> used;
  for (const Triangle& t : triangles) {
    EXPECT_TRUE(t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) << "a degenerate triangle";
    for (int q : t) used.insert(q);
  }
  EXPECT_EQ(used, std::set<int>(points.begin(), points.end())) << "every surface point is used";
}

TEST(Surface, IsClosedAndManifoldWithConsistentWinding) {
  // Each directed edge a->b once, and its reverse b->a once in another triangle: then every
  // edge has exactly two triangles, wound the same way round the surface.
  std::map<std::pair<int, int>, int> directed;
  for (const Triangle& t : surfaceTriangles())
    for (int e = 0; e < 3; ++e) ++directed[{t[e], t[(e + 1) % 3]}];
  std::map<std::pair<int, int>, int> undirected;
  for (const auto& [edge, count] : directed) {
    EXPECT_EQ(count, 1) << "edge " << edge.first << "->" << edge.second << " twice one way";
    EXPECT_EQ(directed.count({edge.second, edge.first}), 1u)
        << "edge " << edge.first << "->" << edge.second << " has no opposite";
    undirected[{std::min(edge.first, edge.second), std::max(edge.first, edge.second)}] += count;
  }
  for (const auto& [edge, count] : undirected)
    EXPECT_EQ(count, 2) << edge.first << "-" << edge.second;
  // Euler's formula for a sphere: V - E + F = 2.
  EXPECT_EQ(296 - static_cast<int>(undirected.size()) + 588, 2);
}

TEST(Surface, EnclosesTheRestCubesOneCubicMetreWoundOutward) {
  const State rest = test::restLattice();
  EXPECT_NEAR(signedVolume(rest.p()), 1.0, 1e-12);
  // Moved rigidly (turned a quarter about z and shifted), the volume stays 1 m^3.
  State moved = rest;
  for (int q = 0; q < kNumPoints; ++q) {
    const Vec3 p = load(rest.p(), q);
    store(moved.p(), q, Vec3{-p.y + 0.5, p.x - 1, p.z + 0.25});
  }
  EXPECT_NEAR(signedVolume(moved.p()), 1.0, 1e-12);
}

TEST(Surface, NormalsOfTheRestCubeAreTheFacesAxesAndTheCornersDiagonals) {
  const State rest = test::restLattice();
  const std::vector<Vec3> normals = surfaceNormals(rest.p());
  ASSERT_EQ(normals.size(), static_cast<std::size_t>(kNumPoints));
  const auto expectNormal = [&](int i, int j, int k, Vec3 expected) {
    const Vec3 n = normals[pointIndex(i, j, k)];
    EXPECT_NEAR(n.x, expected.x, 1e-12) << i << j << k;
    EXPECT_NEAR(n.y, expected.y, 1e-12) << i << j << k;
    EXPECT_NEAR(n.z, expected.z, 1e-12) << i << j << k;
  };
  // A point inside each face (not on an edge): the face's outward axis.
  expectNormal(3, 4, kLast, {0, 0, 1});
  expectNormal(3, 4, 0, {0, 0, -1});
  expectNormal(kLast, 3, 4, {1, 0, 0});
  expectNormal(0, 3, 4, {-1, 0, 0});
  expectNormal(4, kLast, 3, {0, 1, 0});
  expectNormal(4, 0, 3, {0, -1, 0});
  const double c = 1 / std::sqrt(3.0);
  for (int i : {0, kLast})
    for (int j : {0, kLast})
      for (int k : {0, kLast}) expectNormal(i, j, k, {i ? c : -c, j ? c : -c, k ? c : -c});
  // An edge point between faces x = 7 and z = 7 at rest: halfway between their axes.
  expectNormal(kLast, 3, kLast, {std::sqrt(0.5), 0, std::sqrt(0.5)});
  EXPECT_EQ(length(normals[pointIndex(3, 3, 3)]), 0) << "an interior point has none";
  for (int q : surfacePoints()) EXPECT_NEAR(length(normals[q]), 1, 1e-15) << latticeLabel(q);
}

TEST(Surface, NormalsWeighTheTrianglesByTheirAreas) {
  // The cube stretched to 2 m along x: the triangles of the faces y = 7 and z = 7 have twice the
  // area of those of x = 7, so the corner [7][7][7] leans (1, 2, 2)/3, not (1, 1, 1)/sqrt(3).
  State stretched = test::restLattice();
  for (int q = 0; q < kNumPoints; ++q) stretched.p()[coordIndex(q, 0)] *= 2;
  const Vec3 n = surfaceNormals(stretched.p())[pointIndex(kLast, kLast, kLast)];
  EXPECT_NEAR(n.x, 1.0 / 3, 1e-12);
  EXPECT_NEAR(n.y, 2.0 / 3, 1e-12);
  EXPECT_NEAR(n.z, 2.0 / 3, 1e-12);
  EXPECT_NEAR(signedVolume(stretched.p()), 2.0, 1e-12);
}

}  // namespace
}  // namespace jello
