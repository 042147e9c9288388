// showCube.cpp: the drawing code shared by the window and the offscreen renderer.
//
// Every call sets all the GL state it relies on, so that a frame does not depend on what was
// drawn before it, nor on which of the two contexts draws it.

#include "graphics/showCube.h"

#include <GL/gl.h>
#include <GL/glu.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "analysis/contacts.h"
#include "graphics/pixels.h"
#include "graphics/scenedraw.h"
#include "model/elements.h"
#include "model/mat3.h"
#include "model/scenespec.h"

namespace jello {

namespace {

constexpr float kBackground[3] = {0.5f, 0.5f, 0.5f};
constexpr float kJelly[3] = {0.86f, 0.18f, 0.24f};
// The plain colouring of a scene's jellies, in turn (the first is the course's jelly red).
constexpr float kJellies[6][3] = {{0.86f, 0.18f, 0.24f}, {0.2f, 0.62f, 0.25f}, {0.95f, 0.62f, 0.1f},
                                  {0.2f, 0.42f, 0.85f},  {0.62f, 0.3f, 0.75f}, {0.1f, 0.7f, 0.7f}};
constexpr double kNear = 0.05, kFar = 100.0;

// The spring kinds' line colours, shown by their legend too.
constexpr float kStructuralColour[3] = {0.2f, 0.9f, 0.95f};
constexpr float kShearColour[3] = {0.95f, 0.85f, 0.2f};
constexpr float kBendColour[3] = {0.85f, 0.3f, 0.9f};
// Pushes the filled surface this far back in depth (glPolygonOffset's factor and units), so that
// spring lines lying on it are drawn over it instead of flickering in and out of it.
constexpr float kSurfaceOffsetFactor = 1.0f, kSurfaceOffsetUnits = 1.0f;

void vertex(Vec3 p) { glVertex3d(p.x, p.y, p.z); }

// 1, 2 or 5 times a power of ten, at least x: a legend scale that does not flicker with every
// small change of the largest value.
double niceCeiling(double x) {
  if (!(x > 0)) return 1;
  double decade = std::pow(10.0, std::floor(std::log10(x)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * decade >= x * (1 - 1e-12)) return m * decade;
  return 10 * decade;
}

Vec3 lerp(Vec3 a, Vec3 b, double t) { return a + t * (b - a); }

// Diverging map for strain in [-1, 1]: blue (compressed), white, red (stretched).
Vec3 divergingColour(double t) {
  t = std::clamp(t, -1.0, 1.0);
  const Vec3 blue{0.15, 0.3, 0.9}, white{0.95, 0.95, 0.95}, red{0.9, 0.12, 0.1};
  return t < 0 ? lerp(white, blue, -t) : lerp(white, red, t);
}

// Sequential map for a magnitude in [0, 1]: dark blue, cyan, yellow, red.
Vec3 sequentialColour(double t) {
  t = std::clamp(t, 0.0, 1.0);
  const Vec3 stops[] = {{0.1, 0.1, 0.5}, {0.1, 0.75, 0.85}, {0.95, 0.9, 0.2}, {0.85, 0.1, 0.1}};
  double x = t * 3;
  int i = std::min(2, static_cast<int>(x));
  return lerp(stops[i], stops[i + 1], x - i);
}

struct SurfaceColours {
  std::vector<Vec3> color;  // per point
  double scale = 1;         // the value at the end of the legend
  const char* title = "";
  bool diverging = false;
  bool frictionStates = false;  // a swatch per state in the legend, no colour bar
};

// The friction colouring's colours, by FrictionState: out of frictional contact a faded jelly,
// so that the green of sticking and the orange of sliding stand out; and the legend's words.
constexpr float kFrictionColours[3][3] = {
    {0.8f, 0.62f, 0.64f}, {0.15f, 0.72f, 0.25f}, {1.0f, 0.55f, 0.05f}};
constexpr const char* kFrictionLabels[3] = {"NONE", "STICKS", "SLIDES"};

Vec3 frictionColour(FrictionState state) {
  const float* c = kFrictionColours[static_cast<int>(state)];
  return {c[0], c[1], c[2]};
}

// The coloured quantity at every point: strain (relative stretch, signed), force (N) or stress
// (von Mises, Pa).
struct SurfaceValues {
  std::vector<double> value;
  double largest = 0;  // of the magnitudes
};

// The element's principal strain of the largest magnitude, signed (negative compressed): its
// deformation's signed singular value farthest from 1, less 1.
double principalStrain(const ElementTerm& elements, int e, const double* p) {
  const Vec3 s = polarDecomposition(elements.deformation(e, p)).singular;
  double strain = 0;
  for (double stretch : {s.x, s.y, s.z})
    if (std::fabs(stretch - 1) > std::fabs(strain)) strain = stretch - 1;
  return strain;
}

// Each point's mean of `elementValue(e)` over the elements it is a corner of; `value` left as it
// is at a point of no element.
template <typename ElementValue>
void meanOverElements(const ElementTerm& elements, ElementValue elementValue,
                      std::vector<double>* value) {
  std::vector<double> sum(value->size(), 0.0);
  std::vector<int> count(value->size(), 0);
  for (int e = 0; e < elements.elementCount(); ++e) {
    const double x = elementValue(e);
    for (int q : elements.element(e)) {
      sum[q] += x;
      ++count[q];
    }
  }
  for (std::size_t q = 0; q < value->size(); ++q)
    if (count[q] > 0) (*value)[q] = sum[q] / count[q];
}

// Strain at each point: the mean relative stretch of the springs meeting there; at a point of no
// spring, the mean of its elements' principalStrain; 0 at a point of neither.
void strainValues(const Model& model, const State& state, std::vector<double>* value) {
  const int n = model.points();
  if (const ElementTerm* elements = model.forces.elements)
    meanOverElements(
        *elements, [&](int e) { return principalStrain(*elements, e, state.p()); }, value);
  std::vector<double> sum(n, 0.0);
  std::vector<int> count(n, 0);
  for (const Spring& s : model.springs()) {
    double strain = (length(load(state.p(), s.a, n) - load(state.p(), s.b, n)) - s.rest) / s.rest;
    sum[s.a] += strain;
    sum[s.b] += strain;
    ++count[s.a];
    ++count[s.b];
  }
  for (int q = 0; q < n; ++q)
    if (count[q] > 0) (*value)[q] = sum[q] / count[q];
}

SurfaceValues valuesFor(const Model& model, const State& state, Colouring colouring) {
  SurfaceValues out;
  std::vector<double>& value = out.value;
  const int n = model.points();
  value.assign(n, 0.0);
  if (colouring == Colouring::Strain) {
    strainValues(model, state, &value);
  } else if (colouring == Colouring::Force) {
    std::vector<double> force(3 * n);
    computeForces(model, state.p(), state.v(), force.data());
    for (int q = 0; q < n; ++q) value[q] = length(load(force.data(), q, n));
  } else if (colouring == Colouring::Stress) {
    // The mean von Mises stress of each point's elements (0 at a point of none).
    if (const ElementTerm* elements = model.forces.elements)
      meanOverElements(
          *elements, [&](int e) { return elements->vonMises(e, state.p()); }, &value);
  }
  for (int q = 0; q < n; ++q) out.largest = std::max(out.largest, std::fabs(value[q]));
  return out;
}

// The smallest legend scale: a cube at rest still gets a legend that means something (a strain of
// 1e-3, a force of 1e-6 N, a stress of 1 Pa).
double smallestScale(Colouring colouring) {
  switch (colouring) {
    case Colouring::Strain:
      return 1e-3;
    case Colouring::Stress:
      return 1;
    default:
      return 1e-6;
  }
}

// The colour legend's title.
const char* legendTitle(Colouring colouring) {
  switch (colouring) {
    case Colouring::Strain:
      return "STRAIN";
    case Colouring::Stress:
      return "STRESS PA";
    default:
      return "FORCE N";
  }
}

// `heldScale` > 0 is the legend's end value; 0 fits it to this state.
SurfaceColours coloursFor(const Model& model, const State& state, Colouring colouring,
                          double heldScale) {
  SurfaceColours out;
  const int n = model.points();
  out.color.assign(n, Vec3{kJelly[0], kJelly[1], kJelly[2]});
  if (colouring == Colouring::Plain) {
    const Body& body = model.body();
    if (body.joined())
      for (int q = 0; q < n; ++q) {
        const float* c = kJellies[body.partOf(q) % 6];
        out.color[q] = {c[0], c[1], c[2]};
      }
    return out;
  }
  if (colouring == Colouring::Friction) {
    out.frictionStates = true;
    out.title = "FRICTION";
    const std::vector<FrictionState> states = frictionStates(model, state);
    for (int q = 0; q < n; ++q) out.color[q] = frictionColour(states[q]);
    return out;
  }
  const SurfaceValues values = valuesFor(model, state, colouring);
  out.scale =
      heldScale > 0 ? heldScale : niceCeiling(std::max(values.largest, smallestScale(colouring)));
  out.diverging = colouring == Colouring::Strain;
  out.title = legendTitle(colouring);
  for (int q = 0; q < n; ++q) {
    const double t = values.value[q] / out.scale;
    out.color[q] = out.diverging ? divergingColour(t) : sequentialColour(t);
  }
  return out;
}

void setUpCamera(const Camera& camera, const DrawOptions& options, int width, int height) {
  glViewport(0, 0, width, height);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(kFieldOfView, static_cast<double>(width) / std::max(1, height), kNear, kFar);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  // Lights are placed in eye coordinates, so the lighting follows the camera.
  const GLfloat key[] = {options.light[0], options.light[1], options.light[2], 0.0f},
                fill[] = {0.6f, -0.2f, 0.6f, 0.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, key);
  glLightfv(GL_LIGHT1, GL_POSITION, fill);
  Vec3 eye = camera.eye();
  gluLookAt(eye.x, eye.y, eye.z, 0, 0, 0, camera.up.x, camera.up.y, camera.up.z);
}

void setUpLighting() {
  const GLfloat keyDiffuse[] = {0.85f, 0.85f, 0.85f, 1}, fillDiffuse[] = {0.3f, 0.3f, 0.35f, 1};
  const GLfloat specular[] = {0.5f, 0.5f, 0.5f, 1}, ambient[] = {0.25f, 0.25f, 0.25f, 1};
  glLightfv(GL_LIGHT0, GL_DIFFUSE, keyDiffuse);
  glLightfv(GL_LIGHT0, GL_SPECULAR, specular);
  glLightfv(GL_LIGHT1, GL_DIFFUSE, fillDiffuse);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  glEnable(GL_LIGHT0);
  glEnable(GL_LIGHT1);
  glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
  glEnable(GL_COLOR_MATERIAL);
  const GLfloat shine[] = {0.3f, 0.3f, 0.3f, 1};
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, shine);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 40);
}

void drawBox(const std::vector<Edge>& edges) {
  glDisable(GL_LIGHTING);
  glColor3f(0.92f, 0.92f, 0.92f);
  glLineWidth(1.5f);
  glBegin(GL_LINES);
  for (const auto& [from, to] : edges) {
    vertex(from);
    vertex(to);
  }
  glEnd();
}

void drawSurface(const Body& body, const State& state, const SurfaceColours& colors,
                 bool wireframe) {
  // The body's surface mesh (body.h: no GL, so that what is drawn can also be written as files).
  const std::vector<Triangle>& triangles = body.surface;
  const std::vector<Vec3> normal = surfaceNormals(body, state.p());
  const int n = body.count();
  glEnable(GL_LIGHTING);
  glShadeModel(GL_SMOOTH);
  glPolygonMode(GL_FRONT_AND_BACK, wireframe ? GL_LINE : GL_FILL);
  glLineWidth(1.0f);
  glPolygonOffset(kSurfaceOffsetFactor, kSurfaceOffsetUnits);
  if (!wireframe) glEnable(GL_POLYGON_OFFSET_FILL);
  glBegin(GL_TRIANGLES);
  for (const auto& t : triangles)
    for (int q : t) {
      glColor3d(colors.color[q].x, colors.color[q].y, colors.color[q].z);
      glNormal3d(normal[q].x, normal[q].y, normal[q].z);
      vertex(load(state.p(), q, n));
    }
  glEnd();
  glDisable(GL_POLYGON_OFFSET_FILL);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
}

const float* springColour(SpringKind kind) {
  switch (kind) {
    case SpringKind::Structural:
      return kStructuralColour;
    case SpringKind::Shear:
      return kShearColour;
    case SpringKind::Bend:
      return kBendColour;
  }
  return kStructuralColour;  // not reached: every kind is named above
}

// The kinds drawn, in the legend's order.
std::vector<SpringKind> springKindsShown(const DrawOptions& options) {
  std::vector<SpringKind> kinds;
  if (options.structural) kinds.push_back(SpringKind::Structural);
  if (options.shear) kinds.push_back(SpringKind::Shear);
  if (options.bend) kinds.push_back(SpringKind::Bend);
  return kinds;
}

void drawSprings(const Model& model, const State& state, const DrawOptions& options) {
  if (!options.structural && !options.shear && !options.bend) return;
  glDisable(GL_LIGHTING);
  glLineWidth(1.0f);
  glBegin(GL_LINES);
  const int n = model.points();
  for (const Spring& s : model.springs()) {
    bool shown = (s.kind == SpringKind::Structural && options.structural) ||
                 (s.kind == SpringKind::Shear && options.shear) ||
                 (s.kind == SpringKind::Bend && options.bend);
    if (!shown) continue;
    glColor3fv(springColour(s.kind));
    vertex(load(state.p(), s.a, n));
    vertex(load(state.p(), s.b, n));
  }
  glEnd();
}

void drawPlane(const Plane& plane, const std::vector<Edge>& clip) {
  std::vector<Vec3> polygon = planeInBox(plane, clip);
  if (polygon.empty()) return;
  glDisable(GL_LIGHTING);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDepthMask(GL_FALSE);
  glColor4f(0.3f, 0.55f, 0.95f, 0.35f);
  glBegin(GL_POLYGON);
  for (Vec3 p : polygon) vertex(p);
  glEnd();
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  glColor3f(0.25f, 0.45f, 0.85f);
  glBegin(GL_LINE_LOOP);
  for (Vec3 p : polygon) vertex(p);
  glEnd();
}

void drawPull(const State& state, const Pull& pull) {
  const int n = state.points();
  glDisable(GL_LIGHTING);
  glDisable(GL_DEPTH_TEST);
  glColor3f(1.0f, 1.0f, 0.3f);
  glLineWidth(2.0f);
  glBegin(GL_LINES);
  vertex(load(state.p(), pull.point, n));
  vertex(pull.target);
  glEnd();
  glEnable(GL_DEPTH_TEST);
}

std::string formatValue(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

// The friction colouring's legend: its title, then a swatch of each state's colour, one a line,
// in the bar's column with its word beside it; at the bottom of the legend's place, where the
// other colourings' legends end.
void drawFrictionLegend(const SurfaceColours& colors, const LegendLayout& legend, int width,
                        int height) {
  const int scale = legend.scale, glyph = kGlyphHeight * scale, line = kLineAdvance * scale;
  const FrictionState order[] = {FrictionState::Sticking, FrictionState::Sliding,
                                 FrictionState::None};
  int y = std::max(legend.bar.y, legend.bar.bottom() - 3 * line);
  drawText(colors.title, legend.colours.x, y - line, width, height, scale, 1, 1, 1);
  for (FrictionState state : order) {
    const float* c = kFrictionColours[static_cast<int>(state)];
    drawPanel({legend.bar.x, y, legend.bar.width, glyph}, width, height, c[0], c[1], c[2], 1);
    drawText(kFrictionLabels[static_cast<int>(state)], legend.barLabelX, y, width, height, scale, 1,
             1, 1);
    y += line;
  }
}

void drawLegend(const SurfaceColours& colors, const LegendLayout& legend, int width, int height) {
  if (colors.frictionStates) {
    drawFrictionLegend(colors, legend, width, height);
    return;
  }
  const PixelRect& bar = legend.bar;
  const int scale = legend.scale, glyph = kGlyphHeight * scale;
  beginPixels(width, height);
  glBegin(GL_QUADS);
  const int steps = 32;
  for (int i = 0; i < steps; ++i) {
    double t0 = 1 - double(i) / steps, t1 = 1 - double(i + 1) / steps;  // top is the largest
    Vec3 c0 = colors.diverging ? divergingColour(2 * t0 - 1) : sequentialColour(t0);
    Vec3 c1 = colors.diverging ? divergingColour(2 * t1 - 1) : sequentialColour(t1);
    double y0 = bar.y + bar.height * double(i) / steps;
    double y1 = bar.y + bar.height * double(i + 1) / steps;
    glColor3d(c0.x, c0.y, c0.z);
    glVertex2d(bar.x, y0);
    glVertex2d(bar.right(), y0);
    glColor3d(c1.x, c1.y, c1.z);
    glVertex2d(bar.right(), y1);
    glVertex2d(bar.x, y1);
  }
  glEnd();
  endPixels();
  std::string top = (colors.diverging ? "+" : "") + formatValue(colors.scale);
  std::string bottom = colors.diverging ? "-" + formatValue(colors.scale) : "0";
  drawText(colors.title, legend.colours.x, legend.colours.y, width, height, scale, 1, 1, 1);
  drawText(top, legend.barLabelX, bar.y, width, height, scale, 1, 1, 1);
  drawText(bottom, legend.barLabelX, bar.bottom() - glyph - scale, width, height, scale, 1, 1, 1);
}

// A swatch of each kind's line colour and its name.
void drawSpringLegend(const DrawOptions& options, const LegendLayout& legend, int width,
                      int height) {
  const int scale = legend.scale, line = kLineAdvance * scale, glyph = kGlyphHeight * scale;
  int y = legend.springs.y;
  for (SpringKind kind : springKindsShown(options)) {
    const float* c = springColour(kind);
    drawPanel({legend.springs.x, y + glyph / 2 - scale,
               legend.springLabelX - legend.springs.x - 2 * scale, 2 * scale},
              width, height, c[0], c[1], c[2], 1);
    const char* name = kind == SpringKind::Structural ? "STRUCTURAL"
                       : kind == SpringKind::Shear    ? "SHEAR"
                                                      : "BEND";
    drawText(name, legend.springLabelX, y, width, height, scale, c[0], c[1], c[2]);
    y += line;
  }
}

}  // namespace

const char* colouringName(Colouring colouring) {
  static_assert(kColouringKinds == kColouringCount, "a name for every colouring (app/pictures.h)");
  return kColouringNames[static_cast<int>(colouring)];
}

void drawPicture(const Model& model, const State& state, const Camera& camera,
                 const DrawOptions& options, int width, int height, const Pull* pull) {
  glClearColor(kBackground[0], kBackground[1], kBackground[2], 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDisable(GL_CULL_FACE);
  glEnable(GL_NORMALIZE);
  setUpLighting();
  setUpCamera(camera, options, width, height);

  // A course world draws what it always drew, the same way: a scene's additions draw nothing
  // for it.
  const std::vector<Edge> clip = boxEdges(clipBox(model));
  if (drawnBox(model)) drawBox(clip);
  drawSolidObstacles(model);
  SurfaceColours colors = coloursFor(model, state, options.colouring, options.colourScale);
  drawSurface(model.body(), state, colors, options.wireframe);
  drawSprings(model, state, options);
  drawPinnedPoints(model, state);
  // Translucent, after everything opaque, so that what lies behind them shows through.
  if (model.world.hasPlane) drawPlane(model.plane(), clip);
  drawHalfSpaces(model, clip);
  if (pull && pull->point >= 0) drawPull(state, *pull);
  const bool coloured = options.colouring != Colouring::Plain;
  const LegendLayout legend = layoutLegends(width, height, options.springKinds(), coloured);
  if (coloured) drawLegend(colors, legend, width, height);
  if (options.springKinds() > 0) drawSpringLegend(options, legend, width, height);
}

double fittedColourScale(const Model& model, const State& state, Colouring colouring) {
  if (colouring == Colouring::Plain || colouring == Colouring::Friction) return 0;
  return coloursFor(model, state, colouring, 0).scale;
}

}  // namespace jello
