// graphics/scenedraw.cpp: a scene's obstacles, pins and bounding box in the picture.
//
// As in showCube.cpp, every call sets the GL state it relies on.

#include "graphics/scenedraw.h"

#include <GL/gl.h>

#include <algorithm>
#include <cmath>

#include "graphics/showCube.h"  // kPi
#include "model/plane.h"
#include "model/scenespec.h"

namespace jello {

namespace {

// Solid obstacles: a muted teal, apart from the jelly's red and the grey background; their
// edges darker, so that a box's faces read as a box.
constexpr float kSolidColour[3] = {0.25f, 0.6f, 0.62f};
constexpr float kSolidEdgeColour[3] = {0.1f, 0.3f, 0.32f};
// Half-spaces: a sandy ground, translucent so that what is behind shows through, more opaque
// than the course's plane: it is the floor things rest on.
constexpr float kGroundColour[4] = {0.78f, 0.7f, 0.48f, 0.55f};
constexpr float kGroundEdgeColour[3] = {0.55f, 0.47f, 0.28f};
constexpr float kPinColour[3] = {0.08f, 0.08f, 0.1f};
constexpr double kPinRadius = 0.07;  // m: half the lattice's spacing of 1/7 m
// Tessellation of a ball: enough for a smooth outline at the window's size.
constexpr int kBallSlices = 48, kBallStacks = 24, kPinSlices = 12, kPinStacks = 6;
// Solid obstacles are pushed back in depth by this (glPolygonOffset), more than the jelly (1, 1).
constexpr float kObstacleOffsetFactor = 4.0f, kObstacleOffsetUnits = 16.0f;

void vertex(Vec3 p) { glVertex3d(p.x, p.y, p.z); }
void normal(Vec3 n) { glNormal3d(n.x, n.y, n.z); }
double coordinate(Vec3 p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }

Vec3 fromCoordinates(const double c[3]) { return {c[0], c[1], c[2]}; }

// A lit ball of quad strips from pole to pole, its normals the radial directions.
void drawBall(Vec3 centre, double radius, int slices, int stacks) {
  for (int i = 0; i < stacks; ++i) {
    glBegin(GL_QUAD_STRIP);
    for (int j = 0; j <= slices; ++j) {
      const double phi = 2 * kPi * j / slices;
      for (int row : {i, i + 1}) {
        const double theta = kPi * row / stacks;  // from the top
        const Vec3 n{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                     std::cos(theta)};
        normal(n);
        vertex(centre + radius * n);
      }
    }
    glEnd();
  }
}

// A lit solid box: its six faces with their outward normals, then its edges.
void drawSolidBox(const BoxExtent& box) {
  glBegin(GL_QUADS);
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      const int u = (axis + 1) % 3, w = (axis + 2) % 3;
      double n[3] = {0, 0, 0};
      n[axis] = side == 0 ? -1 : 1;
      normal(fromCoordinates(n));
      double c[3];
      c[axis] = coordinate(side == 0 ? box.lower : box.upper, axis);
      const double corners[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
      for (const auto& corner : corners) {
        c[u] = coordinate(corner[0] == 0 ? box.lower : box.upper, u);
        c[w] = coordinate(corner[1] == 0 ? box.lower : box.upper, w);
        vertex(fromCoordinates(c));
      }
    }
  glEnd();
  glDisable(GL_LIGHTING);
  glColor3fv(kSolidEdgeColour);
  glLineWidth(1.5f);
  glBegin(GL_LINES);
  for (const auto& [from, to] : boxEdges(box)) {
    vertex(from);
    vertex(to);
  }
  glEnd();
  glEnable(GL_LIGHTING);
}

const SceneSpec* specOf(const Model& model) { return model.world.scene.get(); }

}  // namespace

std::vector<Edge> boxEdges(const BoxExtent& box) {
  std::vector<Edge> edges;
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, w = (axis + 2) % 3;
    for (Vec3 a : {box.lower, box.upper})
      for (Vec3 b : {box.lower, box.upper}) {
        double from[3], to[3];
        from[axis] = coordinate(box.lower, axis);
        to[axis] = coordinate(box.upper, axis);
        from[u] = to[u] = coordinate(a, u);
        from[w] = to[w] = coordinate(b, w);
        edges.push_back({fromCoordinates(from), fromCoordinates(to)});
      }
  }
  return edges;
}

