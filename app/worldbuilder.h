// worldbuilder.h: making world files from a recipe (createWorld), and the course's five worlds
// as presets.
//
// Units: metres, seconds, kilograms, newtons; angles in degrees; angular velocity in rad/s.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/fieldrecipe.h"
#include "io/input.h"
#include "model/vec3.h"
#include "model/world.h"

namespace jello {

// How the initial state is made: the lattice of a cube of edge cubeSize, its corner p[0][0][0]
// at the origin (the course's [0,1]^3) unless centred elsewhere, then rotated about its centre,
// its corner p[7][7][7] displaced, given a velocity and a spin about its centre. With `from`,
// the lattice is replaced by that state and the same steps act on it (about its centroid).
struct StateRecipe {
  std::optional<State> from;
  double cubeSize = 1;           // m
  std::optional<Vec3> center;    // m
  Vec3 rotateDegrees;            // about x, then y, then z
  bool insideOut = false;        // reflected through its centre: every face faces in
  Vec3 skewCorner;               // m, added to p[7][7][7]
  std::optional<Vec3> velocity;  // m/s, every point (with `from`, unset keeps its velocities)
  Vec3 spin;                     // rad/s, rigid rotation about the centre
};

struct Recipe {
  World world;
  RunSettings run;
  FieldRecipe field;
  StateRecipe state;
};

// The defaults of createWorld: the course's springs and mass, RK4 at dt = 1 ms, a cube on
// [0,1]^3 at rest, no plane, no field.
Recipe defaultRecipe();

// The course's worlds as recipes (createWorld --preset NAME), with exact values (1/512 kg,
// positions i/7) where the course files hold six decimals: the table of their names and makers.
struct Preset {
  const char* name;  // jello, rotate, moveLeft, skewedCorner, gravity
  Recipe (*make)();
};
std::vector<Preset> coursePresets();
// "jello, rotate, moveLeft, skewedCorner or gravity".
std::string presetNameList();
// The preset `name`. Throws InputError for an unknown name.
Recipe coursePreset(const std::string& name);

// The initial state of a recipe.
State buildState(const StateRecipe& recipe);

}  // namespace jello
