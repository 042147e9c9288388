// graphics/panelworld.cpp: the panel's world section (panelstate.h): gravity, the obstacles (add,
// move, resize, delete balls, boxes and planes, their contact and friction) and the pins. Every
// change goes into the draft.

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>

#include "graphics/panelstate.h"
#include "io/scenereader.h"

namespace jello {

namespace {

// The fields of obstacle `i` (IDs obstacle.I.KEY, I from 1); true when one changed.
bool obstacleFields(Viewer& v, Obstacle& o, int i) {
  const std::string id = "obstacle." + std::to_string(i + 1) + ".";
  auto name = [&](const char* shown, const char* key) {
    return std::string(shown) + "##" + id + key;
  };
  bool changed = false;
  if (o.shape == ObstacleShape::Sphere) {
    changed |= vectorField(v, "centre, m", id + "centre", &o.centre, kLargestSceneNumber);
    changed |= numberField(v, name("radius, m", "radius").c_str(), &o.radius, 0,
                           kLargestSceneNumber, true);
  } else if (o.shape == ObstacleShape::Box) {
    Vec3 lower = o.lower, upper = o.upper;
    // Both corners drawn every frame (no short circuit): either may be edited.
    const bool lowerEdited = vectorField(v, "lower, m", id + "lower", &lower, kLargestSceneNumber);
    const bool upperEdited = vectorField(v, "upper, m", id + "upper", &upper, kLargestSceneNumber);
    if (lowerEdited || upperEdited) {
      if (lower.x < upper.x && lower.y < upper.y && lower.z < upper.z)
        o.lower = lower, o.upper = upper, changed = true;
      else
        v.say("a box's lower corner must be below its upper corner on every axis");
    }
  } else {
    changed |= vectorField(v, "point, m", id + "point", &o.point, kLargestSceneNumber);
    Vec3 normal = o.givenNormal;
    if (vectorField(v, "normal", id + "normal", &normal, kLargestSceneNumber)) {
      const double size = length(normal);
      if (size > 0 && std::isfinite(size))
        o.givenNormal = normal, o.normal = (1 / size) * normal, changed = true;
      else
        v.say("a plane's normal must not be zero");
    }
  }
  changed |=
      numberField(v, name("stiffness, N/m", "k").c_str(), &o.spring.k, 0, kLargestSceneNumber);
  changed |=
      numberField(v, name("damping, N s/m", "d").c_str(), &o.spring.d, 0, kLargestSceneNumber);
  changed |= frictionFields(v, id, &o.friction, false);
  return changed;
}

// A new obstacle of `shape` where it is seen, with the contact's spring and no friction; placed
// after those of its kind, as a scene file read back orders them (balls, boxes, planes).
void addObstacle(Viewer& v, ObstacleShape shape) {
  Draft& d = panel(v).draft;
  if (d.scene.obstacles.size() >= static_cast<std::size_t>(kMostObstacles)) {
    v.say("a scene holds at most " + std::to_string(kMostObstacles) + " obstacles");
    return;
  }
  Obstacle o;
  o.shape = shape;
  o.spring = {d.world.kCollision, d.world.dCollision};
  o.centre = {0, 0, -1.2};
  o.radius = 0.4;
  o.lower = {-0.5, -0.5, -1.6};
  o.upper = {0.5, 0.5, -1.2};
  o.point = {0, 0, -1.5};
  o.normal = o.givenNormal = {0, 0, 1};
  auto after = std::find_if(d.scene.obstacles.begin(), d.scene.obstacles.end(),
                            [&](const Obstacle& other) { return other.shape > shape; });
  d.scene.obstacles.insert(after, o);
  draftChanged(v, true);
}

void obstaclesPart(Viewer& v) {
  Draft& d = panel(v).draft;
  auto& obstacles = d.scene.obstacles;
  for (std::size_t i = 0; i < obstacles.size(); ++i) {
    ImGui::PushID(static_cast<int>(i));
    const std::string title =
        std::string(obstacleShapeName(obstacles[i].shape)) + " " + std::to_string(i + 1);
    if (ImGui::TreeNode(title.c_str())) {
      if (obstacleFields(v, obstacles[i], static_cast<int>(i))) draftChanged(v, true);
      const std::string remove = "delete##obstacle." + std::to_string(i + 1) + ".delete";
      const bool deleted = ImGui::Button(remove.c_str());
      traceItem(v, remove.c_str());
      ImGui::TreePop();
      if (deleted) {
        obstacles.erase(obstacles.begin() + static_cast<std::ptrdiff_t>(i));
        draftChanged(v, true);
        ImGui::PopID();
        break;
      }
    }
    ImGui::PopID();
  }
  for (ObstacleShape shape :
       {ObstacleShape::Sphere, ObstacleShape::Box, ObstacleShape::HalfSpace}) {
    const std::string label =
        std::string("add a ") + obstacleShapeName(shape) + "##add." + obstacleShapeName(shape);
    if (shape != ObstacleShape::Sphere) ImGui::SameLine();
    const bool add = ImGui::Button(label.c_str());
    traceItem(v, label.c_str());
    if (add) addObstacle(v, shape);
  }
}

// Pins the free points inside the region, where they are now.
void pinRegion(Viewer& v) {
  PanelState& p = panel(v);
  std::vector<int>& pinned = p.draft.scene.pinned;
  const int n = v.model.points();
  const std::size_t before = pinned.size();
  for (int q = 0; q < n; ++q) {
    if (inBox(load(v.state().p(), q, n), p.pinLower, p.pinUpper) &&
        !std::binary_search(pinned.begin(), pinned.end(), q))
      pinned.insert(std::upper_bound(pinned.begin(), pinned.end(), q), q);
  }
  if (pinned.size() == before) {
    v.say("no free point lies in that region now");
    return;
  }
  v.say(textf("%zu points more to pin (apply pins them)", pinned.size() - before));
  draftChanged(v, true);
}

void pinsPart(Viewer& v) {
  PanelState& p = panel(v);
  ImGui::Text("pinned: %zu points", p.draft.scene.pinned.size());
  ImGui::SameLine();
  if (ImGui::Button("release all##pins.release") && !p.draft.scene.pinned.empty()) {
    p.draft.scene.pinned.clear();
    draftChanged(v, true);
  }
  traceItem(v, "pins.release");
  vectorField(v, "from, m", "pins.lower", &p.pinLower, kLargestSceneNumber);
  vectorField(v, "to, m", "pins.upper", &p.pinUpper, kLargestSceneNumber);
  const bool pin = ImGui::Button("pin the points in it##pins.pin");
  traceItem(v, "pins.pin");
  if (pin) pinRegion(v);
}

}  // namespace

void worldSection(Viewer& v) {
  if (!ImGui::CollapsingHeader("World")) return;
  Draft& d = panel(v).draft;
  if (vectorField(v, "gravity, m/s^2", "gravity", &d.scene.gravity, kLargestSceneNumber))
    draftChanged(v, true);
  ImGui::Separator();
  obstaclesPart(v);
  ImGui::Separator();
  pinsPart(v);
}

}  // namespace jello
