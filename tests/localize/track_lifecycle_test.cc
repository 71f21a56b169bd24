#include "localize/track_lifecycle.h"

#include <gtest/gtest.h>

#include <cmath>

namespace parkloc::localize {
namespace {

const Eigen::Matrix3d kFixCovariance = Eigen::Vector3d(1e-4, 1e-4, 1e-4).asDiagonal();

PoseFix fixAt(const geometry::Pose2& pose) {
  PoseFix fix;
  fix.pose = pose;
  fix.covariance = kFixCovariance;
  return fix;
}

FrameFixes agreeing(const geometry::Pose2& pose) {
  FrameFixes f;
  f.agreeing = fixAt(pose);
  return f;
}

FrameFixes disagreeing(const geometry::Pose2& pose, int landmarks) {
  FrameFixes f;
  f.disagreeing = fixAt(pose);
  f.disagreeing_landmarks = landmarks;
  return f;
}

class TrackLifecycleTest : public ::testing::Test {
 protected:
  TrackingOptions options;
  PoseEkf ekf;
  MotionPrediction motion;
  TrackLifecycle lifecycle{options, 0};

  FrameResult apply(const FrameFixes& fixes, double t) {
    FrameResult r;
    r.timestamp = t;
    lifecycle.apply(fixes, isTracking(ekf, options), ekf, motion, r);
    lifecycle.report(ekf, r);
    return r;
  }
};

TEST_F(TrackLifecycleTest, TheFirstFixStartsTheFilterAndLaterFixesUpdateIt) {
  FrameResult r = apply({}, 0.0);
  EXPECT_FALSE(r.has_pose);
  EXPECT_EQ(r.status, TrackingStatus::kNotInitialised);
  r = apply(agreeing({1.0, 2.0, 0.3}), 0.1);
  EXPECT_TRUE(r.reinitialised);
  EXPECT_EQ(r.status, TrackingStatus::kOk);
  EXPECT_NEAR(r.pose.x, 1.0, 1e-12);
  r = apply(agreeing({1.0, 2.0, 0.3}), 0.2);
  EXPECT_FALSE(r.reinitialised);
  EXPECT_EQ(r.status, TrackingStatus::kOk);
  r = apply({}, 0.3);
  EXPECT_EQ(r.status, TrackingStatus::kDeadReckoning);
}

TEST_F(TrackLifecycleTest, AFilterWhoseUncertaintyGrewPastTheLimitIsLost) {
  apply(agreeing({0.0, 0.0, 0.0}), 0.0);
  ekf.predictWithoutOdometry(100.0);  // 0.5 m/sqrt(s): 5 m
  EXPECT_FALSE(isTracking(ekf, options));
  EXPECT_EQ(apply({}, 100.0).status, TrackingStatus::kLost);
}

TEST_F(TrackLifecycleTest, ConsistentDisagreeingFixesOnTwoLandmarksReinitialiseAfterThree) {
  apply(agreeing({0.0, 0.0, 0.0}), 0.0);
  const geometry::Pose2 elsewhere(20.0, 0.0, 0.0);
  for (int k = 1; k < options.reinit_after_rejected_fixes; ++k) {
    const FrameResult r = apply(disagreeing(elsewhere, 2), 0.1 * k);
    EXPECT_FALSE(r.reinitialised) << k;
    EXPECT_NEAR(r.pose.x, 0.0, 1e-9);
  }
  const FrameResult r = apply(disagreeing(elsewhere, 2), 0.3);
  EXPECT_TRUE(r.reinitialised);
  EXPECT_EQ(r.status, TrackingStatus::kOk);
  EXPECT_NEAR(r.pose.x, 20.0, 1e-9);
}

TEST_F(TrackLifecycleTest, DisagreeingFixesOnOneLandmarkNeedTwiceAsMany) {
  apply(agreeing({0.0, 0.0, 0.0}), 0.0);
  const geometry::Pose2 elsewhere(20.0, 0.0, 0.0);
  const int needed = 2 * options.reinit_after_rejected_fixes;
  for (int k = 1; k < needed; ++k)
    EXPECT_FALSE(apply(disagreeing(elsewhere, 1), 0.1 * k).reinitialised);
  EXPECT_TRUE(apply(disagreeing(elsewhere, 1), 0.1 * needed).reinitialised);
}

TEST_F(TrackLifecycleTest, DisagreeingFixesThatDisagreeWithEachOtherStartTheCountAgain) {
  apply(agreeing({0.0, 0.0, 0.0}), 0.0);
  for (int k = 1; k <= 10; ++k) {
    // Each 5 m from the one before: no consistent other place.
    const FrameResult r = apply(disagreeing({20.0 + 5.0 * k, 0.0, 0.0}, 2), 0.1 * k);
    EXPECT_FALSE(r.reinitialised) << k;
  }
  // An agreeing fix resets the count as well.
  apply(disagreeing({20.0, 0.0, 0.0}, 2), 1.1);
  apply(disagreeing({20.0, 0.0, 0.0}, 2), 1.2);
  apply(agreeing({0.0, 0.0, 0.0}), 1.3);
  EXPECT_FALSE(apply(disagreeing({20.0, 0.0, 0.0}, 2), 1.4).reinitialised);
}

TEST_F(TrackLifecycleTest, AKnownInitialPoseStartsTheFilterWithItsUncertainty) {
  lifecycle.startAt({3.0, 4.0, 0.5}, ekf);
  ASSERT_TRUE(ekf.initialised());
  EXPECT_NEAR(std::sqrt(ekf.covariance()(0, 0)), options.initial_position_sigma_m, 1e-12);
  EXPECT_NEAR(std::sqrt(ekf.covariance()(2, 2)), options.initial_yaw_sigma_deg * M_PI / 180.0,
              1e-12);
}

}  // namespace
}  // namespace parkloc::localize
