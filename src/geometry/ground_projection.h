#pragma once
// Image <-> plane geometry for one rig camera, in the vehicle frame.
//  (a) The paper's method (OCR-RTPS section 3.4): a 3x3 homography between the
//      undistorted (virtual pinhole) image and the ground plane z = 0, computed from the
//      calibration as H = K [r1 r2 t].
//  (b) Exact ray/plane intersection, for the ground or any other plane (a pillar face).
#include <Eigen/Core>
#include <optional>

#include "geometry/rig.h"

namespace parkloc::geometry {

// The plane n . x + d = 0 (n unit length).
struct Plane {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  double offset = 0.0;

  static Plane ground() { return {}; }
  static Plane throughPoint(const Eigen::Vector3d& normal, const Eigen::Vector3d& point) {
    const Eigen::Vector3d n = normal.normalized();
    return {n, -n.dot(point)};
  }
  Plane transformed(const Rigid3& b_from_a) const {
    const Eigen::Vector3d n = b_from_a.linear() * normal;
    return {n, offset - n.dot(b_from_a.translation())};
  }
};

// Point where the ray origin + t * direction (t > 0) meets the plane; empty when the ray
// is parallel to it or points away from it.
std::optional<Eigen::Vector3d> intersectRayPlane(const Eigen::Vector3d& origin,
                                                 const Eigen::Vector3d& direction,
                                                 const Plane& plane);

// The pixel of a rig camera cast onto a plane given in the vehicle frame; the result is
// in the vehicle frame.
std::optional<Eigen::Vector3d> pixelToPlane(const RigCamera& camera, const Eigen::Vector2d& pixel,
                                            const Plane& plane_in_vehicle);

// The paper's ground homography for one camera.
struct GroundHomography {
  Eigen::Matrix3d K_virtual = Eigen::Matrix3d::Identity();  // the undistorted pinhole view
  Eigen::Matrix3d undistorted_from_ground = Eigen::Matrix3d::Identity();  // H = K [r1 r2 t]
  Eigen::Matrix3d ground_from_undistorted = Eigen::Matrix3d::Identity();  // H^-1

  // Builds H from the calibration; the virtual view keeps the camera's focal length and
  // principal point.
  static GroundHomography fromCamera(const RigCamera& camera);

  // Raw (distorted) pixel -> undistorted pixel; empty for rays at or behind 90 degrees.
  std::optional<Eigen::Vector2d> undistort(const CameraModel& model,
                                           const Eigen::Vector2d& raw_pixel) const;
  // Undistorted pixel -> ground point (x, y) in the vehicle frame; empty above the horizon.
  std::optional<Eigen::Vector2d> groundFromUndistorted(const Eigen::Vector2d& pixel) const;
  // Raw pixel -> ground point, the two steps above.
  std::optional<Eigen::Vector2d> groundFromPixel(const CameraModel& model,
                                                 const Eigen::Vector2d& raw_pixel) const;
};

}  // namespace parkloc::geometry
