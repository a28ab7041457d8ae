// An orbit camera for the 3D view: it turns about a target, zooms along its view direction and
// pans in the view plane. World coordinates are the model's with y flipped (up is +Y), in mm.
#pragma once

#include <Eigen/Core>

#include "core/geometry/scene.hpp"

namespace foldlab::gui {

// What one wheel step towards the target leaves of the distance to it (the page's pinch zooms in
// the same steps).
inline constexpr float kZoomPerWheelStep = 0.85f;

struct OrbitCamera {
  Eigen::Vector3f target = Eigen::Vector3f::Zero();
  float yaw_rad = 0.6f;     // about the vertical axis; 0 looks along -Z
  float pitch_rad = 0.25f;  // above the horizon
  float distance_mm = 4000.0f;
  float fov_y_rad = 0.6f;
  bool operator==(const OrbitCamera&) const = default;

  Eigen::Vector3f eye() const;
  Eigen::Matrix4f view() const;
  Eigen::Matrix4f projection(float aspect) const;

  void orbit(float dx_px, float dy_px);
  void zoom(float wheel_steps);
  void pan(float dx_px, float dy_px, float viewport_height_px);
  // Frames a box of the given centre and radius from the default direction.
  void frame(const Eigen::Vector3f& centre, float radius_mm);
};

// The smallest sphere around both spheres, into `centre` and `radius_mm`.
void enclose(Eigen::Vector3f& centre, float& radius_mm, const Eigen::Vector3f& other_centre,
             float other_radius_mm);

// A sphere around the cloth's grid (world coordinates) for framing the camera.
void cloth_bounds(Scene& scene, Eigen::Vector3f& centre, float& radius_mm);

}  // namespace foldlab::gui
