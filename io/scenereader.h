// io/scenereader.h: the scene file reader (TOML, docs/scenes.md). A scene starts from a course
// world (its key `world`, a path relative to the scene file's folder) or from the defaults below,
// and adds gravity, obstacles with friction, pinned points and a bounding box of any size.
//
// Every key is checked: an unknown key, a value of the wrong type and an impossible value are
// refused with one line "FILE:LINE: what (key)", as a malformed world file is.
#pragma once

#include <string>
#include <string_view>

#include "io/input.h"
#include "model/world.h"

namespace jello {

// Whether `path` names a scene file rather than a course world: it ends in ".toml".
bool isSceneFile(const std::string& path);

// The most bytes a scene file may have: far more than any hand-written scene.
constexpr std::size_t kMostSceneBytes = 1 << 20;
// Every number in a scene is at most this in magnitude (m, N/m, kg, ...): with it, no force
// of a scene overflows to infinity, where inf * 0 would make a NaN of a contact's zero axis.
constexpr double kLargestSceneNumber = 1e12;
// A shaped jelly's spacing (its voxels' edge), m.
constexpr double kSmallestSpacing = 1e-3;
constexpr double kLargestSpacing = 10;
// The most nodes per edge of a scene's [field], and the longest expression: the expressions are
// evaluated at every node when the scene is read, and at these caps the dearest (64^3 nodes,
// 1000 characters) is read in 0.43 s (a course world's file holds its field evaluated; 30 nodes).
constexpr int kMostSceneFieldResolution = 64;
constexpr std::size_t kMostFieldExpressionBytes = 1000;

// What a scene without `world` starts from (docs/scenes.md): RK4 at dt 0.5 ms, 10 steps a frame,
// the course's springs and contacts (kElastic 500, dElastic 0.25, kCollision 1000, dCollision 0.25)
// and mass (1/512 kg a point), the cube's rest lattice centred on the origin, at rest; no field, no
// plane.
WorldFile defaultSceneWorld();

// Parses a scene's text; `name` is used in messages, `folder` resolves its `world` key (the
// current folder when empty). Throws InputError.
WorldFile parseScene(std::string_view text, const std::string& name, const std::string& folder);
// Reads and parses a scene file (a regular file). Throws InputError.
WorldFile readSceneFile(const std::string& path);

}  // namespace jello
