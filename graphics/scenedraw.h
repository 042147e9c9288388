// graphics/scenedraw.h: what a scene file (docs/scenes.md) adds to the picture: its balls, boxes
// and half-spaces, its pinned points, and its bounding box at its own size, or none; and the
// box and plane clipping that the course's picture uses too. drawPicture (showCube.h) calls them,
// so that the window and the headless frames show the same. The draw functions need a current
// GL context; the geometry is plain arithmetic.
//
// World units are metres; +z is up in a course world.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "solver/physics.h"

namespace jello {

// Half the side of the cube, centred on the origin, that a scene without a bounding box clips
// its planes to: a floor that reaches past the jelly's usual travel, yet stays in the picture.
constexpr double kOpenSceneHalfSize = 3.0;  // m

struct BoxExtent {
  Vec3 lower, upper;  // m
};
using Edge = std::array<Vec3, 2>;

// The 12 edges of the box, each as its two ends: the edges along x, then y, then z.
std::vector<Edge> boxEdges(const BoxExtent& box);
// The polygon where the plane cuts the box whose edges are given: its crossings of the edges, in
// order around their centroid; empty when it does not cut it.
std::vector<Vec3> planeInBox(const Plane& plane, const std::vector<Edge>& edges);

// The bounding box the picture shows: the course's [-2,2]^3, a scene's own box at its size, or
// none for a scene without one.
std::optional<BoxExtent> drawnBox(const Model& model);
// The box planes are clipped to: the drawn box, or for a scene without one a cube of half side
// kOpenSceneHalfSize.
BoxExtent clipBox(const Model& model);

// The scene's balls and boxes, solid and lit (drawn before the jelly: they are opaque).
void drawSolidObstacles(const Model& model);
// The scene's half-spaces, each as the translucent polygon of its plane within `clip` (drawn
// after the jelly, so that the jelly shows through).
void drawHalfSpaces(const Model& model, const std::vector<Edge>& clip);
// A small dark ball at every pinned point.
void drawPinnedPoints(const Model& model, const State& state);

}  // namespace jello
