// tests/jellyscenes.h: the scenes of several jellies the contact and scene tests share.
#pragma once

#include <string>

#include "io/scenereader.h"
#include "model/bodycontact.h"
#include "model/model.h"

namespace jello::test {

inline WorldFile scene(const std::string& text) { return parseScene(text, "test.toml", ""); }

// Two 4x4x4 lattices 0.1 m apart, spacing 0.1 m, meeting head-on at 1 m/s each: no gravity, no
// walls, damping in the springs and the contact. The second jelly's table is on line 16.
inline const char* const kHeadOn = R"(
dt = 0.0002
[bounds]
present = false
[contact]
stiffness = 2000
damping = 0.3
[[jelly]]
shape = "lattice"
size = [4, 4, 4]
spacing = 0.1
offset = [-0.2, 0.0, 0.0]
velocity = [1.0, 0.0, 0.0]
stiffness = 500
damping = 0.3
[[jelly]]
shape = "lattice"
size = [4, 4, 4]
spacing = 0.1
offset = [0.2, 0.03, -0.02]
velocity = [-1.0, 0.0, 0.0]
stiffness = 500
damping = 0.3
)";

// The contact term of a model, or null.
inline const BodyContactTerm* contactTerm(const Model& model) {
  for (const auto& term : model.forces.terms)
    if (auto* contact = dynamic_cast<const BodyContactTerm*>(term.get())) return contact;
  return nullptr;
}

}  // namespace jello::test
