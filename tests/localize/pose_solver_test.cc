#include "localize/pose_solver.h"

#include <gtest/gtest.h>

#include <random>

#include "synthetic_scene.h"

namespace parkloc::localize {
namespace {

using testing::aisleMap;
using testing::observeExactly;

constexpr double kDeg = M_PI / 180.0;

TEST(PoseSolver, ExactDetectionsGiveThePoseWithinAMillimetre) {
  const auto rig = geometry::defaultRig();
  const auto map = aisleMap();
  for (const geometry::Pose2 truth :
       {geometry::Pose2(5.0, 0.3, 0.1), geometry::Pose2(20.0, -0.8, -0.25),
        geometry::Pose2(33.3, 1.0, M_PI - 0.05)}) {
    const auto obs = observeExactly(rig, map, truth);
    ASSERT_GE(obs.size(), 4u);
    const auto result = solvePose(rig, obs);
    ASSERT_TRUE(result.ok) << result.failure;
    EXPECT_TRUE(result.converged);
    EXPECT_LT((result.pose.translation() - truth.translation()).norm(), 1e-3);
    EXPECT_LT(std::abs(geometry::wrapAngle(result.pose.yaw - truth.yaw)), 0.01 * kDeg);
    EXPECT_LT(result.rms_px, 1e-2);
    for (bool in : result.inlier) EXPECT_TRUE(in);
  }
}

TEST(PoseSolver, PillarTextAloneGivesThePose) {
  const auto rig = geometry::defaultRig();
  const auto map = aisleMap();
  const geometry::Pose2 truth(10.0, 0.5, 0.05);
  auto obs = observeExactly(rig, map, truth);
  std::vector<LandmarkObservation> pillars;
  for (const auto& o : obs)
    if (map.findById(o.landmark_id)->surface == map::Surface::kVertical) pillars.push_back(o);
  ASSERT_GE(pillars.size(), 1u);
  const auto result = solvePose(rig, pillars);
  ASSERT_TRUE(result.ok) << result.failure;
  EXPECT_LT((result.pose.translation() - truth.translation()).norm(), 1e-3);
  EXPECT_LT(std::abs(geometry::wrapAngle(result.pose.yaw - truth.yaw)), 0.01 * kDeg);
}

TEST(PoseSolver, SingleObservationClosedFormIsCloseAndRefinementExact) {
  const auto rig = geometry::defaultRig();
  const auto map = aisleMap();
  const geometry::Pose2 truth(7.0, -0.4, 0.3);
  const auto obs = observeExactly(rig, map, truth);
  for (const auto& o : obs) {
    const auto initial = poseFromObservation(rig.cameras[o.camera], o);
    ASSERT_TRUE(initial);
    // Ray casting is exact too for exact pixels (up to float polygons).
    EXPECT_LT((initial->translation() - truth.translation()).norm(), 0.02);
  }
}

TEST(PoseSolver, PixelNoiseGivesAnUnbiasedPoseWithMatchingCovariance) {
  const auto rig = geometry::defaultRig();
  const auto map = aisleMap();
  const geometry::Pose2 truth(12.0, 0.2, 0.15);
  testing::SpotOptions spot;
  spot.pixel_noise = 1.0;
  std::mt19937 rng(11);
  const int trials = 200;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d predicted = Eigen::Matrix3d::Zero();
  SolverOptions options;
  options.pixel_sigma = spot.pixel_noise;
  for (int t = 0; t < trials; ++t) {
    const auto obs = observeExactly(rig, map, truth, spot, &rng);
    const auto result = solvePose(rig, obs, std::nullopt, options);
    ASSERT_TRUE(result.ok) << result.failure;
    const Eigen::Vector3d e(result.pose.x - truth.x, result.pose.y - truth.y,
                            geometry::wrapAngle(result.pose.yaw - truth.yaw));
    sum += e;
    scatter += e * e.transpose();
    predicted += result.covariance;
  }
  const Eigen::Vector3d mean = sum / trials;
  const Eigen::Matrix3d empirical = scatter / trials - mean * mean.transpose();
  predicted /= trials;
  for (int i = 0; i < 3; ++i) {
    const double standard_error = std::sqrt(empirical(i, i) / trials);
    EXPECT_LT(std::abs(mean[i]), 4.0 * standard_error + 1e-6) << "axis " << i;
    // The covariance from the normal matrix matches the spread (Huber barely bites at 1 px).
    EXPECT_GT(empirical(i, i), 0.6 * predicted(i, i)) << "axis " << i;
    EXPECT_LT(empirical(i, i), 1.6 * predicted(i, i)) << "axis " << i;
  }
  EXPECT_LT(std::sqrt(empirical(0, 0)), 0.02);  // a centimetre-level fix at 1 px
}

TEST(PoseSolver, AWronglyAssociatedLandmarkIsAnOutlier) {
  const auto rig = geometry::defaultRig();
  const auto map = aisleMap();
  const geometry::Pose2 truth(15.0, 0.0, 0.0);
  auto obs = observeExactly(rig, map, truth);
  ASSERT_GE(obs.size(), 3u);
  // The first observation's text read as a number 10 m further on.
  const auto* wrong =
      map.withinRadius(truth.translation() + Eigen::Vector2d(10.0, 4.5), 1.0).front();
  obs[0].landmark_id = wrong->id;
  obs[0].map_corners = wrong->corners();
  const auto result = solvePose(rig, obs);
  ASSERT_TRUE(result.ok) << result.failure;
  EXPECT_FALSE(result.inlier[0]);
  EXPECT_LT((result.pose.translation() - truth.translation()).norm(), 1e-3);
}

TEST(PoseSolver, ReportsFailureWithoutObservations) {
  const auto rig = geometry::defaultRig();
  const auto result = solvePose(rig, {});
  EXPECT_FALSE(result.ok);
  EXPECT_FALSE(result.failure.empty());
}

TEST(PoseSolver, ReportsNonConvergenceWithTooFewIterations) {
  const auto rig = geometry::defaultRig();
  const auto map = aisleMap();
  const geometry::Pose2 truth(5.0, 0.3, 0.1);
  const auto obs = observeExactly(rig, map, truth);
  SolverOptions options;
  options.max_iterations = 1;
  const auto result = refinePose(rig, obs, geometry::Pose2(5.5, 0.0, 0.2), options);
  EXPECT_FALSE(result.converged);
  EXPECT_FALSE(result.ok);
  EXPECT_NE(result.failure.find("converge"), std::string::npos);
}

}  // namespace
}  // namespace parkloc::localize
