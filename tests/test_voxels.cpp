// Voxels (io/voxels.h): OBJ files read through tinyobjloader and their refusals, meshes and
// balls made into voxels with counts worked out by hand, rays through edges and vertices, the
// showcase's model, and the largest piece kept.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <string>
#include <vector>

#include "io/voxels.h"
#include "test_support.h"

namespace jello {
namespace {

using test::makeTempDir;
using test::removeTree;
using test::writeText;

// A box [lo, hi] as a closed mesh, each face cut at the fractions `cuts` (0 and 1 added) of
// its sides into quads, each quad cut into two triangles along a diagonal, wound outwards.
TriangleMesh boxMesh(Vec3 lo, Vec3 hi, std::vector<double> cuts = {}) {
  cuts.insert(cuts.begin(), 0.0);
  cuts.push_back(1.0);
  TriangleMesh mesh;
  const double sign[2] = {-1, 1};
  for (int axis = 0; axis < 3; ++axis)
    for (int end = 0; end < 2; ++end) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;  // (u, v, axis) is right-handed
      const int first = static_cast<int>(mesh.vertices.size());
      const int n = static_cast<int>(cuts.size());
      for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) {
          double p[3];
          const double l[3] = {lo.x, lo.y, lo.z}, h[3] = {hi.x, hi.y, hi.z};
          p[axis] = end ? h[axis] : l[axis];
          p[u] = l[u] + cuts[a] * (h[u] - l[u]);
          p[v] = l[v] + cuts[b] * (h[v] - l[v]);
          mesh.vertices.push_back({p[0], p[1], p[2]});
        }
      for (int a = 0; a + 1 < n; ++a)
        for (int b = 0; b + 1 < n; ++b) {
          const int q00 = first + a * n + b, q10 = q00 + n, q01 = q00 + 1, q11 = q10 + 1;
          // (u, v) counter-clockwise faces +axis: flipped on the low end.
          if (sign[end] > 0) {
            mesh.triangles.push_back({q00, q10, q11});
            mesh.triangles.push_back({q00, q11, q01});
          } else {
            mesh.triangles.push_back({q00, q11, q10});
            mesh.triangles.push_back({q00, q01, q11});
          }
        }
    }
  return mesh;
}

// The mesh as OBJ text: `v` and `f` lines.
std::string objText(const TriangleMesh& mesh) {
  std::string text;
  char line[128];
  for (const Vec3& p : mesh.vertices) {
    std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", p.x, p.y, p.z);
    text += line;
  }
  for (const auto& t : mesh.triangles)
    text += "f " + std::to_string(t[0] + 1) + " " + std::to_string(t[1] + 1) + " " +
            std::to_string(t[2] + 1) + "\n";
  return text;
}

// p rotated by `angle` (radians) about the unit axis `axis` (Rodrigues).
Vec3 rotate(Vec3 p, Vec3 axis, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return c * p + s * cross(axis, p) + (dot(axis, p) * (1 - c)) * axis;
}

// The message is one line of printable text.
void expectOneLine(const std::string& why) {
  EXPECT_FALSE(why.empty());
  for (const char c : why) EXPECT_TRUE(static_cast<unsigned char>(c) >= 0x20 && c != 0x7f) << why;
}

std::string modelPath() { return std::string(JELLO_SOURCE_DIR) + "/scenes/models/jelly-mould.obj"; }

// An OBJ file in a fresh folder, removed with it.
class VoxelObjFile : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = makeTempDir(); }
  void TearDown() override { removeTree(dir_); }
  std::string write(const std::string& text, const std::string& name = "model.obj") {
    const std::string path = dir_ + "/" + name;
    writeText(path, text);
    return path;
  }
  // Reading `text` fails, with one line naming the file and holding `words`.
  void expectRefused(const std::string& text, const std::string& words) {
    const std::string path = write(text);
    TriangleMesh mesh;
    std::string why;
    EXPECT_FALSE(readObjMesh(path, &mesh, &why)) << words;
    expectOneLine(why);
    EXPECT_NE(why.find(path), std::string::npos) << why;
    EXPECT_NE(why.find(words), std::string::npos) << why;
  }
  std::string dir_;
};

constexpr const char* kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

