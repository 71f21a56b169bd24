#include "localize/pose_solver.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include "map/map_noise.h"
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
  // The map is exact, and says so.
  options.assumed_map_position_sigma_m = options.assumed_map_heading_sigma_deg = 0.0;
  options.map_size_sigma = 0.0;
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

TEST(PoseSolver, CornerJacobianMatchesCentralDifferences) {
  const auto rig = geometry::defaultRig();
  const geometry::Pose2 pose(1.0, -0.5, 0.4);
  const Eigen::Vector3d corner(4.5, 0.8, 0.3);  // ahead of the front camera
  const auto at = projectMapCorner(rig.cameras[0], pose, corner);
  ASSERT_TRUE(at);
  const double h = 1e-6;
  for (int k = 0; k < 3; ++k) {
    const auto plus = projectMapCorner(rig.cameras[0], pose, corner + h * Eigen::Vector3d::Unit(k));
    const auto minus = projectMapCorner(rig.cameras[0], pose, corner - h * Eigen::Vector3d::Unit(k));
    ASSERT_TRUE(plus && minus);
    const Eigen::Vector2d numeric = (plus->pixel - minus->pixel) / (2 * h);
    EXPECT_LT((numeric - at->J_pixel_corner.col(k)).norm(), 1e-4 * (1.0 + numeric.norm())) << k;
  }
}

// Observations of the exact scene (1 px noise) whose map corners come from a map with survey
// error `sigma` (map/map_noise.h), as a real map gives them; with `state_accuracy` false the
// observations claim an exact map.
std::vector<LandmarkObservation> observeWithMapError(const geometry::Rig& rig,
                                                     const map::HdMap& exact,
                                                     const map::HdMap& noisy,
                                                     const geometry::Pose2& truth,
                                                     bool state_accuracy, std::mt19937& rng) {
  testing::SpotOptions spot;
  spot.pixel_noise = 1.0;
  auto obs = observeExactly(rig, exact, truth, spot, &rng);
  const FloorHeights floors(noisy);
  for (auto& o : obs) {
    const map::Landmark& l = *noisy.findById(o.landmark_id);
    o.map_corners = floors.cornersAboveFloor(l);
    if (state_accuracy) o.accuracy = l.accuracy;
  }
  return obs;
}

TEST(PoseSolver, MapErrorIsMarginalisedIntoAnHonestCovariance) {
  const auto rig = geometry::defaultRig();
  const auto exact = aisleMap();
  const geometry::Pose2 truth(12.0, 0.2, 0.15);
  std::mt19937 rng(5);
  const int trials = 60;
  double nees_stated = 0.0, nees_ignored = 0.0, error_stated = 0.0, error_ignored = 0.0;
  for (int t = 0; t < trials; ++t) {
    const map::HdMap noisy = map::perturbedMap(exact, {0.10, static_cast<uint64_t>(t)});
    SolverOptions stated;
    stated.pixel_sigma = 1.0;
    SolverOptions ignored = stated;  // an exact map assumed: pixel noise only
    ignored.assumed_map_position_sigma_m = ignored.assumed_map_heading_sigma_deg = 0.0;
    ignored.map_size_sigma = 0.0;
    ignored.max_iterations = 50;
    const auto with = solvePose(rig, observeWithMapError(rig, exact, noisy, truth, true, rng),
                                std::nullopt, stated);
    const auto without = solvePose(rig, observeWithMapError(rig, exact, noisy, truth, false, rng),
                                   std::nullopt, ignored);
    ASSERT_TRUE(with.ok && without.ok) << with.failure << without.failure;
    for (const auto* r : {&with, &without}) {
      const Eigen::Vector3d e(r->pose.x - truth.x, r->pose.y - truth.y,
                              geometry::wrapAngle(r->pose.yaw - truth.yaw));
      const double nees = e.dot(r->covariance.inverse() * e);
      (r == &with ? nees_stated : nees_ignored) += nees / trials;
      (r == &with ? error_stated : error_ignored) += e.head<2>().norm() / trials;
    }
    // The map's share is part of the covariance and most of it at 10 cm.
    EXPECT_GT(with.map_covariance.trace(), 0.5 * with.covariance.trace());
    EXPECT_LT((with.covariance - with.map_covariance).trace(), with.covariance.trace());
  }
  // Consistent: the NEES of 3 dof averages 3; claiming an exact map is far off.
  EXPECT_GT(nees_stated, 1.5);
  EXPECT_LT(nees_stated, 5.0);
  EXPECT_GT(nees_ignored, 30.0);
  // Weighting by the map's error is no worse than treating corners as independent.
  EXPECT_LT(error_stated, 1.05 * error_ignored);
}

