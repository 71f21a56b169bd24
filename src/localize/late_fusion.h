#pragma once
// A measurement that arrives late: the full-frame texts of a frame set spotted on the search
// worker (search_worker.h) come back a frame set or more after their images were captured.
// They are associated and solved as they would have been on time, against the filter's
// prediction then and with each camera where it stood then; the fix, a pose at the capture
// time, is carried to the present by the vehicle's motion since (wheel odometry, through the
// filter's prediction) and fused there. For a pose measured at time k and a motion M known
// from odometry, the pose now is pose_k * M: fusing it now gives the pose that fusing the fix
// at k and predicting by M would have given, up to the odometry noise over the delay
// (speed_sigma * delay: 5 mm at 0.1 s), which stays far below a fix's own uncertainty.
#include <Eigen/Core>

#include "geometry/pose.h"
#include "localize/track_lifecycle.h"

namespace parkloc::localize {

// The pose `motion` later than `then` (then * motion), and the Jacobian of that pose with
// respect to `then` (x, y, yaw): J_now_then.
Eigen::Matrix3d carryJacobian(const geometry::Pose2& then, const geometry::Pose2& motion);

// A fix at the capture time carried to the present: its pose moved by `motion` (the vehicle
// now in the vehicle frame then), its covariances (the whole, the map's part, the floor)
// through the Jacobian.
PoseFix carryFix(const PoseFix& fix, const geometry::Pose2& motion);

// Both fixes of a frame set carried by `motion`.
FrameFixes carryFixes(const FrameFixes& fixes, const geometry::Pose2& motion);

}  // namespace parkloc::localize