TEST(VoxelGrid, AtIsFalseOutsideAndCountCountsTheFilled) {
  VoxelGrid grid;
  grid.nx = 2, grid.ny = 3, grid.nz = 4, grid.size = 0.5, grid.origin = {1, 2, 3};
  grid.filled.assign(24, 0);
  grid.filled[(1 * 3 + 2) * 4 + 3] = 1;
  grid.filled[0] = 1;
  EXPECT_EQ(grid.count(), 2);
  EXPECT_TRUE(grid.at(1, 2, 3));
  EXPECT_TRUE(grid.at(0, 0, 0));
  EXPECT_FALSE(grid.at(1, 2, 2));
  EXPECT_FALSE(grid.at(2, 2, 3));
  EXPECT_FALSE(grid.at(-1, 0, 0));
  EXPECT_FALSE(grid.at(0, 3, 0));
  EXPECT_FALSE(grid.at(0, 0, 4));
  const Vec3 c = grid.centre(1, 2, 3);
  EXPECT_DOUBLE_EQ(c.x, 1.75);
  EXPECT_DOUBLE_EQ(c.y, 3.25);
  EXPECT_DOUBLE_EQ(c.z, 4.75);
}

TEST(VoxelMesh, UnitCubeAtAQuarterFillsExactly64) {
  VoxelGrid grid;
  std::string why;
  ASSERT_TRUE(voxeliseMesh(boxMesh({0, 0, 0}, {1, 1, 1}), 0.25, &grid, &why)) << why;
  EXPECT_EQ(grid.nx, 4);
  EXPECT_EQ(grid.ny, 4);
  EXPECT_EQ(grid.nz, 4);
  EXPECT_EQ(grid.size, 0.25);
  EXPECT_EQ(grid.origin.x, 0);
  EXPECT_EQ(grid.origin.y, 0);
  EXPECT_EQ(grid.origin.z, 0);
  EXPECT_EQ(grid.count(), 64);
}

TEST(VoxelMesh, TheGridIsTheFewestVoxelsCentredOnTheBox) {
  VoxelGrid grid;
  std::string why;
  // 1 m in voxels of 0.3 m: 4 of them, 1.2 m, reaching 0.1 m past each face.
  ASSERT_TRUE(voxeliseMesh(boxMesh({0, 0, 0}, {1, 1, 1}), 0.3, &grid, &why)) << why;
  EXPECT_EQ(grid.nx, 4);
  EXPECT_NEAR(grid.origin.x, -0.1, 1e-15);
  EXPECT_EQ(grid.count(), 64);  // every centre (0.05, 0.35, 0.65, 0.95 on each axis) is inside
  // 1.05 m in voxels of 0.15 m is 7 voxels, though 1.05 / 0.15 is 7.0000000000000009.
  ASSERT_TRUE(voxeliseMesh(boxMesh({0, 0, 0}, {1.05, 0.6, 0.3}), 0.15, &grid, &why)) << why;
  EXPECT_EQ(grid.nx, 7);
  EXPECT_EQ(grid.ny, 4);
  EXPECT_EQ(grid.nz, 2);
  EXPECT_EQ(grid.count(), 56);
}

// The inside test against the cube itself, centre by centre: a cube of edge 0.8 m turned about
// a skew axis and moved far from the origin, in voxels of 0.05 m.
TEST(VoxelMesh, ATurnedAndMovedCubeFillsExactlyTheCentresInsideIt) {
  const Vec3 axis = (1 / std::sqrt(14.0)) * Vec3{1, 2, 3};
  const double angle = 0.7;
  const Vec3 offset{10, -5, 3};
  TriangleMesh mesh = boxMesh({-0.4, -0.4, -0.4}, {0.4, 0.4, 0.4}, {0.5});
  for (Vec3& p : mesh.vertices) p = rotate(p, axis, angle) + offset;
  VoxelGrid grid;
  std::string why;
  ASSERT_TRUE(voxeliseMesh(mesh, 0.05, &grid, &why)) << why;
  int expected = 0, differ = 0;
  for (int i = 0; i < grid.nx; ++i)
    for (int j = 0; j < grid.ny; ++j)
      for (int k = 0; k < grid.nz; ++k) {
        const Vec3 local = rotate(grid.centre(i, j, k) - offset, axis, -angle);
        const bool inside =
            std::fabs(local.x) < 0.4 && std::fabs(local.y) < 0.4 && std::fabs(local.z) < 0.4;
        expected += inside;
        differ += inside != grid.at(i, j, k);
      }
  EXPECT_EQ(differ, 0);
  EXPECT_EQ(grid.count(), expected);
  EXPECT_EQ(grid.count(), 4090);  // this turn's count: 4096 for the cube's volume
  EXPECT_NEAR(grid.count() * 0.05 * 0.05 * 0.05, 0.512, 0.512 * 0.01);  // the cube's volume
}

