#pragma once
// The surround-view rig: named cameras with their extrinsics. Vehicle frame as ROS
// REP-103: x forward, y left, z up, origin on the ground under the rear-axle centre.
#include <optional>
#include <string>
#include <vector>

#include "geometry/camera_model.h"
#include "geometry/pose.h"
#include "geometry/vehicle_body.h"

namespace parkloc::geometry {

struct RigCamera {
  std::string name;
  CameraModel model;
  Rigid3 vehicle_from_camera = Rigid3::Identity();
  // The vehicle the camera is mounted on, the same box for every camera of a rig: what it
  // hides, the camera does not see. Empty: nothing of the vehicle is in the way.
  std::optional<VehicleBody> body;
};

// Whether two cameras are the same calibration: name, model, mounting and body.
bool sameCalibration(const RigCamera& a, const RigCamera& b);

struct Rig {
  std::vector<RigCamera> cameras;

  const RigCamera* find(const std::string& name) const;
};

// Camera orientation for a camera that looks along vehicle heading `yaw` (0 front,
// pi/2 left) and is pitched down by `pitch_down` (radians) from the horizon.
Eigen::Matrix3d vehicleFromCameraRotation(double yaw, double pitch_down, double roll = 0.0);

// A rig resembling a production surround-view system: four 1280x800 fisheye cameras of
// about 197 degrees; front on the bumper (0.6 m), mirrors (1.0 m, looking down), rear (0.9 m);
// the car's body a 4.7 m x 1.85 m box from 0.15 m to 1.45 m above the floor.
Rig defaultRig();

}  // namespace parkloc::geometry
