// model/scenespec.h: what a scene file (docs/scenes.md) adds to a course world: gravity, obstacles
// with friction, pinned points and the bounding box's size. A course world has none of it, and
// its .w format is unchanged; a scene is read once and shared by the world's copies.
//
// Units: metres, seconds, kilograms; gravity in m/s^2.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/limits.h"
#include "model/body.h"
#include "model/material.h"
#include "model/obstacle.h"
#include "model/springs.h"
#include "model/vec3.h"

namespace jello {

// How the scene file gave a jelly's shape (its keys, docs/scenes.md), kept so that the scene can be
// written back (io/scenewriter.h): the body is built from them once, by the reader.
struct JellyRecipe {
  std::string shape;              // "" (the course cube), "lattice", "sphere" or "mesh"
  std::array<int, 3> size{};      // a lattice's points along x, y, z
  double radius = 0;              // a sphere's, m
  std::string mesh;               // a mesh's file (OBJ or TetGen .node), as the reader opened it
  std::optional<double> spacing;  // m, when the file gave one
};

// One jelly of a scene with several ([[jelly]]): its points are body->parts[p]'s in the joined
// body, its mass and springs its own.
struct JellySpec {
  double mass = 0;  // kg a point, > 0 (a jelly of elements: its points' masses are lumped)
  SpringConstants springs;
  bool selfContact = false;  // its surface kept from passing through itself
  Material material;         // springs, or finite elements (model/elements.h)
  JellyRecipe recipe;
};

// Contact between jellies, and of a jelly with itself (model/bodycontact.h): every surface point a
// ball of radius half its body's spacing, or of half `distance` when the scene gives one.
struct BodyContactSpec {
  double distance = 0;  // m, two points' contact distance; 0: the mean of their bodies' spacings
  ContactSpring spring;
  Friction friction;
};

struct SceneSpec {
  // The jelly, when the scene gives its shape ([jelly] shape); null: the course cube.
  std::shared_ptr<const Body> body;
  // The springs' constants by kind, when the scene gives them; none: the world's kElastic and
  // dElastic for every kind.
  std::optional<SpringConstants> springs;
  // Several jellies: one each, body the joined body (Body::parts), pins and the state in its
  // numbering; `springs` unused, the world's mass the first jelly's. Empty for one jelly.
  std::vector<JellySpec> jellies;
  // Whether the one jelly keeps from passing through itself ([jelly] self_contact).
  bool selfContact = false;
  // What the one jelly is made of ([jelly] material), and how its shape was given.
  Material material;
  JellyRecipe recipe;
  // Contact between bodies: there for several jellies or self-contact, else none.
  std::optional<BodyContactSpec> bodyContact;
  Vec3 gravity;                     // m/s^2, on every point, everywhere
  std::vector<Obstacle> obstacles;  // in the order of the file
  // Points that do not move (the body's point numbers), sorted, each once. Their velocities are 0.
  std::vector<int> pinned;
  // The box that holds the jelly: the course's walls of [-2,2]^3 with the world's kCollision and
  // dCollision (nullopt), or a container obstacle of any size, with friction; or none at all.
  bool boundsPresent = true;
  std::optional<Obstacle> bounds;
};

// Whether the course's walls of [-2,2]^3 hold the jelly: a course world (no scene), or a scene
// that neither removes its bounding box nor gives one of its own.
inline bool hasCourseWalls(const SceneSpec* spec) {
  return !spec || (spec->boundsPresent && !spec->bounds);
}

}  // namespace jello