std::vector<Vec3> planeInBox(const Plane& plane, const std::vector<Edge>& edges) {
  const Vec3 n{plane.a, plane.b, plane.c};
  std::vector<Vec3> points;
  for (const auto& [p, q] : edges) {
    double sp = planeValue(plane, p), sq = planeValue(plane, q);
    // sp == sq: the edge lies in the plane (its ends come from the edges that meet it there)
    // or parallel to it.
    if (sp * sq > 0 || sp == sq) continue;
    Vec3 x = p + (sp / (sp - sq)) * (q - p);
    // A corner on the plane is found by each of its three edges: keep it once.
    bool seen =
        std::any_of(points.begin(), points.end(), [&](Vec3 y) { return length(x - y) < 1e-9; });
    if (!seen) points.push_back(x);
  }
  if (points.size() < 3) return {};
  Vec3 centre;
  for (Vec3 p : points) centre += p;
  centre = (1.0 / points.size()) * centre;
  double len;
  Vec3 unitNormal = direction(n, &len);
  Vec3 e1 = direction(points[0] - centre, &len);
  Vec3 e2 = cross(unitNormal, e1);
  std::sort(points.begin(), points.end(), [&](Vec3 p, Vec3 q) {
    return std::atan2(dot(p - centre, e2), dot(p - centre, e1)) <
           std::atan2(dot(q - centre, e2), dot(q - centre, e1));
  });
  return points;
}

std::optional<BoxExtent> drawnBox(const Model& model) {
  const SceneSpec* spec = specOf(model);
  if (spec && !spec->boundsPresent) return std::nullopt;
  if (spec && spec->bounds) return BoxExtent{spec->bounds->lower, spec->bounds->upper};
  const double h = kBoxHalfSize;
  return BoxExtent{{-h, -h, -h}, {h, h, h}};
}

BoxExtent clipBox(const Model& model) {
  if (std::optional<BoxExtent> box = drawnBox(model)) return *box;
  const double h = kOpenSceneHalfSize;
  return {{-h, -h, -h}, {h, h, h}};
}

void drawSolidObstacles(const Model& model) {
  const SceneSpec* spec = specOf(model);
  if (!spec) return;
  glEnable(GL_LIGHTING);
  glShadeModel(GL_SMOOTH);
  // Pushed back in depth further than the jelly's surface is (showCube.cpp): a surface that
  // rests on an obstacle, its flat triangles chords within a millimetre of a ball, is drawn over
  // it instead of the ball showing through in patches.
  glPolygonOffset(kObstacleOffsetFactor, kObstacleOffsetUnits);
  glEnable(GL_POLYGON_OFFSET_FILL);
  for (const Obstacle& o : spec->obstacles) {
    glColor3fv(kSolidColour);
    if (o.shape == ObstacleShape::Sphere) drawBall(o.centre, o.radius, kBallSlices, kBallStacks);
    if (o.shape == ObstacleShape::Box) drawSolidBox({o.lower, o.upper});
  }
  glDisable(GL_POLYGON_OFFSET_FILL);
}

void drawHalfSpaces(const Model& model, const std::vector<Edge>& clip) {
  const SceneSpec* spec = specOf(model);
  if (!spec) return;
  glDisable(GL_LIGHTING);
  for (const Obstacle& o : spec->obstacles) {
    if (o.shape != ObstacleShape::HalfSpace) continue;
    const Plane plane{o.normal.x, o.normal.y, o.normal.z, -dot(o.normal, o.point)};
    const std::vector<Vec3> polygon = planeInBox(plane, clip);
    if (polygon.empty()) continue;
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
    glColor4fv(kGroundColour);
    glBegin(GL_POLYGON);
    for (Vec3 p : polygon) vertex(p);
    glEnd();
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glColor3fv(kGroundEdgeColour);
    glLineWidth(1.5f);
    glBegin(GL_LINE_LOOP);
    for (Vec3 p : polygon) vertex(p);
    glEnd();
  }
}

void drawPinnedPoints(const Model& model, const State& state) {
  if (model.pinned.empty()) return;
  glEnable(GL_LIGHTING);
  glShadeModel(GL_SMOOTH);
  glColor3fv(kPinColour);
  for (int q : model.pinned)
    drawBall(load(state.p(), q, model.points()), kPinRadius, kPinSlices, kPinStacks);
}

}  // namespace jello
