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
  const PoseFix carried =
      carryFix(measured, then.inverse() * late.pose(), OdometrySensitivity::Zero());
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

// The transition's bias and scale block between two copies of a filter is the motion's
// sensitivity to them: predicting with a slightly other bias (scale) moves the pose by it.
TEST(LateFusion, OdometrySensitivityMatchesPredictingWithAnotherBiasAndScale) {
  const geometry::Pose2 start(1.0, 2.0, 0.4);
  PoseEkf then;
  then.initialise(start, Eigen::Matrix3d::Identity() * 0.01, 0.0);
  for (int i = 0; i < 4; ++i) then.predictWithOdometry(2.0, 0.3, 0.1);
  PoseEkf now = then;
  for (int i = 0; i < 3; ++i) now.predictWithOdometry(1.5 + 0.3 * i, 0.2 - 0.2 * i, 0.1);
  const OdometrySensitivity G = now.odometrySensitivitySince(then);

  // The same motion from then's pose, integrated with the bias (scale) moved by h.
  const auto moved = [&](double bias, double scale) {
    geometry::Pose2 pose = then.pose();
    for (int i = 0; i < 3; ++i) {
      const OdometryArc arc = odometryArc(pose.yaw, 1.5 + 0.3 * i, 0.2 - 0.2 * i, bias, scale, 0.1);
      pose = geometry::Pose2(pose.x + arc.delta(0), pose.y + arc.delta(1), pose.yaw + arc.delta(2));
    }
    return Eigen::Vector3d(pose.x, pose.y, pose.yaw);
  };
  const double h = 1e-6;
  const Eigen::Vector3d d_bias = (moved(h, 1.0) - moved(-h, 1.0)) / (2 * h);
  const Eigen::Vector3d d_scale = (moved(0.0, 1.0 + h) - moved(0.0, 1.0 - h)) / (2 * h);
  EXPECT_TRUE(G.col(0).isApprox(d_bias, 1e-5)) << G << "\n" << d_bias.transpose();
  EXPECT_TRUE(G.col(1).isApprox(d_scale, 1e-5)) << G << "\n" << d_scale.transpose();
  EXPECT_NEAR(G(2, 0), -0.3, 1e-9);  // the bias turns the vehicle for the 0.3 s
}

// Without odometry noise over the delay, a late fix carried with its sensitivity to the bias
// and scale gives what fusing it on time and predicting on gives: the pose, the covariance and
// the bias.
TEST(LateFusion, ACarriedFixTeachesTheBiasWhatItWouldHaveTaughtOnTime) {
  EkfOptions quiet;
  quiet.speed_sigma = 0.0;
  quiet.yaw_rate_sigma = 0.0;
  quiet.yaw_rate_bias_walk = 0.0;
  quiet.speed_scale_walk = 0.0;
  const double speed = 2.0, yaw_rate = 0.1, dt = 0.1;
  const geometry::Pose2 start(1.0, 2.0, 0.4);
  const Eigen::Matrix3d P0 = Eigen::Vector3d(0.0004, 0.0004, 0.00003).asDiagonal();
  const Eigen::Matrix3d R = Eigen::Vector3d(0.0004, 0.0004, 0.00003).asDiagonal();

  // Fixed at t = 0, then a fix 0.3 s later that says the vehicle turned 0.6 deg less.
  PoseEkf on_time(quiet), late(quiet), naive(quiet);
  for (PoseEkf* ekf : {&on_time, &late, &naive}) {
    ekf->initialise(start, P0, 0.0);
    for (int i = 0; i < 3; ++i) ekf->predictWithOdometry(speed, yaw_rate, dt);
  }
  const geometry::Pose2 fix = on_time.pose() * geometry::Pose2(0.0, 0.0, -0.6 * M_PI / 180.0);
  PoseFix measured;
  measured.pose = fix;
  measured.covariance = R;

  on_time.update(fix, R);
  const PoseEkf then = late;
  for (int i = 0; i < 2; ++i) {
    on_time.predictWithOdometry(speed, yaw_rate, dt);
    late.predictWithOdometry(speed, yaw_rate, dt);
    naive.predictWithOdometry(speed, yaw_rate, dt);
  }
  const geometry::Pose2 motion = then.pose().inverse() * late.pose();
  const PoseFix carried = carryFix(measured, motion, late.odometrySensitivitySince(then));
  late.update(carried.pose, carried.covariance, Eigen::Matrix3d::Zero(), carried.carried);
  const PoseFix stale = carryFix(measured, motion, OdometrySensitivity::Zero());
  naive.update(stale.pose, stale.covariance);

  // The fix saw the vehicle turn less than the odometry said: a bias.
  EXPECT_GT(on_time.yawRateBias(), 0.005);
  EXPECT_NEAR(late.yawRateBias(), on_time.yawRateBias(), 0.02 * std::abs(on_time.yawRateBias()));
  EXPECT_NEAR(late.pose().x, on_time.pose().x, 1e-4);
  EXPECT_NEAR(late.pose().y, on_time.pose().y, 1e-4);
  EXPECT_NEAR(geometry::wrapAngle(late.pose().yaw - on_time.pose().yaw), 0.0, 1e-5);
  EXPECT_TRUE(late.fullCovariance().isApprox(on_time.fullCovariance(), 0.02))
      << late.fullCovariance() << "\n\n"
      << on_time.fullCovariance();
  // Carried as a fix of the present, the fix is taken to have seen the bias act for 0.5 s
  // instead of 0.3 s: the filter claims to know the bias better than the fix told it (a
  // wrong bias then outlasts the fixes that follow) and its heading is off.
  EXPECT_LT(naive.yawRateBiasVariance(), 0.8 * on_time.yawRateBiasVariance());
  EXPECT_GT(std::abs(geometry::wrapAngle(naive.pose().yaw - on_time.pose().yaw)), 5e-4);
}

}  // namespace
}  // namespace parkloc::localize
