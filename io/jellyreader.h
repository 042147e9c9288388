// io/jellyreader.h: a scene's jellies (docs/scenes.md): one [jelly] table, or several [[jelly]]
// tables joined into one body (model/body.h joinBodies), and the checks of where they start.
// Part of the scene reader (scenereader.cpp); refusals are its "FILE:LINE: what (key)".
#pragma once

#include <toml++/toml.h>

#include "io/input.h"
#include "io/scenereader.h"
#include "io/scenetable.h"
#include "model/scenespec.h"

namespace jello {

// Reads [jelly] or [[jelly]] into the file's world, state and scene (the body, each jelly's mass,
// springs and self-contact; the world's mass and springs for one jelly).
void readJelly(const Reader& r, const toml::table& root, WorldFile* file, SceneSpec* spec);

// Several jellies, once the scene's box and contact are known: refused when there are more points
// than kMostScenePoints, when a jelly starts outside the box that holds them, or when two start
// closer than their contact distance (overlapping, or one inside the other).
void checkJellies(const Reader& r, const toml::table& root, const WorldFile& file,
                  const SceneSpec& spec);

}  // namespace jello
