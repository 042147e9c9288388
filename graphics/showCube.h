// showCube.h: drawing the jello world with legacy fixed-function OpenGL, the one drawing code
// that serves the GLUT window and the offscreen (OSMesa) renderer, so that a headless frame is
// the picture a user would have seen. Needs a current GL context; knows nothing of GLUT.
//
// World units are metres; +z is up. Screen coordinates for text are pixels from the top-left.
#pragma once

#include <array>
#include <string>

#include "app/pictures.h"
#include "graphics/layout.h"
#include "solver/physics.h"

namespace jello {

constexpr double kFieldOfView = 72.0;  // degrees, vertical: the whole box at the default camera

// A camera on a sphere around the origin, looking at it, `up` up (README: The viewer): +z, or
// against a scene's gravity. theta is the elevation above the plane normal to `up`, phi the
// azimuth in it from horizontalAxis(0) (radians); with up +z, from +x in the xy-plane.
struct Camera {
  double radius = 6;
  double theta = kPi / 6;
  double phi = kPi / 6;
  Vec3 up{0, 0, 1};  // a unit vector
  Vec3 eye() const;
  // The unit vectors of the plane normal to `up` that phi is measured in: 0 is the azimuth's
  // zero (+x projected on the plane, or +y when up is near x), 1 a quarter turn on (+y for +z up).
  Vec3 horizontalAxis(int which) const;
  // Horizontal unit vectors (normal to `up`): away from the camera, and to its right, as seen.
  Vec3 away() const;
  Vec3 right() const;
};
// The camera a world's pictures start with (and the window's `e` goes back to): the default one,
// with `up` against the scene's gravity (a slope made by tilting gravity is seen as a slope), for
// a bounding box larger than the course's far enough back to see it whole (up to
// kMaxCameraDistance); then placed where `request` (--camera) says, when there is one.
Camera cameraFor(const Model& model, const std::optional<CameraRequest>& request = std::nullopt);

// How the cube's surface is coloured; `c` in the viewer cycles through them (Stress only for a
// model with elements). Strain: at a point of springs the mean relative stretch of its springs; at
// a point of elements the mean over its tetrahedra of each one's principal strain of the largest
// magnitude (a signed singular value of its deformation, less 1); blue compressed, red stretched.
// Force: the magnitude of the force on each point, N. Stress: the mean von Mises stress of each
// point's tetrahedra, Pa (0 at a point of none). Friction: each point in contact with a frictional
// obstacle, sticking or sliding (analysis/contacts.h).
enum class Colouring { Plain, Strain, Force, Stress, Friction };
constexpr int kColouringKinds = 5;
const char* colouringName(Colouring colouring);

struct DrawOptions {
  bool wireframe = false;
  bool structural = false, shear = false, bend = false;  // springs drawn as lines
  Colouring colouring = Colouring::Plain;
  // The value at the colour legend's end (strain, newtons for force, Pa for stress), held by the
  // viewer's `f`; 0: fitted to each frame's largest value.
  double colourScale = 0;
  // The key light's direction in the camera's frame (x right, y up, z toward the viewer): from the
  // upper left, in front. The panel turns it.
  std::array<float, 3> light{-0.4f, 0.6f, 1.0f};
  int springKinds() const { return int(structural) + int(shear) + int(bend); }
};

// Clears and draws the whole scene into a width x height viewport: the box, the cube's lit,
// smooth-shaded surface (or its wireframe), the springs asked for (over the surface, never
// half-hidden in it), the inclined plane clipped to the box, the legends of the springs and the
// colouring where layoutLegends (layout.h) puts them, and the pull line when a point is pulled.
void drawPicture(const Model& model, const State& state, const Camera& camera,
                 const DrawOptions& options, int width, int height, const Pull* pull = nullptr);

// The colour legend's end value that drawPicture fits to `state` (a round 1, 2 or 5 times a power
// of ten at least its largest value); 0 for Colouring::Plain and Colouring::Friction (no scale).
double fittedColourScale(const Model& model, const State& state, Colouring colouring);

// Text in a small built-in bitmap font (upper case, digits, punctuation; lower case is drawn
// as upper case), its top-left corner at pixel (x, y), `scale` pixels per font dot.
// Its width is textWidth (layout.h).
void drawText(const std::string& text, int x, int y, int width, int height, int scale, float r,
              float g, float b);
// A filled rectangle in pixels, blended with what is under it at `alpha` (0 to 1).
void drawPanel(const PixelRect& rect, int width, int height, float r, float g, float b,
               float alpha);

}  // namespace jello