// Every column's line meets the top and bottom faces exactly at a vertex or on an edge: the
// faces are cut at 0.125, 0.5 and 0.875 of their sides, and the voxel centres are at 0.125,
// 0.375, 0.625 and 0.875, so that a line meets a corner of the cuts (where 3 or 6 triangles
// meet), a cut's side (0.375, 0.125) or a diagonal (0.375, 0.375).
TEST(VoxelMesh, RaysThroughEdgesAndVerticesCountEachCrossingOnce) {
  const TriangleMesh mesh = boxMesh({0, 0, 0}, {1, 1, 1}, {0.125, 0.5, 0.875});
  VoxelGrid grid;
  std::string why;
  ASSERT_TRUE(voxeliseMesh(mesh, 0.25, &grid, &why)) << why;
  EXPECT_EQ(grid.count(), 64);
  // A regular octahedron |x| + |y| + |z| <= 1 in voxels of 2/3 m: the middle column meets both
  // apexes, where four faces meet, and four columns run along edges' shadows. Inside: the
  // middle voxel and its six face neighbours (|x| + |y| + |z| = 2/3).
  TriangleMesh octahedron;
  octahedron.vertices = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  octahedron.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                          {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  ASSERT_TRUE(voxeliseMesh(octahedron, 2.0 / 3, &grid, &why)) << why;
  EXPECT_EQ(grid.nx, 3);
  EXPECT_EQ(grid.count(), 7);
  EXPECT_TRUE(grid.at(1, 1, 1));
  EXPECT_TRUE(grid.at(1, 1, 0));
  EXPECT_FALSE(grid.at(1, 0, 0));
}

TEST(VoxelMesh, TheWindingOfTheFacesDoesNotMatter) {
  TriangleMesh mesh = boxMesh({0, 0, 0}, {1, 1, 1}, {0.5});
  for (std::size_t t = 0; t < mesh.triangles.size(); t += 3)
    std::swap(mesh.triangles[t][0], mesh.triangles[t][1]);
  VoxelGrid grid;
  std::string why;
  ASSERT_TRUE(voxeliseMesh(mesh, 0.25, &grid, &why)) << why;
  EXPECT_EQ(grid.count(), 64);
}

TEST(VoxelMesh, AMeshWithAHoleIsRefused) {
  TriangleMesh mesh = boxMesh({0, 0, 0}, {1, 1, 1});
  mesh.triangles.erase(mesh.triangles.begin() + 10);  // half the top face (+z)
  mesh.name = "holed.obj";
  VoxelGrid grid;
  std::string why;
  EXPECT_FALSE(voxeliseMesh(mesh, 0.25, &grid, &why));
  expectOneLine(why);
  EXPECT_EQ(why.rfind("holed.obj is not closed: the vertical line through", 0), 0u) << why;
}

TEST(VoxelMesh, BadSizesAndBadMeshesAreRefused) {
  const TriangleMesh cube = boxMesh({0, 0, 0}, {1, 1, 1});
  VoxelGrid grid;
  std::string why;
  for (const double size : {0.0, -0.1, std::nan(""), HUGE_VAL, 2e6}) {
    EXPECT_FALSE(voxeliseMesh(cube, size, &grid, &why)) << size;
    expectOneLine(why);
    EXPECT_NE(why.find("voxel size"), std::string::npos) << why;
  }
  EXPECT_FALSE(voxeliseMesh(TriangleMesh{}, 0.1, &grid, &why));
  EXPECT_EQ(why, "the mesh has no triangles");
  TriangleMesh bad = cube;
  bad.triangles[3][1] = 99;
  EXPECT_FALSE(voxeliseMesh(bad, 0.1, &grid, &why));
  EXPECT_EQ(why, "the mesh: a triangle refers to vertex 99 of 24");
  bad = cube;
  bad.vertices[2].y = std::nan("");
  EXPECT_FALSE(voxeliseMesh(bad, 0.1, &grid, &why));
  expectOneLine(why);
  // Flat: no centre inside.
  TriangleMesh flat;
  flat.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  flat.triangles = {{0, 1, 2}, {0, 2, 1}};
  EXPECT_FALSE(voxeliseMesh(flat, 0.1, &grid, &why));
  EXPECT_NE(why.find("no voxel's centre is inside it"), std::string::npos) << why;
}

TEST(VoxelMesh, TooManyVoxelsSaysTheSizeToUse) {
  TriangleMesh mesh = boxMesh({0, 0, 0}, {2.3, 1, 0.5});
  mesh.name = "big.obj";
  VoxelGrid grid;
  std::string why;
  EXPECT_FALSE(voxeliseMesh(mesh, 0.01, &grid, &why));
  EXPECT_EQ(why,
            "big.obj is 2.3 m across (along x): at voxel size 0.01 m that is 230 voxels, at most "
            "47; use a voxel of at least 0.049 m");
  ASSERT_TRUE(voxeliseMesh(mesh, 0.049, &grid, &why)) << why;
  EXPECT_EQ(grid.nx, 47);
  // 47 along an axis is allowed, 48 is not.
  EXPECT_TRUE(voxeliseMesh(boxMesh({0, 0, 0}, {4.7, 1, 1}), 0.1, &grid, &why)) << why;
  EXPECT_FALSE(voxeliseMesh(boxMesh({0, 0, 0}, {1, 1, 4.8}), 0.1, &grid, &why));
  EXPECT_NE(why.find("(along z)"), std::string::npos) << why;
}

TEST(VoxelSphere, TheFilledVolumeIsTheBallsWithinAFewPercent) {
  const double radius = 0.5;
  for (const double size : {0.025, 0.04, 0.05}) {
    VoxelGrid grid;
    std::string why;
    ASSERT_TRUE(voxeliseSphere(radius, size, &grid, &why)) << why;
    const double volume = grid.count() * size * size * size;
    EXPECT_NEAR(volume / (4.0 / 3 * kPi * radius * radius * radius), 1, 0.02) << size;
    // Symmetric about the centre, on each axis and across the diagonal planes.
    int asymmetric = 0;
    const int n = grid.nx;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        for (int k = 0; k < n; ++k) {
          const bool in = grid.at(i, j, k);
          asymmetric += in != grid.at(n - 1 - i, j, k) || in != grid.at(i, n - 1 - j, k) ||
                        in != grid.at(i, j, n - 1 - k) || in != grid.at(j, k, i);
        }
    EXPECT_EQ(asymmetric, 0) << size;
  }
  VoxelGrid grid;
  std::string why;
  ASSERT_TRUE(voxeliseSphere(radius, 0.025, &grid, &why)) << why;
  EXPECT_EQ(grid.nx, 40);
  EXPECT_EQ(grid.origin.x, -0.5);
  EXPECT_EQ(grid.count(), 33552);  // pi/6 * 40^3 is 33510
}

TEST(VoxelSphere, SmallGridsAndRefusals) {
  VoxelGrid grid;
  std::string why;
  ASSERT_TRUE(voxeliseSphere(1, 3, &grid, &why)) << why;  // one voxel, centred on the ball
  EXPECT_EQ(grid.count(), 1);
  // 3 voxels an axis: all but the 8 corners (whose centres are 1.15 m out).
  ASSERT_TRUE(voxeliseSphere(1, 2.0 / 3, &grid, &why)) << why;
  EXPECT_EQ(grid.count(), 19);
  for (const double radius : {0.0, -1.0, std::nan(""), 2e6}) {
    EXPECT_FALSE(voxeliseSphere(radius, 0.1, &grid, &why));
    EXPECT_NE(why.find("radius"), std::string::npos) << why;
  }
  EXPECT_FALSE(voxeliseSphere(1, 0, &grid, &why));
  EXPECT_FALSE(voxeliseSphere(1.15, 0.01, &grid, &why));
  EXPECT_EQ(why,
            "a ball of radius 1.15 m is 2.3 m across (along x): at voxel size 0.01 m that is 230 "
            "voxels, at most 47; use a voxel of at least 0.049 m");
}

TEST(VoxelPieces, KeepLargestPieceDropsSeparateLumps) {
  VoxelGrid grid;
  grid.nx = 6, grid.ny = 6, grid.nz = 6, grid.size = 0.1;
  grid.filled.assign(216, 0);
  auto set = [&](int i, int j, int k) { grid.filled[(i * 6 + j) * 6 + k] = 1; };
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) set(i, j, k);  // 27
  set(3, 1, 1);                                  // joined through a face: kept
  set(5, 5, 5);                                  // a lump of 2 across the grid
  set(5, 5, 4);
  set(3, 3, 2);  // touching the block's corner edge only (2,2,2)-(3,3,2): a lump of its own
  ASSERT_EQ(grid.count(), 31);
  EXPECT_EQ(keepLargestPiece(&grid), 3);
  EXPECT_EQ(grid.count(), 28);
  EXPECT_TRUE(grid.at(3, 1, 1));
  EXPECT_FALSE(grid.at(5, 5, 5));
  EXPECT_FALSE(grid.at(3, 3, 2));
  EXPECT_EQ(keepLargestPiece(&grid), 0);
  // Two cubes 0.5 m apart, of 27 and 8 voxels: the smaller goes.
  TriangleMesh two = boxMesh({0, 0, 0}, {0.3, 0.3, 0.3});
  const TriangleMesh small = boxMesh({0.8, 0, 0}, {1.0, 0.2, 0.2});
  for (auto t : small.triangles) {
    for (int& index : t) index += static_cast<int>(two.vertices.size());
    two.triangles.push_back(t);
  }
  two.vertices.insert(two.vertices.end(), small.vertices.begin(), small.vertices.end());
  std::string why;
  ASSERT_TRUE(voxeliseMesh(two, 0.1, &grid, &why)) << why;
  EXPECT_EQ(grid.count(), 35);
  EXPECT_EQ(keepLargestPiece(&grid), 8);
  EXPECT_EQ(grid.count(), 27);
  VoxelGrid empty;
  EXPECT_EQ(keepLargestPiece(&empty), 0);
}

