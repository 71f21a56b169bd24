#include "localize/late_fusion.h"

#include <cmath>

namespace parkloc::localize {

Eigen::Matrix3d carryJacobian(const geometry::Pose2& then, const geometry::Pose2& motion) {
  // now.xy = then.xy + R(then.yaw) motion.xy, now.yaw = then.yaw + motion.yaw.
  const double c = std::cos(then.yaw), s = std::sin(then.yaw);
  Eigen::Matrix3d J = Eigen::Matrix3d::Identity();
  J(0, 2) = -s * motion.x - c * motion.y;
  J(1, 2) = c * motion.x - s * motion.y;
  return J;
}

PoseFix carryFix(const PoseFix& fix, const geometry::Pose2& motion,
                 const OdometrySensitivity& sensitivity) {
  const Eigen::Matrix3d J = carryJacobian(fix.pose, motion);
  PoseFix now = fix;
  now.pose = fix.pose * motion;
  now.covariance = J * fix.covariance * J.transpose();
  now.map_part = J * fix.map_part * J.transpose();
  now.floor = J * fix.floor * J.transpose();
  now.pixel_part = J * fix.pixel_part * J.transpose();
  for (MapErrorTerm& t : now.map_terms) t.J_fix_map = (J * t.J_fix_map).eval();
  now.carried = J * fix.carried + sensitivity;
  return now;
}

FrameFixes carryFixes(const FrameFixes& fixes, const geometry::Pose2& motion,
                      const OdometrySensitivity& sensitivity) {
  FrameFixes now = fixes;
  if (fixes.agreeing) now.agreeing = carryFix(*fixes.agreeing, motion, sensitivity);
  if (fixes.disagreeing) now.disagreeing = carryFix(*fixes.disagreeing, motion, sensitivity);
  return now;
}

}  // namespace parkloc::localize
