#include "localize/search_window.h"

#include <gtest/gtest.h>

#include "localize/pose_solver.h"
#include "synthetic_scene.h"

namespace parkloc::localize {
namespace {

constexpr double kDeg = M_PI / 180.0;

OdometrySample sample(double t, double speed, double yaw_rate) {
  OdometrySample s;
  s.timestamp = t;
  s.speed = speed;
  s.yaw_rate = yaw_rate;
  return s;
}

TEST(IntegrateOdometry, StraightAheadCoversSpeedTimesTime) {
  const auto motion = integrateOdometry(sample(0.0, 2.0, 0.0), {}, 1.0, 1.5);
  ASSERT_TRUE(motion.has_value());
  EXPECT_NEAR(motion->x, 1.0, 1e-12);
  EXPECT_NEAR(motion->y, 0.0, 1e-12);
  EXPECT_NEAR(motion->yaw, 0.0, 1e-12);
}

TEST(IntegrateOdometry, AConstantTurnFollowsTheCircle) {
  // A quarter circle of radius 4 m in one second: 2 pi m/s at pi/2 rad/s.
  const auto motion = integrateOdometry(sample(0.0, 2.0 * M_PI, M_PI / 2), {}, 0.0, 1.0);
  ASSERT_TRUE(motion.has_value());
  EXPECT_NEAR(motion->x, 4.0, 1e-9);
  EXPECT_NEAR(motion->y, 4.0, 1e-9);
  EXPECT_NEAR(motion->yaw, M_PI / 2, 1e-12);
}

TEST(IntegrateOdometry, EachSampleHoldsFromItsTimestamp) {
  // 1 m/s until 0.2 s, then 3 m/s: 0.2 + 0.3 * 3 = 1.1 m by 0.5 s.
  const auto motion = integrateOdometry(sample(-0.1, 1.0, 0.0), {sample(0.2, 3.0, 0.0)}, 0.0, 0.5);
  ASSERT_TRUE(motion.has_value());
  EXPECT_NEAR(motion->x, 1.1, 1e-12);
}

TEST(IntegrateOdometry, NothingWithoutOdometryOrBackwards) {
  EXPECT_FALSE(integrateOdometry(std::nullopt, {}, 0.0, 1.0).has_value());
  EXPECT_FALSE(integrateOdometry(sample(0.0, 1.0, 0.0), {}, 1.0, 0.5).has_value());
}

// Observations of one camera only, as a search turn makes them.
std::vector<LandmarkObservation> seenBy(const std::vector<LandmarkObservation>& all, int camera) {
  std::vector<LandmarkObservation> out;
  for (const auto& o : all)
    if (o.camera == camera) out.push_back(o);
  return out;
}

TEST(SearchWindow, TextsSeenEarlierSolveTheCurrentPoseExactly) {
  const auto rig = geometry::defaultRig();
  const auto map = testing::aisleMap();
  // The vehicle drives 0.8 m and turns 5 degrees between two frame sets; the front camera
  // is searched first, then the rear one.
  const geometry::Pose2 before(10.0, 0.2, 0.05), motion(0.8, 0.03, 5.0 * kDeg);
  const geometry::Pose2 now = before * motion;
  const auto front_before = seenBy(testing::observeExactly(rig, map, before), 0);
  const auto rear_now = seenBy(testing::observeExactly(rig, map, now), 1);
  ASSERT_FALSE(front_before.empty());
  ASSERT_FALSE(rear_now.empty());

  SearchWindow window(3);
  window.add(front_before);
  window.advance(motion);
  const auto combined = window.combine(rig, rear_now);
  ASSERT_EQ(combined.current, rear_now.size());
  ASSERT_EQ(combined.observations.size(), rear_now.size() + front_before.size());
  ASSERT_EQ(combined.rig.cameras.size(), 2 * rig.cameras.size());
  // The earlier texts alone already give the current pose: they were carried correctly.
  std::vector<LandmarkObservation> earlier(combined.observations.begin() + combined.current,
                                           combined.observations.end());
  for (const auto& result :
       {solvePose(combined.rig, combined.observations), solvePose(combined.rig, earlier)}) {
    ASSERT_TRUE(result.ok) << result.failure;
    EXPECT_LT((result.pose.translation() - now.translation()).norm(), 1e-3);
    EXPECT_LT(std::abs(geometry::wrapAngle(result.pose.yaw - now.yaw)), 0.01 * kDeg);
  }
}

TEST(SearchWindow, KeepsTheLastFramesAndForgetsWhenTheMotionIsUnknown) {
  const auto rig = geometry::defaultRig();
  const auto obs = testing::observeExactly(rig, testing::aisleMap(), geometry::Pose2(10, 0, 0));
  ASSERT_FALSE(obs.empty());
  SearchWindow window(2);
  for (int k = 0; k < 3; ++k) {
    window.advance(geometry::Pose2(0.1, 0.0, 0.0));
    window.add(obs);
  }
  EXPECT_EQ(window.frames(), 2u);
  window.add({});  // nothing seen: nothing stored
  EXPECT_EQ(window.frames(), 2u);
  window.advance(std::nullopt);
  EXPECT_TRUE(window.empty());
}

}  // namespace
}  // namespace parkloc::localize