TEST(VoxelModel, TheJellyMouldVoxelisesToOneBody) {
  TriangleMesh mesh;
  std::string why;
  ASSERT_TRUE(readObjMesh(modelPath(), &mesh, &why)) << why;
  EXPECT_EQ(mesh.vertices.size(), 866u);
  EXPECT_EQ(mesh.triangles.size(), 1728u);
  VoxelGrid grid;
  ASSERT_TRUE(voxeliseMesh(mesh, 0.1, &grid, &why)) << why;
  EXPECT_EQ(grid.nx, 11);
  EXPECT_EQ(grid.ny, 11);
  EXPECT_EQ(grid.nz, 8);
  EXPECT_EQ(grid.count(), 420);  // its volume is 0.404 m^3: 404 voxels
  EXPECT_EQ(keepLargestPiece(&grid), 0);
  ASSERT_TRUE(voxeliseMesh(mesh, 0.15, &grid, &why)) << why;
  EXPECT_EQ(grid.nx, 8);
  EXPECT_EQ(grid.nz, 6);
  EXPECT_EQ(grid.count(), 132);  // 120 for its volume
  EXPECT_EQ(keepLargestPiece(&grid), 0);
}

TEST_F(VoxelObjFile, ReadsPolygonsRelativeIndicesAndAttributes) {
  // The unit cube as six quads in every index form OBJ has, with CRLF line ends, a normal, a
  // texture coordinate, a material that is not there and groups.
  const std::string text =
      "# a cube\r\nmtllib none.mtl\r\nv 0 0 0\r\nv 1 0 0\r\nv 1 1 0\r\nv 0 1 0\r\n"
      "v 0 0 1\r\nv 1 0 1\r\nv 1 1 1\r\nv 0 1 1\r\nvn 0 0 1\r\nvt 0 0\r\n"
      "g bottom\r\nusemtl jelly\r\nf 1 4 3 2\r\ng top\r\nf 5/1 6/1 7/1 8/1\r\n"
      "o sides\r\nf 1//1 2//1 6//1 5//1\r\nf 2/1/1 3/1/1 7/1/1 6/1/1\r\nf -5 -1 -2 -6\r\n"
      "f 4 1 5 8";
  const std::string path = write(text);
  TriangleMesh mesh;
  std::string why;
  ASSERT_TRUE(readObjMesh(path, &mesh, &why)) << why;
  EXPECT_EQ(mesh.name, path);
  EXPECT_EQ(mesh.vertices.size(), 8u);
  ASSERT_EQ(mesh.triangles.size(), 12u);
  EXPECT_EQ(mesh.vertices[6].z, 1);
  const std::array<int, 3> fan{0, 3, 2};
  EXPECT_EQ(mesh.triangles[0], fan);
  const std::array<int, 3> relative{3, 7, 6};  // -5 -1 -2 of 8 vertices: 4 8 7
  EXPECT_EQ(mesh.triangles[8], relative);
  VoxelGrid grid;
  ASSERT_TRUE(voxeliseMesh(mesh, 0.25, &grid, &why)) << why;
  EXPECT_EQ(grid.count(), 64);
}

