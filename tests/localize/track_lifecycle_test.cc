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

// A fix whose inliers include these landmarks read by OCR (and fits of others, unnamed).
PoseFix readFixAt(const geometry::Pose2& pose, std::vector<std::string> read) {
  PoseFix fix = fixAt(pose);
  fix.landmarks = read;
  fix.read_landmarks = std::move(read);
  return fix;
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
  EXPECT_FALSE(r.odometry);
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
  // Every pose comes with the filter's odometry estimates: at their priors here.
  ASSERT_TRUE(r.odometry);
  EXPECT_EQ(r.odometry->yaw_rate_bias, ekf.yawRateBias());
  EXPECT_EQ(r.odometry->speed_scale, ekf.speedScale());
  EXPECT_NEAR(r.odometry->yaw_rate_bias_sigma, std::sqrt(ekf.yawRateBiasVariance()), 1e-15);
  EXPECT_GT(r.odometry->speed_scale_sigma, 0.0);
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

// A misreading ("B005" read as "C005") starts the filter at C005's place from that one
// landmark. Fits at the places the wrong pose predicts agree with it (they read nothing),
// while the texts read there place the vehicle elsewhere: the tentative track re-initialises
// at once on two such reads, where a confirmed one waits for three frame sets.
TEST_F(TrackLifecycleTest, AWrongFirstFixFromOneLandmarkIsTentativeAndReadsElsewhereRescueIt) {
  const geometry::Pose2 wrong(10.0, 5.0, 0.0), truth(10.0, 0.0, 0.0);
  FrameFixes first;
  first.agreeing = readFixAt(wrong, {"C005"});
  FrameResult r = apply(first, 0.0);
  EXPECT_TRUE(r.reinitialised);
  EXPECT_TRUE(r.tentative);
  EXPECT_TRUE(lifecycle.tentative());

  // Fits of C004 and C006 agree with the wrong pose; B004 and B006 are read elsewhere.
  FrameFixes next;
  next.agreeing = fixAt(wrong);
  next.agreeing->landmarks = {"C004", "C006"};
  next.disagreeing = readFixAt(truth, {"B004", "B006"});
  next.disagreeing_landmarks = 2;
  r = apply(next, 0.1);
  EXPECT_TRUE(r.reinitialised);
  EXPECT_EQ(r.status, TrackingStatus::kOk);
  EXPECT_NEAR(r.pose.y, 0.0, 1e-9);
  // Two distinct landmarks read: the new track is confirmed.
  EXPECT_FALSE(r.tentative);
}

TEST_F(TrackLifecycleTest, ATentativeTrackTakesTwoConsistentSingleLandmarkReadsToMove) {
  const geometry::Pose2 wrong(10.0, 5.0, 0.0), truth(10.0, 0.0, 0.0);
  FrameFixes first;
  first.agreeing = readFixAt(wrong, {"C005"});
  apply(first, 0.0);
  FrameFixes one;
  one.agreeing = fixAt(wrong);
  one.disagreeing = readFixAt(truth, {"B004"});
  one.disagreeing_landmarks = 1;
  FrameResult r = apply(one, 0.1);
  EXPECT_FALSE(r.reinitialised);
  EXPECT_NEAR(r.pose.y, 5.0, 1e-6);
  EXPECT_TRUE(r.tentative);
  one.disagreeing = readFixAt(truth, {"B006"});
  r = apply(one, 0.2);
  EXPECT_TRUE(r.reinitialised);
  EXPECT_NEAR(r.pose.y, 0.0, 1e-9);
  // The new track rests on one read landmark: tentative itself.
  EXPECT_TRUE(r.tentative);
}

// A right first fix from one landmark: fits and rereads of the same landmark leave it
// tentative, a second landmark read with it confirms it; after that a single disagreeing
// landmark needs the confirmed track's count again.
TEST_F(TrackLifecycleTest, ARightTentativeTrackIsConfirmedByASecondLandmarkRead) {
  const geometry::Pose2 pose(3.0, 1.0, 0.2);
  FrameFixes f;
  f.agreeing = readFixAt(pose, {"B005"});
  EXPECT_TRUE(apply(f, 0.0).tentative);
  f.agreeing = readFixAt(pose, {"B005"});  // read again: the same landmark
  EXPECT_TRUE(apply(f, 0.1).tentative);
  f.agreeing = fixAt(pose);  // fits of other landmarks read nothing
  f.agreeing->landmarks = {"B004", "B006"};
  EXPECT_TRUE(apply(f, 0.2).tentative);
  f.agreeing = readFixAt(pose, {"B006"});
  const FrameResult r = apply(f, 0.3);
  EXPECT_FALSE(r.tentative);
  EXPECT_FALSE(lifecycle.tentative());
  EXPECT_NEAR(r.pose.x, 3.0, 1e-6);

  FrameFixes elsewhere;
  elsewhere.disagreeing = readFixAt({20.0, 1.0, 0.2}, {"D001"});
  elsewhere.disagreeing_landmarks = 1;
  for (int k = 1; k < 2 * options.reinit_after_rejected_fixes; ++k)
    EXPECT_FALSE(apply(elsewhere, 0.3 + 0.1 * k).reinitialised) << k;
}

TEST_F(TrackLifecycleTest, AFirstFixFromTwoReadLandmarksIsConfirmedAtOnce) {
  FrameFixes f;
  f.agreeing = readFixAt({1.0, 2.0, 0.0}, {"B005", "B006"});
  EXPECT_FALSE(apply(f, 0.0).tentative);
}

TEST_F(TrackLifecycleTest, AKnownInitialPoseIsNotTentative) {
  lifecycle.startAt({3.0, 4.0, 0.5}, ekf);
  FrameResult r;
  lifecycle.report(ekf, r);
  EXPECT_TRUE(r.has_pose);
  EXPECT_FALSE(r.tentative);
}

}  // namespace
}  // namespace parkloc::localize
