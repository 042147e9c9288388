// The exported surface meshes (--export, app/surface.h, app/export.h): the mesh is a closed,
// consistently wound surface of the right volume, its normals are right on the rest lattice,
// a VTU holds a jelly of elements whole with its stresses, and a headless run writes one readable
// file per frame, numbered like the frames. No GL.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "app/export.h"
#include "app/pictures.h"
#include "io/scenereader.h"
#include "model/body.h"
#include "model/mat3.h"
#include "model/model.h"
#include "solver/simulation.h"
#include "test_support.h"

namespace jello {
namespace {

constexpr int kLast = kLatticeSize - 1;

// Volume enclosed by the surface at `positions` (divergence theorem): the sum over triangles of
// a . (b x c) / 6. Positive when the triangles wind counter-clockwise seen from outside.
double signedVolume(const double* positions) {
  double sixTimes = 0;
  for (const Triangle& t : courseBody().surface)
    sixTimes += dot(load(positions, t[0]), cross(load(positions, t[1]), load(positions, t[2])));
  return sixTimes / 6;
}

bool onSurface(int i, int j, int k) {
  return i == 0 || i == kLast || j == 0 || j == kLast || k == 0 || k == kLast;
}

TEST(Surface, Has296VerticesAnd588TrianglesOnTheBoundaryPoints) {
  const std::vector<int>& points = courseBody().surfacePoints;
  ASSERT_EQ(points.size(), 296u);
  EXPECT_EQ(courseBody().surfacePoints.size(), 296u);
  EXPECT_TRUE(std::is_sorted(points.begin(), points.end()));
  int boundary = 0;
  for (int i = 0; i < kLatticeSize; ++i)
    for (int j = 0; j < kLatticeSize; ++j)
      for (int k = 0; k < kLatticeSize; ++k) {
        const int q = pointIndex(i, j, k);
        const bool listed = std::binary_search(points.begin(), points.end(), q);
        EXPECT_EQ(listed, onSurface(i, j, k)) << latticeLabel(q);
        EXPECT_EQ(courseBody().surfaceVertexOf[q] >= 0, onSurface(i, j, k)) << latticeLabel(q);
        boundary += onSurface(i, j, k);
      }
  EXPECT_EQ(boundary, 296);
  for (std::size_t n = 0; n < points.size(); ++n)
    EXPECT_EQ(courseBody().surfaceVertexOf[points[n]], static_cast<int>(n));

  const std::vector<Triangle>& triangles = courseBody().surface;
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
  for (const Triangle& t : courseBody().surface)
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
  const std::vector<Vec3> normals = surfaceNormals(courseBody(), rest.p());
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
  for (int q : courseBody().surfacePoints)
    EXPECT_NEAR(length(normals[q]), 1, 1e-15) << latticeLabel(q);
}

TEST(Surface, NormalsWeighTheTrianglesByTheirAreas) {
  // The cube stretched to 2 m along x: the triangles of the faces y = 7 and z = 7 have twice the
  // area of those of x = 7, so the corner [7][7][7] leans (1, 2, 2)/3, not (1, 1, 1)/sqrt(3).
  State stretched = test::restLattice();
  for (int q = 0; q < kNumPoints; ++q) stretched.p()[coordIndex(q, 0)] *= 2;
  const Vec3 n = surfaceNormals(courseBody(), stretched.p())[pointIndex(kLast, kLast, kLast)];
  EXPECT_NEAR(n.x, 1.0 / 3, 1e-12);
  EXPECT_NEAR(n.y, 2.0 / 3, 1e-12);
  EXPECT_NEAR(n.z, 2.0 / 3, 1e-12);
  EXPECT_NEAR(signedVolume(stretched.p()), 2.0, 1e-12);
}

// ---- The files ------------------------------------------------------------------------------

struct ParsedObj {
  std::vector<Vec3> v, vn;
  std::vector<std::array<int, 6>> f;  // v//vn pairs, from 1
  int comments = 0, other = 0;
  long long step = -1;  // from the header
};

ParsedObj parseObj(const std::string& text) {
  ParsedObj out;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::string kind;
    words >> kind;
    if (kind == "#") {
      ++out.comments;
      const std::size_t at = line.find(", step ");
      if (at != std::string::npos) out.step = std::atoll(line.c_str() + at + 7);
    } else if (kind == "v" || kind == "vn") {
      Vec3 p;
      words >> p.x >> p.y >> p.z;
      (kind == "v" ? out.v : out.vn).push_back(p);
    } else if (kind == "f") {
      std::array<int, 6> face{};
      char slash;
      for (int corner = 0; corner < 3; ++corner)
        words >> face[2 * corner] >> slash >> slash >> face[2 * corner + 1];
      out.f.push_back(face);
    } else {
      ++out.other;
    }
  }
  return out;
}

// The course cube's model of springs: meshText reads its body (and for VTU, its elements: none).
const Model& courseModel() {
  static const Model model = makeModel(test::springsOnlyWorld(), test::restLattice());
  return model;
}

TEST(MeshText, ObjListsTheSurfaceExactlyWithItsNormalsAndTriangles) {
  const State rest = test::restLattice();
  const ParsedObj obj =
      parseObj(meshText(MeshFormat::Obj, courseModel(), rest, {"a.w", 12, 0.012}));
  ASSERT_EQ(obj.v.size(), 296u);
  ASSERT_EQ(obj.vn.size(), 296u);
  ASSERT_EQ(obj.f.size(), 588u);
  EXPECT_EQ(obj.other, 0);
  EXPECT_EQ(obj.step, 12);
  const std::vector<Vec3> normals = surfaceNormals(courseBody(), rest.p());
  for (std::size_t n = 0; n < 296; ++n) {
    const Vec3 p = load(rest.p(), courseBody().surfacePoints[n]);
    EXPECT_EQ(obj.v[n].x, p.x);  // shortest round-trip digits: the same doubles
    EXPECT_EQ(obj.v[n].y, p.y);
    EXPECT_EQ(obj.v[n].z, p.z);
    EXPECT_EQ(obj.vn[n].z, normals[courseBody().surfacePoints[n]].z);
  }
  for (std::size_t t = 0; t < 588; ++t)
    for (int corner = 0; corner < 3; ++corner) {
      const int vertex = obj.f[t][2 * corner];
      EXPECT_EQ(obj.f[t][2 * corner + 1], vertex) << "vertex a's normal is vn a";
      ASSERT_TRUE(vertex >= 1 && vertex <= 296);
      EXPECT_EQ(courseBody().surfacePoints[vertex - 1], courseBody().surface[t][corner]);
    }
}

TEST(MeshText, PlyHasTheHeaderBlenderAndHoudiniReadAndTheSameMesh) {
  const State rest = test::restLattice();
  const std::string text = meshText(MeshFormat::Ply, courseModel(), rest, {"a.w", 0, 0});
  std::istringstream lines(text);
  std::vector<std::string> header;
  for (std::string line; std::getline(lines, line) && line != "end_header";)
    if (line.rfind("comment ", 0) != 0) header.push_back(line);
  const std::vector<std::string> expected = {"ply",
                                             "format ascii 1.0",
                                             "element vertex 296",
                                             "property double x",
                                             "property double y",
                                             "property double z",
                                             "property double nx",
                                             "property double ny",
                                             "property double nz",
                                             "element face 588",
                                             "property list uchar int vertex_indices"};
  EXPECT_EQ(header, expected);
  for (std::size_t n = 0; n < 296; ++n) {
    Vec3 p, normal;
    lines >> p.x >> p.y >> p.z >> normal.x >> normal.y >> normal.z;
    EXPECT_EQ(p.x, load(rest.p(), courseBody().surfacePoints[n]).x);
    EXPECT_EQ(p.z, load(rest.p(), courseBody().surfacePoints[n]).z);
  }
  for (std::size_t t = 0; t < 588; ++t) {
    int count = 0, a = -1, b = -1, c = -1;
    lines >> count >> a >> b >> c;
    ASSERT_EQ(count, 3);
    EXPECT_EQ(courseBody().surfacePoints[a], courseBody().surface[t][0]);  // PLY counts from 0
    EXPECT_EQ(courseBody().surfacePoints[c], courseBody().surface[t][2]);
    (void)b;
  }
  std::string rest_;
  EXPECT_FALSE(lines >> rest_) << "nothing after the faces: " << rest_;
}

TEST(MeshText, AWorldNamedWithANewlineStaysInItsCommentLine) {
  const State rest = test::restLattice();
  const ParsedObj obj =
      parseObj(meshText(MeshFormat::Obj, courseModel(), rest, {"evil\nv 9 9 9\n.w", 0, 0}));
  EXPECT_EQ(obj.v.size(), 296u);
  EXPECT_EQ(obj.other, 0);
}

TEST(MeshFormat, NamesAreObjPlyOrVtuInAnyCase) {
  MeshFormat format = MeshFormat::Obj;
  EXPECT_TRUE(parseMeshFormat("PLY", &format));
  EXPECT_EQ(format, MeshFormat::Ply);
  EXPECT_TRUE(parseMeshFormat("obj", &format));
  EXPECT_EQ(format, MeshFormat::Obj);
  EXPECT_TRUE(parseMeshFormat("Vtu", &format));
  EXPECT_EQ(format, MeshFormat::Vtu);
  EXPECT_STREQ(meshExtension(format), ".vtu");
  EXPECT_STREQ(meshFormatName(format), "VTU");
  for (const char* bad : {"stl", "", "objx", "ob", ".vtu", "vtk"})
    EXPECT_FALSE(parseMeshFormat(bad, &format));
}

// ---- VTU ------------------------------------------------------------------------------------

// The numbers of the DataArray named `name` in a VTU's text; empty when it has none.
std::vector<double> vtuArray(const std::string& text, const std::string& name) {
  const std::size_t at = text.find("Name=\"" + name + "\"");
  if (at == std::string::npos) return {};
  const std::size_t begin = text.find('>', at) + 1;
  std::istringstream numbers(text.substr(begin, text.find("</DataArray>", begin) - begin));
  std::vector<double> out;
  for (double x; numbers >> x;) out.push_back(x);
  EXPECT_TRUE(numbers.eof()) << name << ": only numbers in a DataArray";
  return out;
}

// The value of the attribute `name` ("NumberOfPoints") in a VTU's text; -1 when it has none.
long long vtuCount(const std::string& text, const std::string& name) {
  const std::size_t at = text.find(" " + name + "=\"");
  return at == std::string::npos ? -1 : std::atoll(text.c_str() + at + name.size() + 3);
}

// A small jelly of elements: 3 x 3 x 3 points, 48 tetrahedra.
WorldFile elementScene() {
  return parseScene(
      "dt = 0.0001\n[bounds]\npresent = false\n[jelly]\nshape = \"lattice\"\nsize = [3, 3, 3]\n"
      "spacing = 0.02\nmaterial = \"neohookean\"\nyoungs_modulus = 1e4\npoisson_ratio = 0.45\n"
      "density = 1000\n",
      "elements.toml", "");
}

// The rest state of `file` stretched along x, sheared and bent a little, each point moving.
State deformed(const Model& model, const State& rest) {
  State out = rest;
  const int n = model.points();
  for (int q = 0; q < n; ++q) {
    const Vec3 p = load(rest.p(), q, n);
    store(out.p(), q, n, {1.1 * p.x + 0.2 * p.z, p.y - 3 * p.x * p.x, 0.95 * p.z});
    store(out.v(), q, n, {0.5 * p.y, -0.25, q * 1e-3});
  }
  return out;
}

TEST(MeshText, VtuOfElementsHoldsEveryPointAndEveryTetrahedron) {
  const WorldFile file = elementScene();
  const Model model = makeModel(file.world, file.state);
  ASSERT_NE(model.forces.elements, nullptr);
  const ElementTerm& elements = *model.forces.elements;
  ASSERT_EQ(elements.elementCount(), 48);
  const State state = deformed(model, file.state);
  const std::string text = meshText(MeshFormat::Vtu, model, state, {"evil--\n-->.w", 7, 0.25});
  EXPECT_EQ(text.rfind("<?xml version=\"1.0\"?>\n", 0), 0u);
  EXPECT_NE(text.find("<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" "
                      "byte_order=\"LittleEndian\">"),
            std::string::npos);
  // The stamp is one comment that the world's name cannot end: one "--", at its start and end.
  const std::size_t open = text.find("<!--"), close = text.find("-->");
  ASSERT_NE(close, std::string::npos);
  EXPECT_EQ(text.find("--", open + 4), close) << text.substr(open, close - open);
  EXPECT_NE(text.find(", step 7, time 0.25 s"), std::string::npos);
  EXPECT_EQ(vtuArray(text, "TimeValue"), std::vector<double>{0.25});

  const int n = model.points();
  EXPECT_EQ(vtuCount(text, "NumberOfPoints"), n);
  EXPECT_EQ(vtuCount(text, "NumberOfCells"), elements.elementCount());
  const std::vector<double> types = vtuArray(text, "types");
  ASSERT_EQ(types.size(), 48u);
  for (double type : types) EXPECT_EQ(type, 10) << "VTK_TETRA";
  const std::vector<double> connectivity = vtuArray(text, "connectivity");
  const std::vector<double> offsets = vtuArray(text, "offsets");
  ASSERT_EQ(connectivity.size(), 4u * 48);
  ASSERT_EQ(offsets.size(), 48u);
  for (int e = 0; e < 48; ++e) {
    EXPECT_EQ(offsets[e], 4 * (e + 1));
    for (int corner = 0; corner < 4; ++corner)
      EXPECT_EQ(connectivity[4 * e + corner], elements.element(e)[corner]);
  }
  // Every point, in point order: positions and velocities exactly.
  const std::vector<double> points = vtuArray(text, "Points");
  const std::vector<double> velocity = vtuArray(text, "velocity");
  ASSERT_EQ(points.size(), 3u * n);
  ASSERT_EQ(velocity.size(), 3u * n);
  for (int q = 0; q < n; ++q) {
    const Vec3 p = load(state.p(), q, n), v = load(state.v(), q, n);
    EXPECT_EQ(points[3 * q], p.x);
    EXPECT_EQ(points[3 * q + 1], p.y);
    EXPECT_EQ(points[3 * q + 2], p.z);
    EXPECT_EQ(velocity[3 * q], v.x);
    EXPECT_EQ(velocity[3 * q + 2], v.z);
  }
}

TEST(MeshText, VtuStressesAreTheElementsVonMisesAndVolumeChangesTheirs) {
  const WorldFile file = elementScene();
  const Model model = makeModel(file.world, file.state);
  const ElementTerm& elements = *model.forces.elements;
  const State state = deformed(model, file.state);
  const std::string text = meshText(MeshFormat::Vtu, model, state, {"a.toml", 0, 0});
  const std::vector<double> stress = vtuArray(text, "von_mises_stress");
  const std::vector<double> change = vtuArray(text, "volume_change");
  ASSERT_EQ(stress.size(), 48u);
  ASSERT_EQ(change.size(), 48u);
  double most = 0;
  for (int e = 0; e < 48; ++e) {
    EXPECT_EQ(stress[e], elements.vonMises(e, state.p())) << e;  // shortest round-trip digits
    EXPECT_EQ(change[e], determinant(elements.deformation(e, state.p())) - 1) << e;
    most = std::max(most, stress[e]);
  }
  EXPECT_GT(most, 100) << "Pa: the deformed jelly is stressed";
  // At rest: no stress, no volume change.
  const std::string rest = meshText(MeshFormat::Vtu, model, file.state, {"a.toml", 0, 0});
  for (double s : vtuArray(rest, "von_mises_stress")) EXPECT_NEAR(s, 0, 1e-6);
  for (double c : vtuArray(rest, "volume_change")) EXPECT_NEAR(c, 0, 1e-12);
}

TEST(MeshText, VtuOfSpringsHoldsTheSurfaceTrianglesAndNoStress) {
  State state = test::restLattice();
  for (int q = 0; q < kNumPoints; ++q) store(state.v(), q, {0, 0, 0.001 * q});
  const std::string text = meshText(MeshFormat::Vtu, courseModel(), state, {"a.w", 0, 0});
  EXPECT_EQ(vtuCount(text, "NumberOfPoints"), 296);
  EXPECT_EQ(vtuCount(text, "NumberOfCells"), 588);
  const std::vector<double> types = vtuArray(text, "types");
  ASSERT_EQ(types.size(), 588u);
  for (double type : types) EXPECT_EQ(type, 5) << "VTK_TRIANGLE";
  const std::vector<double> connectivity = vtuArray(text, "connectivity");
  ASSERT_EQ(connectivity.size(), 3u * 588);
  const Body& body = courseBody();
  for (std::size_t t = 0; t < 588; ++t)
    for (int corner = 0; corner < 3; ++corner)
      EXPECT_EQ(body.surfacePoints[connectivity[3 * t + corner]], body.surface[t][corner]);
  const std::vector<double> velocity = vtuArray(text, "velocity");
  ASSERT_EQ(velocity.size(), 3u * 296);
  for (std::size_t k = 0; k < 296; ++k)
    EXPECT_EQ(velocity[3 * k + 2], load(state.v(), body.surfacePoints[k]).z);
  EXPECT_EQ(text.find("<CellData"), std::string::npos);
  EXPECT_EQ(text.find("von_mises_stress"), std::string::npos);
}

// ---- Through jello --------------------------------------------------------------------------

std::string meshName(int index, const char* extension) {
  char name[32];
  std::snprintf(name, sizeof name, "%04d%s", index, extension);
  return name;
}

// The steps a headless run with --fps saves frames at, for `steps` steps (FrameClock).
std::vector<long long> frameSteps(double fps, double dt, long long steps) {
  const FrameClock clock(fps, 1, dt);
  std::vector<long long> out;
  for (long long s = 0; s <= steps; s = clock.nextAfter(s)) out.push_back(s);
  return out;
}

TEST(CliExport, AHeadlessRunWritesOneMeshPerFrameNumberedLikeTheFrames) {
  const std::string dir = test::makeTempDir(), meshes = dir + "/meshes";
  const std::string world = test::dataPath("rotate.w");
  test::CommandResult r =
      test::runJelloArgs({"--headless", "--export", meshes, "--fps", "30", "--time", "0.1", world});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_NE(r.out.find("; 4 meshes (OBJ) in " + meshes + "/"), std::string::npos) << r.out;
  // 100 steps of 1 ms at 30 a second: steps 0, 34, 67, 100, as --frames saves them.
  const std::vector<long long> steps = frameSteps(30, 0.001, stepsForTime(0.1, 0.001).value());
  ASSERT_EQ(steps, (std::vector<long long>{0, 34, 67, 100}));
  EXPECT_EQ(countMeshes(meshes), 4);
  const WorldFile initial = readWorldFile(world);
  for (int k = 0; k < 4; ++k) {
    const ParsedObj obj = parseObj(test::readText(meshes + "/" + meshName(k, ".obj")));
    EXPECT_EQ(obj.v.size(), 296u) << k;
    EXPECT_EQ(obj.vn.size(), 296u) << k;
    EXPECT_EQ(obj.f.size(), 588u) << k;
    EXPECT_EQ(obj.step, steps[k]) << "mesh " << k << " is the frame of step " << steps[k];
    if (k > 0) continue;
    for (std::size_t n = 0; n < obj.v.size(); ++n) {
      const Vec3 p = load(initial.state.p(), courseBody().surfacePoints[n]);
      EXPECT_EQ(obj.v[n].x, p.x) << n;
      EXPECT_EQ(obj.v[n].y, p.y) << n;
      EXPECT_EQ(obj.v[n].z, p.z) << n;
    }
  }
  EXPECT_FALSE(test::readText(meshes + "/0003.obj") == test::readText(meshes + "/0000.obj"));
  test::removeTree(dir);
}

TEST(CliExport, PlyFilesAndMaxFramesAndTheDefaultLengthFollowTheFrames) {
  const std::string dir = test::makeTempDir(), meshes = dir + "/m";
  const std::string world = test::dataPath("rotate.w");
  test::CommandResult r = test::runJelloArgs({"--headless", "--export", meshes, "--export-format",
                                              "PLY", "--max-frames", "3", "--fps", "50", world});
  ASSERT_EQ(r.status, 0) << r.err;
  // No --steps or --time: as long as --max-frames frames take, 3 at 50 a second.
  EXPECT_NE(r.out.find("steps=40 "), std::string::npos) << r.out;
  EXPECT_EQ(countMeshes(meshes), 3);
  EXPECT_EQ(test::readText(meshes + "/0002.ply").rfind("ply\nformat ascii 1.0\n", 0), 0u);
  r = test::runJelloArgs({"--headless", "--export", meshes, "--overwrite", "--export-format", "vtu",
                          "--max-frames", "2", "--fps", "50", world});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("2 meshes (VTU) in " + meshes + "/"), std::string::npos) << r.out;
  EXPECT_EQ(countMeshes(meshes), 2) << "the PLY files gave way to 0000.vtu and 0001.vtu";
  EXPECT_EQ(vtuCount(test::readText(meshes + "/0001.vtu"), "NumberOfCells"), 588);
  r = test::runJelloArgs(
      {"--headless", "--export", meshes, "--overwrite", "--max-frames", "2", "--time", "1", world});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(countMeshes(meshes), 2) << "--overwrite leaves no stale tail, nor the other format";
  EXPECT_NE(r.err.find(meshes + "/: saving stopped at 2 frames"), std::string::npos) << r.err;
  test::removeTree(dir);
}