TEST_F(VoxelObjFile, ATurnedCubeReadsBackAsWritten) {
  TriangleMesh mesh = boxMesh({-0.4, -0.4, -0.4}, {0.4, 0.4, 0.4});
  for (Vec3& p : mesh.vertices) p = rotate(p, {0, 0.6, 0.8}, 0.3) + Vec3{1, 2, 3};
  TriangleMesh read;
  std::string why;
  ASSERT_TRUE(readObjMesh(write(objText(mesh)), &read, &why)) << why;
  ASSERT_EQ(read.vertices.size(), mesh.vertices.size());
  for (std::size_t n = 0; n < mesh.vertices.size(); ++n)
    EXPECT_NEAR(length(read.vertices[n] - mesh.vertices[n]), 0, 1e-14);
  EXPECT_EQ(read.triangles, mesh.triangles);
}

TEST(VoxelObjText, ParsedFromMemoryAsFromAFile) {
  TriangleMesh mesh;
  std::string why;
  ASSERT_TRUE(parseObjText(objText(boxMesh({0, 0, 0}, {1, 1, 1})), "inline", &mesh, &why)) << why;
  EXPECT_EQ(mesh.name, "inline");
  EXPECT_EQ(mesh.triangles.size(), 12u);
  EXPECT_FALSE(parseObjText("v 0 0 nan\n", "inline", &mesh, &why));
  EXPECT_EQ(why, "inline:1: vertex coordinate 'nan' is not a number");
  EXPECT_FALSE(parseObjText(std::string(kMostObjBytes + 1, '#'), "inline", &mesh, &why));
  EXPECT_EQ(why, "inline: longer than 64 MB");
}

