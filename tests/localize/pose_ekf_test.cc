#include "localize/pose_ekf.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

namespace parkloc::localize {
namespace {

TEST(PoseEkf, DeadReckoningCovarianceGrows) {
  PoseEkf ekf;
  ekf.initialise({0.0, 0.0, 0.0}, Eigen::Matrix3d::Identity() * 1e-4, 0.0);
  double previous_trace = ekf.covariance().trace();
  double previous_lateral = ekf.covariance()(1, 1);
  for (int i = 0; i < 50; ++i) {
    ekf.predictWithOdometry(2.0, 0.0, 0.1);
    EXPECT_GT(ekf.covariance().trace(), previous_trace);
    EXPECT_GT(ekf.covariance()(1, 1), previous_lateral);  // heading error -> lateral error
    previous_trace = ekf.covariance().trace();
    previous_lateral = ekf.covariance()(1, 1);
  }
  // Straight at 2 m/s for 5 s.
  EXPECT_NEAR(ekf.pose().x, 10.0, 1e-9);
  EXPECT_NEAR(ekf.pose().y, 0.0, 1e-9);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(ekf.covariance());
  EXPECT_GT(eigen.eigenvalues().minCoeff(), 0.0);
}

TEST(PoseEkf, RandomWalkWithoutOdometryGrowsLinearlyInTime) {
  EkfOptions options;
  options.no_odometry_position_sigma = 0.5;
  PoseEkf ekf(options);
  ekf.initialise({1.0, 2.0, 0.3}, Eigen::Matrix3d::Zero(), 0.0);
  ekf.predictWithoutOdometry(2.0);
  EXPECT_NEAR(ekf.covariance()(0, 0), 0.25 * 2.0, 1e-12);
  EXPECT_NEAR(ekf.pose().x, 1.0, 1e-12);
}

TEST(PoseEkf, ArcMotionIsExactForConstantInputs) {
  PoseEkf ekf;
  ekf.initialise({0.0, 0.0, 0.0}, Eigen::Matrix3d::Identity() * 1e-4, 0.0);
  // A quarter circle of radius 5 m in 100 steps.
  const double radius = 5.0, speed = 1.0, rate = speed / radius;
  const double total = 0.5 * M_PI / rate;
  for (int i = 0; i < 100; ++i) ekf.predictWithOdometry(speed, rate, total / 100);
  EXPECT_NEAR(ekf.pose().x, radius, 1e-9);
  EXPECT_NEAR(ekf.pose().y, radius, 1e-9);
  EXPECT_NEAR(ekf.pose().yaw, M_PI / 2, 1e-9);
}

TEST(PoseEkf, UpdateShrinksCovarianceAndMovesTowardsTheFix) {
  PoseEkf ekf;
  ekf.initialise({0.0, 0.0, 0.0}, Eigen::Matrix3d::Identity(), 0.0);
  const Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  EXPECT_NEAR(ekf.mahalanobis2({1.0, 0.0, 0.0}, R), 0.5, 1e-12);
  ekf.update({1.0, 0.0, 0.0}, R);
  EXPECT_NEAR(ekf.pose().x, 0.5, 1e-12);
  EXPECT_NEAR(ekf.covariance()(0, 0), 0.5, 1e-12);
  // The yaw innovation is wrapped: a fix at +179 degrees against -179 is 2 degrees away.
  PoseEkf wrap;
  wrap.initialise({0.0, 0.0, -179.0 * M_PI / 180}, Eigen::Matrix3d::Identity(), 0.0);
  wrap.update({0.0, 0.0, 179.0 * M_PI / 180}, Eigen::Matrix3d::Identity());
  EXPECT_NEAR(std::abs(wrap.pose().yaw), M_PI, 1.1 * M_PI / 180);
}

}  // namespace
}  // namespace parkloc::localize
