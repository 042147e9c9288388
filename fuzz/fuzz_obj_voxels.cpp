// libFuzzer target: an OBJ file's text read (io/voxels.h) and, when accepted, made into
// voxels at a size the input picks and cut to its largest piece. Aborts unless a refusal is one
// line naming the file, an accepted mesh keeps the reader's promises (triangles, indices in
// range, finite coordinates within kLargestMeshCoordinate), and a grid holds 1 to 47 voxels an
// axis with at least one filled, before and after the cut.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "io/voxels.h"

namespace {

void require(bool condition, const char* what) {
  if (condition) return;
  std::fprintf(stderr, "fuzz_obj_voxels: %s\n", what);
  std::abort();
}

void requireRefusal(const std::string& why) {
  require(why.rfind("fuzz.obj", 0) == 0 || why.rfind("the voxel size", 0) == 0,
          "a refusal names the file");
  for (const char c : why)
    require(static_cast<unsigned char>(c) >= 0x20 && c != 0x7f, "a refusal is one line");
}

// The widest extent of the mesh's triangles (m).
double widestExtent(const jello::TriangleMesh& mesh) {
  jello::Vec3 lo = mesh.vertices[mesh.triangles[0][0]], hi = lo;
  for (const auto& t : mesh.triangles)
    for (const int index : t) {
      require(index >= 0 && index < static_cast<int>(mesh.vertices.size()), "index in range");
      const jello::Vec3 p = mesh.vertices[index];
      require(std::fabs(p.x) <= jello::kLargestMeshCoordinate &&
                  std::fabs(p.y) <= jello::kLargestMeshCoordinate &&
                  std::fabs(p.z) <= jello::kLargestMeshCoordinate,
              "coordinates finite and in range");
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
  return std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
}

void requireGrid(const jello::VoxelGrid& grid) {
  for (const int n : {grid.nx, grid.ny, grid.nz})
    require(n >= 1 && n <= jello::kMostBodyPoints - 1, "1 to 47 voxels an axis");
  require(grid.filled.size() == static_cast<std::size_t>(grid.nx) * grid.ny * grid.nz,
          "one value a voxel");
  require(grid.count() > 0, "a voxel filled");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  jello::TriangleMesh mesh;
  std::string why;
  if (!jello::parseObjText(std::string(data, data + size), "fuzz.obj", &mesh, &why)) {
    requireRefusal(why);
    return 0;
  }
  require(!mesh.triangles.empty(), "an accepted mesh has triangles");
  // 1 to 60 voxels across the widest axis: above 47 the size is refused.
  const double extent = widestExtent(mesh);
  const double voxel = extent > 0 ? extent / (1 + size % 60) : 1.0;
  jello::VoxelGrid grid;
  if (!jello::voxeliseMesh(mesh, voxel, &grid, &why)) {
    requireRefusal(why);
    return 0;
  }
  requireGrid(grid);
  const int before = grid.count();
  const int dropped = jello::keepLargestPiece(&grid);
  requireGrid(grid);
  require(grid.count() + dropped == before, "the cut drops what it says");
  return 0;
}