TEST_F(VoxelObjFile, UnreadableFilesAreRefused) {
  TriangleMesh mesh;
  std::string why;
  const std::string missing = dir_ + "/missing.obj";
  EXPECT_FALSE(readObjMesh(missing, &mesh, &why));
  EXPECT_EQ(why, missing + ": cannot open: No such file or directory");
  EXPECT_FALSE(readObjMesh(dir_, &mesh, &why));
  EXPECT_EQ(why, dir_ + ": not a regular file (an OBJ model is read whole)");
  const std::string fifo = dir_ + "/fifo.obj";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_FALSE(readObjMesh(fifo, &mesh, &why));  // at once: no writer is waited for
  EXPECT_EQ(why, fifo + ": not a regular file (an OBJ model is read whole)");
  const std::string large = write("");
  ASSERT_EQ(::truncate(large.c_str(), static_cast<off_t>(kMostObjBytes) + 1), 0);  // sparse
  EXPECT_FALSE(readObjMesh(large, &mesh, &why));
  EXPECT_EQ(why, large + ": larger than 64 MB");  // said before reading it
  // A name with a line break in it still makes one line.
  const std::string odd = write(kTriangle, "two\nlines.obj");
  EXPECT_FALSE(readObjMesh(odd, &mesh, &why));
  expectOneLine(why);
  EXPECT_NE(why.find("two lines.obj"), std::string::npos) << why;
}

TEST_F(VoxelObjFile, FilesWithoutFacesAreRefused) {
  expectRefused("", "no faces of three or more corners (f lines): not a solid model");
  expectRefused("# nothing\n\n", "no faces");
  expectRefused(kTriangle, "no faces");
  expectRefused(std::string(kTriangle) + "l 1 2 3\np 1\nf 1 2\n", "no faces");
}

