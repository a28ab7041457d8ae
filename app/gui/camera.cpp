#include "app/gui/camera.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

namespace foldlab::gui {

Eigen::Vector3f OrbitCamera::eye() const {
  const Eigen::Vector3f direction(std::cos(pitch_rad) * std::sin(yaw_rad), std::sin(pitch_rad),
                                  std::cos(pitch_rad) * std::cos(yaw_rad));
  return target + distance_mm * direction;
}

Eigen::Matrix4f OrbitCamera::view() const {
  const Eigen::Vector3f f = (target - eye()).normalized();
  const Eigen::Vector3f s = f.cross(Eigen::Vector3f::UnitY()).normalized();
  const Eigen::Vector3f u = s.cross(f);
  Eigen::Matrix4f m = Eigen::Matrix4f::Identity();
  m.block<1, 3>(0, 0) = s.transpose();
  m.block<1, 3>(1, 0) = u.transpose();
  m.block<1, 3>(2, 0) = -f.transpose();
  m(0, 3) = -s.dot(eye());
  m(1, 3) = -u.dot(eye());
  m(2, 3) = f.dot(eye());
  return m;
}

Eigen::Matrix4f OrbitCamera::projection(float aspect) const {
  // Near and far follow the distance so that depth precision stays where the cloth is.
  const float near_mm = std::max(1.0f, distance_mm * 0.02f);
  const float far_mm = distance_mm * 20.0f;
  const float f = 1.0f / std::tan(0.5f * fov_y_rad);
  Eigen::Matrix4f m = Eigen::Matrix4f::Zero();
  m(0, 0) = f / std::max(aspect, 1e-3f);
  m(1, 1) = f;
  m(2, 2) = (far_mm + near_mm) / (near_mm - far_mm);
  m(2, 3) = 2.0f * far_mm * near_mm / (near_mm - far_mm);
  m(3, 2) = -1.0f;
  return m;
}

void OrbitCamera::orbit(float dx_px, float dy_px) {
  constexpr float kRadPerPixel = 0.008f;
  yaw_rad -= dx_px * kRadPerPixel;
  pitch_rad = std::clamp(pitch_rad + dy_px * kRadPerPixel, -1.5f, 1.5f);
}

void OrbitCamera::zoom(float wheel_steps) {
  distance_mm = std::clamp(distance_mm * std::pow(kZoomPerWheelStep, wheel_steps), 10.0f, 1e6f);
}

void OrbitCamera::pan(float dx_px, float dy_px, float viewport_height_px) {
  const Eigen::Vector3f f = (target - eye()).normalized();
  const Eigen::Vector3f s = f.cross(Eigen::Vector3f::UnitY()).normalized();
  const Eigen::Vector3f u = s.cross(f);
  // One pixel moves the target by the size of a pixel at the target's depth.
  const float mm_per_px =
      2.0f * distance_mm * std::tan(0.5f * fov_y_rad) / std::max(viewport_height_px, 1.0f);
  target += (-dx_px * s + dy_px * u) * mm_per_px;
}

void OrbitCamera::frame(const Eigen::Vector3f& centre, float radius_mm) {
  *this = OrbitCamera{};
  target = centre;
  distance_mm = std::max(radius_mm, 1.0f) / std::sin(0.5f * fov_y_rad) * 1.15f;
}

void enclose(Eigen::Vector3f& centre, float& radius_mm, const Eigen::Vector3f& other_centre,
             float other_radius_mm) {
  const float apart = (other_centre - centre).norm();
  if (apart + other_radius_mm <= radius_mm) {
    return;
  }
  if (apart + radius_mm <= other_radius_mm) {
    centre = other_centre;
    radius_mm = other_radius_mm;
    return;
  }
  const float radius = 0.5f * (apart + radius_mm + other_radius_mm);
  centre += (other_centre - centre) * ((radius - radius_mm) / apart);
  radius_mm = radius;
}

// The grid's bounding box in world coordinates (y up), whatever the shape.
void cloth_bounds(Scene& scene, Eigen::Vector3f& centre, float& radius_mm) {
  Eigen::Vector3f lo = Eigen::Vector3f::Constant(std::numeric_limits<float>::max());
  Eigen::Vector3f hi = -lo;
  for (const Eigen::Vector3f& v : scene.grid().positions_mm) {
    const Eigen::Vector3f world(v.x(), -v.y(), v.z());
    lo = lo.cwiseMin(world);
    hi = hi.cwiseMax(world);
  }
  centre = 0.5f * (lo + hi);
  radius_mm = std::max(1.0f, 0.5f * (hi - lo).norm());
}

}  // namespace foldlab::gui
