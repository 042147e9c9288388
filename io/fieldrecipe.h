// io/fieldrecipe.h: a force field (world.h's ForceField, N at each node) made from a
// recipe: uniform, a swirl, a radial field, "fx; fy; fz" expressions (muparser), or given.
// createWorld's field options and a scene's [field] table both build through it.
#pragma once

#include <stdexcept>
#include <string>

#include "io/inputerror.h"
#include "model/vec3.h"
#include "model/world.h"

namespace jello {

// How the force field is made. Node positions are those of docs/world-format.md.
struct FieldRecipe {
  enum class Source { None, Uniform, Swirl, Radial, Expression, Given };
  Source source = Source::None;
  int resolution = kCourseResolution;  // the course's
  Vec3 uniform;                        // N, Uniform
  double strength = 0;                 // N/m: Swirl F = s (-y, x, 0), Radial F = s (x, y, z)
  std::string expression;              // Expression: "fx; fy; fz" in x, y, z (muparser syntax)
  std::string label = "--field-expr";  // what the expression's errors begin with ("" nothing)
  ForceField given;  // Given: this field as it is (e.g. copied from another world)
};

// The field of a recipe. Throws InputError (a bad expression: what is wrong with it, in muparser's
// words after ours).
ForceField buildField(const FieldRecipe& recipe);

}  // namespace jello
