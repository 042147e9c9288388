// io/statefile.h: a state file: every body's points, positions and velocities, in CSV
// (docs/scenes.md, "State files"). `jello --save-state FILE` writes one at the end of a run; a
// scene's `state = "FILE"` starts from one, and the run goes on bit for bit as the saved one would
// have: the numbers are the shortest that read back exactly.
//
//   body,index,x,y,z,vx,vy,vz
//   1,0,-0.5,-0.5,-0.5,0,0,0
//   ...
//
// body: the jelly, from 1 (a scene's [[jelly]] order; 1 for one jelly); index: the point in its
// jelly, from 0 (body.h numbering). Every point once, in that order. Units: m and m/s.
#pragma once

#include <cstddef>
#include <string>

#include "model/body.h"
#include "model/world.h"

namespace jello {

// The most bytes a state file may have: the most points a scene may hold, about 200 bytes each.
constexpr std::size_t kMostStateBytes = std::size_t(256) << 20;

// The file's text for the body's state.
std::string formatState(const Body& body, const State& state);
// Writes it whole to `path` (core/output.h; a file there is replaced: the option names it).
// Throws OutputError.
void writeStateFile(const std::string& path, const Body& body, const State& state);
// Reads a state of `body`. Throws InputError "FILE:LINE: what (field)".
State readStateFile(const std::string& path, const Body& body);
// The same from text; `name` for the messages.
State parseState(const std::string& text, const std::string& name, const Body& body);

}  // namespace jello
