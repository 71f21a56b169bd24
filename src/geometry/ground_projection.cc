#include "geometry/ground_projection.h"

#include <Eigen/LU>
#include <cmath>

namespace parkloc::geometry {

std::optional<Eigen::Vector3d> intersectRayPlane(const Eigen::Vector3d& origin,
                                                 const Eigen::Vector3d& direction,
                                                 const Plane& plane) {
  const double denom = plane.normal.dot(direction);
  if (std::abs(denom) < 1e-12) return std::nullopt;
  const double t = -(plane.normal.dot(origin) + plane.offset) / denom;
  if (t <= 0.0) return std::nullopt;
  return origin + t * direction;
}

std::optional<Eigen::Vector3d> pixelToPlane(const RigCamera& camera, const Eigen::Vector2d& pixel,
                                            const Plane& plane_in_vehicle) {
  const auto ray = camera.model.unproject(pixel);
  if (!ray) return std::nullopt;
  const Eigen::Vector3d direction = camera.vehicle_from_camera.linear() * *ray;
  return intersectRayPlane(camera.vehicle_from_camera.translation(), direction, plane_in_vehicle);
}

GroundHomography GroundHomography::fromCamera(const RigCamera& camera) {
  GroundHomography h;
  const CameraModel& m = camera.model;
  h.K_virtual << m.fx, 0.0, m.cx, 0.0, m.fy, m.cy, 0.0, 0.0, 1.0;
  const Rigid3 camera_from_vehicle = camera.vehicle_from_camera.inverse();
  Eigen::Matrix3d Rt;
  Rt.col(0) = camera_from_vehicle.linear().col(0);
  Rt.col(1) = camera_from_vehicle.linear().col(1);
  Rt.col(2) = camera_from_vehicle.translation();
  h.undistorted_from_ground = h.K_virtual * Rt;
  h.ground_from_undistorted = h.undistorted_from_ground.inverse();
  return h;
}

std::optional<Eigen::Vector2d> GroundHomography::undistort(const CameraModel& model,
                                                           const Eigen::Vector2d& raw_pixel) const {
  const auto ray = model.unproject(raw_pixel);
  if (!ray || ray->z() < 1e-6) return std::nullopt;
  const Eigen::Vector3d p = K_virtual * (*ray / ray->z());
  return p.head<2>();
}

std::optional<Eigen::Vector2d> GroundHomography::groundFromUndistorted(
    const Eigen::Vector2d& pixel) const {
  const Eigen::Vector3d g = ground_from_undistorted * pixel.homogeneous();
  // The pixel's ray meets the ground in front of the camera only when the camera-frame
  // depth of that ground point is positive. K's last row is (0, 0, 1), so the depth is
  // H's last row applied to the ground point g / w.
  if (std::abs(g.z()) < 1e-12 || undistorted_from_ground.row(2).dot(g) / g.z() <= 0.0)
    return std::nullopt;
  return g.head<2>() / g.z();
}

std::optional<Eigen::Vector2d> GroundHomography::groundFromPixel(
    const CameraModel& model, const Eigen::Vector2d& raw_pixel) const {
  const auto undistorted = undistort(model, raw_pixel);
  if (!undistorted) return std::nullopt;
  return groundFromUndistorted(*undistorted);
}

}  // namespace parkloc::geometry