TEST_F(VoxelObjFile, BadCoordinatesAreRefused) {
  expectRefused("v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n",
                ":2: vertex coordinate 'nan' is not a number");
  expectRefused("v 0 0 inf\n", ":1: vertex coordinate 'inf' is not a number");
  expectRefused("v 0 0x1p3 0\n", "'0x1p3' is not a number");
  expectRefused("v 0 0 1,5\n", "'1,5' is not a number");
  expectRefused("v 0 . 0\n", "'.' is not a number");
  expectRefused("v 1 2\n", ":1: a vertex (v) needs three coordinates");
  expectRefused("\n\nv 1e300 0 0\n", ":3: vertex coordinate 1e300 is beyond 1000000 m");
  expectRefused("v 0 -1e400 0\n", "vertex coordinate -1e400 is beyond");
  expectRefused("v 0 0 1000001\n", "vertex coordinate 1000001 is beyond");
  expectRefused("v 0 0 0\r\rv 0 0 x\n", ":3: vertex coordinate 'x' is not a number");
  // Plain numbers of every shape are read.
  const std::string path =
      write("v +1. -.5 2e-1\nv 1E+2 0.000 -0\nv 1000000 -1000000 .25e1\nf 1 2 3\n");
  TriangleMesh mesh;
  std::string why;
  ASSERT_TRUE(readObjMesh(path, &mesh, &why)) << why;
  EXPECT_DOUBLE_EQ(mesh.vertices[0].y, -0.5);
  EXPECT_DOUBLE_EQ(mesh.vertices[0].z, 0.2);
  EXPECT_DOUBLE_EQ(mesh.vertices[1].x, 100);
  EXPECT_DOUBLE_EQ(mesh.vertices[2].y, -1e6);
  EXPECT_DOUBLE_EQ(mesh.vertices[2].z, 2.5);
}

TEST_F(VoxelObjFile, BadFacesAreRefused) {
  expectRefused(std::string(kTriangle) + "f 1 2 9\n",
                "a face (f) refers to a vertex that is not there (3 vertices)");
  expectRefused(std::string(kTriangle) + "f 1 2 3 4\n", "not there");
  expectRefused(std::string(kTriangle) + "f -1 -2 -4\n", "not there");
  // An index beyond an int wraps in tinyobjloader (2^32 + 8 to vertex 8): refused as written.
  expectRefused(std::string(kTriangle) + "f 1 2 4294967304\n",
                ":4: face index 4294967304 is not a whole number of at most 3000000");
  expectRefused(std::string(kTriangle) + "f 1/4294967297 2 3\n", "face index 4294967297");
  expectRefused(std::string(kTriangle) + "f 1 2 +3\n", "face index +3");
  // In this program's words, with the line (tinyobjloader's own text is not shown).
  expectRefused(std::string(kTriangle) + "f 1 2 0\n",
                ":4: not an OBJ model this program reads (v lines of three numbers, f lines of "
                "vertex numbers from 1, or from -1 backwards)");
  const char nul[] = "v 0 0 0\0v 1 0 0\nv 0 1 0\nf 1 2 3\n";
  expectRefused(std::string(nul, sizeof nul - 1), "holds a NUL byte");
  // One face of 1,000,003 corners is 1,000,001 triangles, one too many.
  std::string many = std::string(kTriangle) + "f";
  for (int n = 0; n < 1000003; ++n) many += n % 2 ? " 2" : " 3";
  expectRefused(many + " 1\n", ":4: more than 1000000 triangles");
}

TEST_F(VoxelObjFile, AModelTooLargeForTheVoxelsNamesTheFile) {
  const std::string path = write(objText(boxMesh({0, 0, 0}, {2.3, 1, 1})), "wide.obj");
  TriangleMesh mesh;
  VoxelGrid grid;
  std::string why;
  ASSERT_TRUE(readObjMesh(path, &mesh, &why)) << why;
  EXPECT_FALSE(voxeliseMesh(mesh, 0.01, &grid, &why));
  EXPECT_EQ(why, path +
                     " is 2.3 m across (along x): at voxel size 0.01 m that is 230 voxels, at "
                     "most 47; use a voxel of at least 0.049 m");
}

}  // namespace
}  // namespace jello