TEST(CliExport, BadFormatsAndMisplacedOptionsAreRefusedInOneLine) {
  const std::string world = test::dataPath("rotate.w");
  const std::string dir = test::makeTempDir(), never = dir + "/never";
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--headless", "--export", never, "--export-format", "stl", world},
       "--export-format: unknown format 'stl', expected obj, ply or vtu"},
      {{"--headless", "--export-format", "ply", world}, "--export-format goes with --export"},
      {{"--check", "--export", never, world}, "--export goes with a run"},
      {{"--headless", "--export", "", world}, "--export"},
  };
  for (const auto& [args, says] : cases) {
    test::CommandResult r = test::runJelloArgs(args);
    EXPECT_EQ(r.status, 2) << says;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(says), std::string::npos) << r.err;
    EXPECT_EQ(r.out, "");
  }
  EXPECT_NE(::access(never.c_str(), F_OK), 0) << "nothing was made";
  // --fps goes with --export as with --frames.
  test::CommandResult r = test::runJelloArgs(
      {"--headless", "--export", dir + "/e", "--fps", "10", "--time", "0.2", world});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(countMeshes(dir + "/e"), 3);
  test::removeTree(dir);
}

TEST(CliExport, AFolderHoldingExportedMeshesIsRefusedWithoutOverwrite) {
  const std::string dir = test::makeTempDir(), meshes = dir + "/meshes";
  const std::vector<std::string> args = {
      "--headless", "--export", meshes, "--steps", "10",
      "--fps",      "0",        "--n",  "5",       test::dataPath("rotate.w")};
  ASSERT_EQ(test::runJelloArgs(args).status, 0);
  ASSERT_EQ(countMeshes(meshes), 3);  // steps 0, 5, 10
  test::writeText(meshes + "/0001.obj", "mine\n");
  test::CommandResult again = test::runJelloArgs(args);
  EXPECT_EQ(again.status, 2);
  EXPECT_EQ(std::count(again.err.begin(), again.err.end(), '\n'), 1) << again.err;
  EXPECT_NE(again.err.find(meshes + " already holds 3 exported meshes"), std::string::npos)
      << again.err;
  EXPECT_NE(again.err.find("--overwrite"), std::string::npos) << again.err;
  EXPECT_EQ(again.out, "");
  EXPECT_EQ(test::readText(meshes + "/0001.obj"), "mine\n") << "nothing was replaced";

  std::vector<std::string> overwrite = args;
  overwrite.insert(overwrite.begin(), "--overwrite");
  test::CommandResult replaced = test::runJelloArgs(overwrite);
  EXPECT_EQ(replaced.status, 0) << replaced.err;
  EXPECT_EQ(parseObj(test::readText(meshes + "/0001.obj")).v.size(), 296u);
  test::removeTree(dir);
}

TEST(CliExport, TwoRunsCannotExportIntoOneFolderAtOnce) {
  const std::string dir = test::makeTempDir(), meshes = dir + "/m";
  const std::string world = test::dataPath("still.w");
  // The first run is long (200 meshes 1000 steps apart); the second starts once it has begun.
  const pid_t first = ::fork();
  if (first == 0) {
    ::execl(JELLO_BINARY, JELLO_BINARY, "--headless", "--steps", "200000", "--n", "1000", "--fps",
            "0", "--export", meshes.c_str(), world.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  for (int i = 0; i < 400 && countMeshes(meshes) == 0; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(25));
  const test::CommandResult second =
      test::runJelloArgs({"--headless", "--steps", "10", "--overwrite", "--export", meshes, world});
  ::kill(first, SIGTERM);
  ::waitpid(first, nullptr, 0);
  EXPECT_EQ(second.status, 2) << second.err;
  EXPECT_NE(second.err.find(meshes + ": in use by another run"), std::string::npos) << second.err;
  test::removeTree(dir);
}

}  // namespace
}  // namespace jello
