#include "localize/late_fusion.h"

#include <gtest/gtest.h>

#include "localize/pose_ekf.h"

namespace parkloc::localize {
namespace {

TEST(LateFusion, CarryJacobianMatchesCentralDifferences) {
  const geometry::Pose2 then(3.0, -2.0, 0.7), motion(0.4, 0.1, -0.2);
  const Eigen::Matrix3d J = carryJacobian(then, motion);
  const double h = 1e-6;
  for (int i = 0; i < 3; ++i) {
    Eigen::Vector3d d = Eigen::Vector3d::Zero();
    d(i) = h;
    const geometry::Pose2 plus = geometry::Pose2(then.x + d(0), then.y + d(1), then.yaw + d(2)) * motion;
    const geometry::Pose2 minus = geometry::Pose2(then.x - d(0), then.y - d(1), then.yaw - d(2)) * motion;
    const Eigen::Vector3d numeric((plus.x - minus.x) / (2 * h), (plus.y - minus.y) / (2 * h),
                                  geometry::wrapAngle(plus.yaw - minus.yaw) / (2 * h));
    EXPECT_TRUE(J.col(i).isApprox(numeric, 1e-6)) << i << "\n" << J << "\n" << numeric;
  }
}

// A fix measured at frame set k and fused three frame sets later, carried by the filter's
// motion since, gives the pose that fusing it at k and predicting on would have given.
TEST(LateFusion, AFixFusedLateAtItsCaptureTimeGivesThePoseOfFusingItOnTime) {
  const double speed = 2.0, yaw_rate = 0.3, dt = 0.1;
  const geometry::Pose2 start(1.0, 2.0, 0.4);
  const Eigen::Matrix3d P0 = Eigen::Vector3d(0.04, 0.04, 0.003).asDiagonal();
  // The fix disagrees with the prediction by a few centimetres and half a degree.
  PoseEkf probe;
  probe.initialise(start, P0, 0.0);
  probe.predictWithOdometry(speed, yaw_rate, dt);
  const geometry::Pose2 fix = probe.pose() * geometry::Pose2(0.03, -0.02, 0.009);
  PoseFix measured;
  measured.pose = fix;
  measured.covariance = Eigen::Vector3d(0.0004, 0.0004, 0.00005).asDiagonal();

  PoseEkf on_time;
  on_time.initialise(start, P0, 0.0);
  on_time.predictWithOdometry(speed, yaw_rate, dt);
  on_time.update(measured.pose, measured.covariance);
  for (int i = 0; i < 3; ++i) on_time.predictWithOdometry(speed, yaw_rate, dt);

  PoseEkf late;
  late.initialise(start, P0, 0.0);
  late.predictWithOdometry(speed, yaw_rate, dt);
  const geometry::Pose2 then = late.pose();
  for (int i = 0; i < 3; ++i) late.predictWithOdometry(speed, yaw_rate, dt);
  const PoseFix carried = carryFix(measured, then.inverse() * late.pose());
  late.update(carried.pose, carried.covariance);

  EXPECT_NEAR(late.pose().x, on_time.pose().x, 0.002);
  EXPECT_NEAR(late.pose().y, on_time.pose().y, 0.002);
  EXPECT_NEAR(geometry::wrapAngle(late.pose().yaw - on_time.pose().yaw), 0.0, 0.001);
  // Fused as it came, the fix drags the pose back towards where the vehicle was 0.3 s ago.
  PoseEkf stale;
  stale.initialise(start, P0, 0.0);
  for (int i = 0; i < 4; ++i) stale.predictWithOdometry(speed, yaw_rate, dt);
  stale.update(measured.pose, measured.covariance);
  EXPECT_GT((stale.pose().translation() - on_time.pose().translation()).norm(), 0.1);
  EXPECT_NEAR(late.covariance().trace(), on_time.covariance().trace(),
              0.25 * on_time.covariance().trace());
}

}  // namespace
}  // namespace parkloc::localize
