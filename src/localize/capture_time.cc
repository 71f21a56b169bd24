#include "localize/capture_time.h"

#include <cmath>

namespace parkloc::localize {

geometry::Rigid3 vehicleMotionOver(const OdometrySample& motion, double dt) {
  const double turn = motion.yaw_rate * dt;
  const double distance = motion.speed * dt;
  // The chord of the arc points along half the turn.
  geometry::Rigid3 T = geometry::Rigid3::Identity();
  T.translation() = Eigen::Vector3d(distance * std::cos(0.5 * turn), distance * std::sin(0.5 * turn), 0.0);
  T.linear() = Eigen::AngleAxisd(turn, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return T;
}

geometry::Rig rigAtFrameTime(const geometry::Rig& nominal, const FrameInput& frame,
                             const std::optional<OdometrySample>& motion) {
  geometry::Rig rig = nominal;
  if (!motion) return rig;
  for (const CameraInput& input : frame.cameras) {
    if (!input.capture_time || !std::isfinite(*input.capture_time)) continue;
    const double dt = *input.capture_time - frame.timestamp;
    if (dt == 0.0) continue;
    for (geometry::RigCamera& camera : rig.cameras)
      if (camera.name == input.camera)
        camera.vehicle_from_camera = vehicleMotionOver(*motion, dt) * camera.vehicle_from_camera;
  }
  return rig;
}

}  // namespace parkloc::localize
