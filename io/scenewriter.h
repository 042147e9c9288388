// io/scenewriter.h: a setup written back as a scene (the window's "save as"; docs/scenes.md,
// "Saved scenes"): NAME.toml, and beside it NAME.w, the course world it starts from (the springs'
// and contacts' constants, the mass, the field, the plane, the run settings and, for a course
// world, the cube's state), and for a scene NAME.csv, its state file (every point's position and
// velocity). Read back, the three give the same world, run settings and state, bit for bit: every
// number is written in its shortest round-trip form, and what the reader builds (bodies, masses,
// normals) is built from the same keys the first scene gave.
#pragma once

#include <string>

#include "model/world.h"

namespace jello {

// The files of a saved scene: NAME.toml, NAME.w and NAME.csv (none for a course world, whose state
// the .w holds).
struct SavedSceneFiles {
  std::string scene, world, state;
};
// The files for a scene at `scenePath`, which ends in .toml; `hasScene`: the world has a scene
// (a state file is written).
SavedSceneFiles savedSceneFiles(const std::string& scenePath, bool hasScene);

// The scene file's text; it names `files.world` and `files.state` by their names alone (they lie
// beside it) and a mesh by its path from the scene's folder. Throws OutputError when a path cannot
// be written in a TOML string (not UTF-8).
std::string formatScene(const World& world, const RunSettings& run, const SavedSceneFiles& files);

// Writes the files, each whole (core/output.h). Refuses (OutputError, nothing written) a path that
// does not end in .toml, and, without `overwrite`, any of the files that exists; a write that
// fails removes those it made before it (one it replaced stays replaced).
void writeScene(const std::string& scenePath, const World& world, const RunSettings& run,
                const State& state, bool overwrite);

}  // namespace jello
