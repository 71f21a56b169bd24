#include "eval/trajectory_metrics.h"

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/pose.h"

namespace parkloc::eval {
namespace {

io::StampedPose pose(double t, double x, double y, double yaw) {
  return {t, geometry::Pose2(x, y, yaw).toRigid3()};
}

TEST(Trajectory, AssociationPicksTheClosestStampWithinTheLimit) {
  const std::vector<double> estimate = {0.0, 0.1, 0.2, 0.3};
  const std::vector<double> truth = {0.004, 0.095, 0.1, 0.25, 0.308};
  const auto pairs = associateTimestamps(estimate, truth, 0.01);
  using P = std::pair<size_t, size_t>;
  EXPECT_EQ(pairs, std::vector<P>({P{0, 0}, P{1, 2}, P{3, 4}}));
}

TEST(Trajectory, AssociationIsOneToOne) {
  const auto pairs = associateTimestamps({1.0, 1.001}, {1.0005}, 0.01);
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0].first, 0u);
}

TEST(Trajectory, HandComputedErrors) {
  const std::vector<io::StampedPose> truth = {pose(0.0, 0, 0, 0), pose(0.1, 1, 0, 0.5),
                                              pose(0.2, 2, 0, -3.1)};
  // Errors: (0.03, 0.04) -> 0.05; (0, -0.1) -> 0.1; none for t=0.2 (no estimate); an
  // estimate at 0.5 has no truth. Yaw: +1 degree; 0.5 -> -3.1 + 0.1 wraps across pi.
  const double deg = M_PI / 180.0;
  const std::vector<io::StampedPose> estimate = {pose(0.002, 0.03, 0.04, deg),
                                                 pose(0.1, 1, -0.1, 0.5), pose(0.5, 9, 9, 0)};
  const TrajectoryError e = trajectoryError(estimate, truth);
  ASSERT_EQ(e.frames.size(), 2u);
  EXPECT_EQ(e.estimated_poses, 3u);
  EXPECT_EQ(e.truth_poses, 3u);
  EXPECT_DOUBLE_EQ(e.frames[0].timestamp, 0.0);
  EXPECT_NEAR(e.frames[0].dx, 0.03, 1e-12);
  EXPECT_NEAR(e.frames[0].dy, 0.04, 1e-12);
  EXPECT_NEAR(e.frames[1].dy, -0.1, 1e-12);
  EXPECT_NEAR(e.position_m.mean, 0.075, 1e-12);
  EXPECT_NEAR(e.position_m.rmse, std::sqrt((0.0025 + 0.01) / 2.0), 1e-12);
  EXPECT_NEAR(e.position_m.max, 0.1, 1e-12);
  EXPECT_NEAR(e.abs_x_m.mean, 0.015, 1e-12);
  EXPECT_NEAR(e.abs_y_m.mean, 0.07, 1e-12);
  EXPECT_NEAR(e.abs_yaw_deg.mean, 0.5, 1e-9);
}

TEST(Trajectory, YawErrorWrapsAroundPi) {
  const TrajectoryError e =
      trajectoryError({pose(0.0, 0, 0, M_PI - 0.01)}, {pose(0.0, 0, 0, -M_PI + 0.01)});
  ASSERT_EQ(e.frames.size(), 1u);
  EXPECT_NEAR(e.frames[0].yaw, -0.02, 1e-9);
}

TEST(Trajectory, SubsetKeepsOnlyTheMarkedFrames) {
  const std::vector<io::StampedPose> truth = {pose(0, 0, 0, 0), pose(1, 0, 0, 0)};
  const std::vector<io::StampedPose> estimate = {pose(0, 0.1, 0, 0), pose(1, 0.3, 0, 0)};
  const TrajectoryError all = trajectoryError(estimate, truth);
  const TrajectoryError second = subsetError(all, {false, true});
  ASSERT_EQ(second.frames.size(), 1u);
  EXPECT_NEAR(second.position_m.mean, 0.3, 1e-12);
  EXPECT_NEAR(all.position_m.mean, 0.2, 1e-12);
}

}  // namespace
}  // namespace parkloc::eval
