#include "geometry/rig.h"

#include <cmath>

namespace parkloc::geometry {

const RigCamera* Rig::find(const std::string& name) const {
  for (const auto& camera : cameras)
    if (camera.name == name) return &camera;
  return nullptr;
}

Eigen::Matrix3d vehicleFromCameraRotation(double yaw, double pitch_down, double roll) {
  // A camera looking along vehicle +x: camera z -> vehicle x, camera x -> vehicle -y,
  // camera y -> vehicle -z.
  Eigen::Matrix3d forward;
  forward.col(0) = -Eigen::Vector3d::UnitY();
  forward.col(1) = -Eigen::Vector3d::UnitZ();
  forward.col(2) = Eigen::Vector3d::UnitX();
  // Pitching down rotates the optical axis about the vehicle's y axis (positive = down).
  return (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(pitch_down, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
             .toRotationMatrix() *
         forward;
}

bool sameCalibration(const RigCamera& a, const RigCamera& b) {
  const CameraModel &m = a.model, &n = b.model;
  const bool same_body = a.body.has_value() == b.body.has_value() &&
                         (!a.body || (a.body->lo == b.body->lo && a.body->hi == b.body->hi));
  return a.name == b.name && m.type == n.type && m.width == n.width && m.height == n.height &&
         m.fx == n.fx && m.fy == n.fy && m.cx == n.cx && m.cy == n.cy &&
         m.distortion == n.distortion && m.max_theta == n.max_theta &&
         a.vehicle_from_camera.matrix() == b.vehicle_from_camera.matrix() && same_body;
}

Rig defaultRig() {
  CameraModel fisheye;
  fisheye.type = CameraModelType::kFisheye;
  fisheye.width = 1280;
  fisheye.height = 800;
  // Near-equidistant lens: about 98 degrees off-axis at the left and right image edges
  // (a 197-degree horizontal field of view); the image corners see 118 degrees.
  fisheye.fx = fisheye.fy = 365.0;
  fisheye.cx = 639.5;
  fisheye.cy = 399.5;
  fisheye.distortion = {0.015, -0.003, 0.0005, -0.00005};
  fisheye.max_theta = 2.15;  // 123 degrees; theta_d stays monotonic up to here

  auto make = [&](const std::string& name, Eigen::Vector3d position, double yaw, double pitch) {
    RigCamera camera;
    camera.name = name;
    camera.model = fisheye;
    camera.vehicle_from_camera.linear() = vehicleFromCameraRotation(yaw, pitch);
    camera.vehicle_from_camera.translation() = position;
    return camera;
  };
  const double deg = M_PI / 180.0;
  Rig rig;
  // A 4.7 m car: 2.8 m wheelbase, 0.9 m front and 1.0 m rear overhang, 1.85 m wide. The
  // cameras sit on its bumpers and (mirrors) 2.5 cm beside its flanks.
  rig.cameras.push_back(make("front", {3.70, 0.0, 0.60}, 0.0, 20.0 * deg));
  rig.cameras.push_back(make("rear", {-1.00, 0.0, 0.90}, M_PI, 30.0 * deg));
  rig.cameras.push_back(make("left", {2.00, 0.95, 1.00}, M_PI / 2, 55.0 * deg));
  rig.cameras.push_back(make("right", {2.00, -0.95, 1.00}, -M_PI / 2, 55.0 * deg));
  const VehicleBody body{Eigen::Vector3d(-1.0, -0.925, 0.15), Eigen::Vector3d(3.7, 0.925, 1.45)};
  for (auto& camera : rig.cameras) camera.body = body;
  return rig;
}

}  // namespace parkloc::geometry
