#pragma once
// The surround-view rig: named cameras with their extrinsics. Vehicle frame as ROS
// REP-103: x forward, y left, z up, origin on the ground under the rear-axle centre.
#include <optional>
#include <string>
#include <vector>

#include "geometry/camera_model.h"
#include "geometry/pose.h"

namespace parkloc::geometry {

struct RigCamera {
  std::string name;
  CameraModel model;
  Rigid3 vehicle_from_camera = Rigid3::Identity();
};

struct Rig {
  std::vector<RigCamera> cameras;

  const RigCamera* find(const std::string& name) const;
};

// Camera orientation for a camera that looks along vehicle heading `yaw` (0 front,
// pi/2 left) and is pitched down by `pitch_down` (radians) from the horizon.
Eigen::Matrix3d vehicleFromCameraRotation(double yaw, double pitch_down, double roll = 0.0);

// A rig resembling a production surround-view system: four 1280x800 fisheye cameras of
// about 197 degrees; front on the bumper (0.6 m), mirrors (1.0 m, looking down), rear (0.9 m).
Rig defaultRig();

}  // namespace parkloc::geometry
