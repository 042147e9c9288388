// core/limits.h: the limits of the project, named once: what an input may ask for (a world file,
// a scene file, a model, a command line) and what a run may take. Each reader and each command
// line refuses beyond them with one line; docs/world-format.md, docs/scenes.md and the README
// state the same figures.
#pragma once

#include <climits>
#include <cstddef>

namespace jello {

// ---- Worlds ----------------------------------------------------------------------------------

// m: a point further from the origin has diverged (a run stops there); a state file that starts
// a point beyond it is refused.
constexpr double kDivergenceRadius = 100.0;

// The largest field resolution. What a field of R^3 nodes costs is memory (memory.h; a world that
// does not fit is refused before anything is allocated): 24 bytes a node held once by createWorld,
// 80 by a run (the World read, the Model's copy of it and its 32-byte padded nodes). Peak RSS at
// R = 512 (134M nodes; /usr/bin/time -v): createWorld 3.27 GB, a run with --dump 10.7 GB.
constexpr int kMaxResolution = 512;
// The course's field resolution: createWorld's default, a --from world's replaced field, the
// grader's zero field.
constexpr int kCourseResolution = 30;
// n, the steps per drawn frame, in a world file, a scene file or on a command line: 1 to this
// (a 32-bit signed integer, as the course's world files hold it).
constexpr int kMostStepsPerFrame = INT_MAX;

// ---- Scenes and models -----------------------------------------------------------------------

// The most obstacles a scene may have (each is a term the kernel goes through).
constexpr int kMostObstacles = 64;

// A mesh's limits. A coordinate beyond kLargestMeshCoordinate (m) is a mistake (a unit or a
// corrupt file), never a model. The file and triangle caps (and 3 million lines each of `v`,
// `vn` and `vt`) bound the memory a read takes: a sphere of a million triangles (30 MB) is read
// in under 2 s in 150 MB, and the dearest file within the caps (measured: 3 million vertices
// and normals, a million triangles) in 5 s in 380 MB.
constexpr double kLargestMeshCoordinate = 1e6;
constexpr std::size_t kMostMeshTriangles = 1000000;
constexpr std::size_t kMostObjBytes = std::size_t(64) << 20;
// A TetGen mesh's limits (io/tetmesh.h): each of its .node and .ele files at most this long, and
// at most this many tetrahedra (a body's points are kMostScenePoints at most, model/body.h).
constexpr std::size_t kMostTetMeshBytes = std::size_t(256) << 20;
constexpr std::size_t kMostMeshTetrahedra = 2000000;
// The smallest tetrahedron a mesh may hold, m (its longest edge): below it a coordinate's
// rounding is the element's size.
constexpr double kSmallestTetrahedron = 1e-6;
// A material's density (docs/scenes.md, "Finite elements"): one whose points' lumped masses could
// underflow, or beyond any solid's, is a mistake (a unit), never a jelly. (Young's modulus is held
// by every scene number's 1e12.)
constexpr double kSmallestDensity = 1e-3;  // kg/m^3 (air: 1.2)
constexpr double kLargestDensity = 1e5;    // kg/m^3 (osmium: 22,590)

// ---- Runs ------------------------------------------------------------------------------------

// The most steps a run may take. 1e12 steps are months of computing at the kernel's microseconds
// a step, so no run meant to finish asks for more; and up to it a step count, and the time
// s * dt of step s, are exact in a double (2^53 ~ 9e15) and far from long long's limit.
constexpr double kMaxSteps = 1e12;
// The most threads --threads may ask for (a run uses at most one for each kPointsPerThread
// points, solver/physics.h, and at most the cores available by default).
constexpr int kMostThreads = 256;
// The default length of a run: 300 drawn frames of n steps each, or, when frames are saved by
// simulated time (--fps), as long as --max-frames of them take.
constexpr long long kDefaultFrames = 300;
// A default run longer than this (n above 100,000) is refused rather than started: at about
// 100 us an RK4 step it would take most of an hour, which nobody asks for without saying so.
constexpr long long kMostDefaultSteps = 30'000'000;

// ---- Pictures --------------------------------------------------------------------------------

constexpr int kMinPictureSize = 16;  // pixels a side
constexpr int kMaxPictureSize = 8192;
constexpr int kDefaultMaxFrames = 300;
constexpr int kFrameDigits = 4;
constexpr int kMaxFrames = 10000;   // what four digits can number
constexpr double kDefaultFps = 30;  // saved frames per simulated second
constexpr double kMaxFps = 1e6;

}  // namespace jello
