#pragma once
// A measurement that arrives late: the full-frame texts of a frame set spotted on the search
// worker (search_worker.h) come back a frame set or more after their images were captured.
// They are associated and solved as they would have been on time, against the filter's
// prediction then and with each camera where it stood then; the fix, a pose at the capture
// time, is carried to the present by the vehicle's motion since (wheel odometry, through the
// filter's prediction) and fused there. For a pose measured at time k and a motion M known
// from odometry, the pose now is pose_k * M. M is the filter's: its bias and scale estimates
// turned and stretched it, so the carried fix holds their errors over the delay (a bias
// 1 deg/s off turns a fix 0.2 s late by 0.2 deg). The fix says so (PoseFix::carried, the
// motion's sensitivity to them) and the filter's update takes it in (H = [I -G]): fusing it
// now then gives what fusing the fix at k and predicting by M would have given, up to the
// odometry noise over the delay (speed_sigma * delay: 5 mm at 0.1 s), far below a fix's own
// uncertainty. Without it the filter would read the fix's heading as the bias acting until
// now, over an interval the fix has not seen, and with fixes a few tenths of a second apart
// and as late, learn a bias the drive does not have.
#include <Eigen/Core>

#include "geometry/pose.h"
#include "localize/track_lifecycle.h"

namespace parkloc::localize {

// The pose `motion` later than `then` (then * motion), and the Jacobian of that pose with
// respect to `then` (x, y, yaw): J_now_then.
Eigen::Matrix3d carryJacobian(const geometry::Pose2& then, const geometry::Pose2& motion);

// A fix at the capture time carried to the present: its pose moved by `motion` (the vehicle
// now in the vehicle frame then), its covariances (the whole, the map's part, the floor)
// through the Jacobian; `sensitivity` is the motion's on the filter's bias and scale.
PoseFix carryFix(const PoseFix& fix, const geometry::Pose2& motion,
                 const OdometrySensitivity& sensitivity);

// Both fixes of a frame set carried by `motion`.
FrameFixes carryFixes(const FrameFixes& fixes, const geometry::Pose2& motion,
                      const OdometrySensitivity& sensitivity);

}  // namespace parkloc::localize
