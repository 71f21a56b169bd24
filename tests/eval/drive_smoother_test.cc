#include "eval/drive_smoother.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

namespace parkloc::eval {
namespace {

std::vector<OdometrySample> constantOdometry(double speed, double yaw_rate, double t1, double hz) {
  std::vector<OdometrySample> out;
  for (int i = 0; i <= static_cast<int>(t1 * hz); ++i) out.push_back({i / hz, speed, yaw_rate});
  return out;
}

TEST(DriveSmoother, HeldOdometryIntegratesTheArc) {
  const auto odometry = constantOdometry(1.0, 0.5, 3.0, 50.0);
  const OdometryMotion m = integrateHeldOdometry(odometry, 0.5, 2.5, 0.0, 1.0, {});
  EXPECT_NEAR(m.delta(0), std::sin(1.0) / 0.5, 1e-9);
  EXPECT_NEAR(m.delta(1), (1.0 - std::cos(1.0)) / 0.5, 1e-9);
  EXPECT_NEAR(m.delta(2), 1.0, 1e-12);
  // The bias slows the turn; the scale lengthens the path.
  const OdometryMotion biased = integrateHeldOdometry(odometry, 0.5, 2.5, 0.1, 1.02, {});
  EXPECT_NEAR(biased.delta(2), 0.8, 1e-12);
  EXPECT_GT(m.covariance(1, 1), 0.0);
}

TEST(DriveSmoother, NoFixNoSmoothing) {
  std::vector<SmootherFrame> frames(3);
  for (int k = 0; k < 3; ++k) frames[k].timestamp = k;
  EXPECT_FALSE(smoothDrive(frames, constantOdometry(1.0, 0.0, 3.0, 10.0), {}).has_value());
}

TEST(DriveSmoother, OdometryAveragesTheMapErrorsOfSuccessiveLandmarks) {
  // A straight drive at 1 m/s past a landmark every 2.5 m, each frame set's fix resting on the
  // nearest one: z = truth + (its map error) + pixel noise. One landmark's error is common to
  // its fixes; odometry ties the landmarks together, so the smoothed drive is far better
  // than any fix.
  std::mt19937 rng(11);
  std::normal_distribution<double> map_error(0.0, 0.10), pixel(0.0, 0.01);
  const double hz = 10.0, duration = 30.0;
  std::vector<Eigen::Vector2d> errors;
  for (int l = 0; l < 20; ++l) errors.emplace_back(map_error(rng), map_error(rng));
  std::vector<SmootherFrame> frames;
  double fix_error = 0.0;
  for (int k = 0; k < static_cast<int>(duration * hz); ++k) {
    const double t = k / hz, x = t;
    const int l = static_cast<int>(std::lround(x / 2.5));
    localize::FusedFix fix;
    fix.pose = {x + errors[l].x() + pixel(rng), errors[l].y() + pixel(rng), 0.0};
    fix.pixel_covariance = Eigen::Vector3d(1e-4, 1e-4, 1e-6).asDiagonal();
    localize::MapErrorTerm term;
    term.landmark_id = "L" + std::to_string(l);
    term.J_fix_map(0, 0) = term.J_fix_map(1, 1) = 1.0;
    term.variance << 0.01, 0.01, 0.0, 0.0, 0.0;
    fix.map_terms = {term};
    fix_error += std::hypot(fix.pose.x - x, fix.pose.y) / (duration * hz);
    frames.push_back({t, fix.pose, {fix}});
  }
  const auto smoothed = smoothDrive(frames, constantOdometry(1.0, 0.0, duration, 50.0), {});
  ASSERT_TRUE(smoothed.has_value());
  EXPECT_TRUE(smoothed->converged);
  double error = 0.0;
  for (size_t k = 0; k < frames.size(); ++k)
    error += std::hypot(smoothed->poses[k].x - frames[k].timestamp, smoothed->poses[k].y) /
             static_cast<double>(frames.size());
  // What no estimator can undo: the mean of the landmarks' errors (odometry moves every
  // pose with the others). The smoothed drive is off by about that, not by each fix's own.
  Eigen::Vector2d common = Eigen::Vector2d::Zero();
  const int landmarks = static_cast<int>(std::lround(duration / 2.5)) + 1;
  for (int l = 0; l < landmarks; ++l) common += errors[l] / landmarks;
  for (size_t k = 0; k < frames.size(); ++k)
    EXPECT_LT(
        (Eigen::Vector2d(smoothed->poses[k].x - frames[k].timestamp, smoothed->poses[k].y) - common)
            .norm(),
        0.03);
  EXPECT_GT(fix_error, 0.06);
  EXPECT_LT(error, 0.6 * fix_error) << error << " against " << fix_error;
}

}  // namespace
}  // namespace parkloc::eval
