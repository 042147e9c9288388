// showCube.h: drawing the jello world with legacy fixed-function OpenGL, the one drawing code
// that serves the GLUT window and the offscreen (OSMesa) renderer, so that a headless frame is
// the picture a user would have seen. Needs a current GL context; knows nothing of GLUT.
//
// World units are metres; +z is up. Screen coordinates for text are pixels from the top-left.
#pragma once

#include <string>

#include "graphics/layout.h"
#include "physics.h"

namespace jello {

constexpr double kFieldOfView = 72.0;  // degrees, vertical: the whole box at the default camera

// A camera on a sphere around the origin, looking at it, +z up (README: The viewer).
// theta is the elevation above the xy-plane, phi the azimuth from +x (radians).
struct Camera {
  double radius = 6;
  double theta = kPi / 6;
  double phi = kPi / 6;
  Vec3 eye() const;
};

// How the cube's surface is coloured; `c` in the viewer cycles through them.
enum class Coloring { Plain, Strain, Force };
const char* coloringName(Coloring coloring);

struct DrawOptions {
  bool wireframe = false;
  bool structural = false, shear = false, bend = false;  // springs drawn as lines
  Coloring coloring = Coloring::Plain;
  // The value at the colour legend's end (strain, or newtons for force), held by the viewer's
  // `f`; 0: fitted to each frame's largest value.
  double colourScale = 0;
  int springKinds() const { return int(structural) + int(shear) + int(bend); }
};

// Clears and draws the whole scene into a width x height viewport: the box, the cube's lit,
// smooth-shaded surface (or its wireframe), the springs asked for (over the surface, never
// half-hidden in it), the inclined plane clipped to the box, the legends of the springs and the
// colouring where layoutLegends (layout.h) puts them, and the pull line when a point is pulled.
void drawScene(const Model& model, const State& state, const Camera& camera,
               const DrawOptions& options, int width, int height, const Pull* pull = nullptr);

// The colour legend's end value that drawScene fits to `state` (a round 1, 2 or 5 times a power
// of ten at least its largest value); 0 for Coloring::Plain.
double fittedColourScale(const Model& model, const State& state, Coloring coloring);

// Text in a small built-in bitmap font (upper case, digits, punctuation; lower case is drawn
// as upper case), its top-left corner at pixel (x, y), `scale` pixels per font dot.
// Its width is textWidth (layout.h).
void drawText(const std::string& text, int x, int y, int width, int height, int scale, float r,
              float g, float b);
// A filled rectangle in pixels, blended with what is under it at `alpha` (0 to 1).
void drawPanel(const PixelRect& rect, int width, int height, float r, float g, float b,
               float alpha);

}  // namespace jello
