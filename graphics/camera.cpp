// graphics/camera.cpp: where the pictures' camera looks from (showCube.h): the default one for a
// world, --camera's request, and its horizontal axes.

#include <cmath>
#include <optional>

#include "graphics/scenedraw.h"
#include "graphics/showCube.h"
#include "model/scenespec.h"

namespace jello {

Vec3 Camera::horizontalAxis(int which) const {
  // Beyond this |up.x|, +x is too near `up` to give the azimuth's zero: +y does.
  constexpr double kNearX = 0.9;
  const Vec3 reference = std::fabs(up.x) > kNearX ? Vec3{0, 1, 0} : Vec3{1, 0, 0};
  double len;
  const Vec3 zero = direction(reference - dot(reference, up) * up, &len);
  return which == 0 ? zero : cross(up, zero);
}

// With up +z the axes are +x and +y exactly, and this is the course viewer's eye to the bit.
Vec3 Camera::eye() const {
  return (radius * std::cos(phi) * std::cos(theta)) * horizontalAxis(0) +
         (radius * std::sin(phi) * std::cos(theta)) * horizontalAxis(1) +
         (radius * std::sin(theta)) * up;
}

Vec3 Camera::away() const {
  return (-std::cos(phi)) * horizontalAxis(0) + (-std::sin(phi)) * horizontalAxis(1);
}

Vec3 Camera::right() const { return cross(away(), up); }

namespace {

// cameraFor without a request.
Camera defaultCamera(const Model& model) {
  Camera camera;
  const SceneSpec* spec = model.world.scene.get();
  if (!spec) return camera;
  double g;
  const Vec3 up = direction((-1.0) * spec->gravity, &g);
  if (g > 0) camera.up = up;
  // The default distance sees the course's box whole: as far back again as a larger box's
  // farthest corner is beyond the course box's. A box less than half the course's (a scene in
  // centimetres) is seen as closely as a box half the course's: the camera comes nearer.
  if (const std::optional<BoxExtent> box = drawnBox(model)) {
    const Vec3 corner{std::max(std::fabs(box->lower.x), std::fabs(box->upper.x)),
                      std::max(std::fabs(box->lower.y), std::fabs(box->upper.y)),
                      std::max(std::fabs(box->lower.z), std::fabs(box->upper.z))};
    const double courseCorner = kBoxHalfSize * std::sqrt(3.0);
    const double ratio = length(corner) / courseCorner;
    const double scale = ratio >= 0.5 ? std::max(ratio, 1.0) : 2 * ratio;
    camera.radius = std::min(camera.radius * scale, kMaxCameraDistance);
  }
  return camera;
}

}  // namespace

Camera cameraFor(const Model& model, const std::optional<CameraRequest>& request) {
  Camera camera = defaultCamera(model);
  if (request) {
    camera.phi = request->azimuth * kPi / 180;
    camera.theta = request->elevation * kPi / 180;
    if (request->distance > 0) camera.radius = request->distance;
  }
  return camera;
}

}  // namespace jello