// A landmark's map corners moved by the map error e (x, y, heading, log width, log height):
// shifted, turned about their centre, stretched along their half-width and half-height.
std::array<Eigen::Vector3d, 4> movedCorners(const std::array<Eigen::Vector3d, 4>& c,
                                            const Eigen::Matrix<double, 5, 1>& e) {
  const Eigen::Vector3d centre = 0.25 * (c[0] + c[1] + c[2] + c[3]);
  const Eigen::Vector3d half_width = 0.25 * (c[1] - c[0] + c[2] - c[3]);
  const Eigen::Vector3d half_height = 0.25 * (c[0] - c[3] + c[1] - c[2]);
  constexpr double kWidthSign[4] = {-1.0, 1.0, 1.0, -1.0};
  constexpr double kHeightSign[4] = {1.0, 1.0, -1.0, -1.0};
  std::array<Eigen::Vector3d, 4> out;
  for (int i = 0; i < 4; ++i) {
    Eigen::Vector3d d = c[i] - centre + kWidthSign[i] * (std::exp(e(3)) - 1.0) * half_width +
                        kHeightSign[i] * (std::exp(e(4)) - 1.0) * half_height;
    const double cs = std::cos(e(2)), sn = std::sin(e(2));
    d = Eigen::Vector3d(cs * d.x() - sn * d.y(), sn * d.x() + cs * d.y(), d.z());
    out[i] = centre + d + Eigen::Vector3d(e(0), e(1), 0.0);
  }
  return out;
}

TEST(PoseSolver, MapTermsPredictHowALandmarksMapErrorMovesTheFix) {
  const auto rig = geometry::defaultRig();
  const auto map = aisleMap();
  const geometry::Pose2 truth(12.0, 0.2, 0.15);
  auto obs = observeExactly(rig, map, truth);
  ASSERT_GE(obs.size(), 3u);
  for (auto& o : obs) o.accuracy = {0.05, 0.5 * kDeg};
  SolverOptions options;
  options.max_iterations = 50;
  const auto exact = refinePose(rig, obs, truth, options);
  ASSERT_TRUE(exact.ok) << exact.failure;
  // Every inlier landmark has a term; with Huber weights of 1 the split is exact.
  EXPECT_FALSE(exact.map_terms.empty());
  Eigen::Matrix3d total = exact.pixel_covariance;
  for (const MapErrorTerm& t : exact.map_terms)
    total += t.J_fix_map * t.variance.asDiagonal() * t.J_fix_map.transpose();
  EXPECT_TRUE(total.isApprox(exact.covariance, 1e-6)) << total << "\n" << exact.covariance;

  // One landmark's map entry off by e: the fix moves by J_fix_map e (to first order).
  const std::string id = obs.front().landmark_id;
  Eigen::Matrix<double, 5, 1> e;
  e << 0.01, -0.006, 0.3 * kDeg, 0.01, -0.01;
  auto moved = obs;
  for (auto& o : moved)
    if (o.landmark_id == id) o.map_corners = movedCorners(o.map_corners, e);
  const auto off = refinePose(rig, moved, truth, options);
  ASSERT_TRUE(off.ok) << off.failure;
  const auto term = std::find_if(exact.map_terms.begin(), exact.map_terms.end(),
                                 [&](const MapErrorTerm& t) { return t.landmark_id == id; });
  ASSERT_NE(term, exact.map_terms.end());
  const Eigen::Vector3d predicted = term->J_fix_map * e;
  const Eigen::Vector3d actual(off.pose.x - exact.pose.x, off.pose.y - exact.pose.y,
                               geometry::wrapAngle(off.pose.yaw - exact.pose.yaw));
  EXPECT_GT(actual.head<2>().norm(), 2e-4);  // the error does move the fix
  EXPECT_LT((predicted - actual).norm(), 0.05 * actual.norm() + 1e-5)
      << predicted.transpose() << " against " << actual.transpose();
}

TEST(PoseSolver, ExactMapStatedHasNoMapCovariance) {
  const auto rig = geometry::defaultRig();
  const auto map = aisleMap();
  const geometry::Pose2 truth(20.0, -0.8, -0.25);
  auto obs = observeExactly(rig, map, truth);
  for (auto& o : obs) o.accuracy = {0.0, 0.0};
  SolverOptions options;
  options.map_size_sigma = 0.0;
  const auto result = solvePose(rig, obs, std::nullopt, options);
  ASSERT_TRUE(result.ok) << result.failure;
  EXPECT_LT((result.pose.translation() - truth.translation()).norm(), 1e-3);
  EXPECT_LT(result.map_covariance.norm(), 1e-12 * result.covariance.norm() + 1e-18);
}

}  // namespace
}  // namespace parkloc::localize
