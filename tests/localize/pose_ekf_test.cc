#include "localize/pose_ekf.h"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <random>

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

// A drive along a gentle S-curve at 2 m/s with odometry at 50 Hz whose yaw rate reads
// true + bias + white noise and whose speed reads true / scale + white noise; a pose fix
// (the true pose plus Gaussian noise of covariance R) every `fix_every` samples.
struct OdometryErrors {
  double yaw_rate_bias = 0.0;
  double speed_scale = 1.0;
};

struct SimulatedDrive {
  PoseEkf ekf;
  geometry::Pose2 truth;
  std::vector<double> nees;  // after every fix
};

SimulatedDrive drive(const EkfOptions& options, const OdometryErrors& errors, int fix_every,
                     double seconds, unsigned seed) {
  constexpr double kDt = 0.02, kSpeed = 2.0;
  const double yaw_sigma = 0.5 * M_PI / 180.0, position_sigma = 0.02;
  const Eigen::Matrix3d R = Eigen::Vector3d(position_sigma * position_sigma,
                                            position_sigma * position_sigma, yaw_sigma * yaw_sigma)
                                .asDiagonal();
  std::mt19937 rng(seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  SimulatedDrive d{PoseEkf(options), geometry::Pose2(0.0, 0.0, 0.0), {}};
  d.ekf.initialise(d.truth, R, 0.0);
  const int steps = static_cast<int>(std::lround(seconds / kDt));
  for (int i = 1; i <= steps; ++i) {
    const double rate = 0.2 * std::sin(0.3 * i * kDt);
    d.ekf.predictWithOdometry(kSpeed / errors.speed_scale + options.speed_sigma * gauss(rng),
                              rate + errors.yaw_rate_bias + options.yaw_rate_sigma * gauss(rng),
                              kDt);
    // The truth moves on the exact arc of the true inputs (the filter's own motion model).
    PoseEkf exact;
    exact.initialise(d.truth, Eigen::Matrix3d::Zero(), 0.0);
    exact.predictWithOdometry(kSpeed, rate, kDt);
    d.truth = exact.pose();
    if (fix_every > 0 && i % fix_every == 0) {
      const geometry::Pose2 fix(d.truth.x + position_sigma * gauss(rng),
                                d.truth.y + position_sigma * gauss(rng),
                                d.truth.yaw + yaw_sigma * gauss(rng));
      d.ekf.update(fix, R);
      const Eigen::Vector3d e(d.ekf.pose().x - d.truth.x, d.ekf.pose().y - d.truth.y,
                              geometry::wrapAngle(d.ekf.pose().yaw - d.truth.yaw));
      d.nees.push_back(e.dot(d.ekf.covariance().ldlt().solve(e)));
    }
  }
  return d;
}

double fractionInside(const std::vector<double>& nees, double bound) {
  size_t inside = 0;
  for (double v : nees) inside += v <= bound ? 1 : 0;
  return static_cast<double>(inside) / static_cast<double>(nees.size());
}

// 95 % quantile of chi-square with 3 degrees of freedom.
constexpr double kNeesBound = 7.815;

TEST(PoseEkf, OdometryErrorsConvergeFromPoseFixes) {
  // 0.02 rad/s (1.15 deg/s), the bias the fault injection uses (1 sigma of the prior), and
  // a wheel radius 1.5 % off.
  const OdometryErrors errors{0.02, 1.015};
  const EkfOptions options;
  const SimulatedDrive d = drive(options, errors, 5, 60.0, 7);
  // After a minute the filter's own sigmas are a small part of the errors, and the
  // estimates lie within 4 of them (a 1-dof Gaussian leaves that with probability 6e-5).
  const double bias_sigma = std::sqrt(d.ekf.yawRateBiasVariance());
  const double scale_sigma = std::sqrt(d.ekf.speedScaleVariance());
  EXPECT_LT(bias_sigma, 0.1 * errors.yaw_rate_bias);
  EXPECT_NEAR(d.ekf.yawRateBias(), errors.yaw_rate_bias, 4.0 * bias_sigma);
  EXPECT_LT(scale_sigma, 0.2 * (errors.speed_scale - 1.0));
  EXPECT_NEAR(d.ekf.speedScale(), errors.speed_scale, 4.0 * scale_sigma);
  // The pose stays on the truth, within 4 sigma of its covariance, and the covariance is
  // honest over the drive.
  EXPECT_LT(std::hypot(d.ekf.pose().x - d.truth.x, d.ekf.pose().y - d.truth.y),
            4.0 * std::sqrt(d.ekf.covariance().topLeftCorner<2, 2>().trace()));
  EXPECT_GE(fractionInside(d.nees, kNeesBound), 0.9);
}

TEST(PoseEkf, DuringTheLearningDelayFixesMoveThePoseButNotTheOdometryEstimates) {
  // A vehicle standing still whose gyro reads a bias of 0.02 rad/s, a fix of its true pose
  // every 0.1 s. With odometry_learning_delay_s = 1 the bias estimate keeps its prior for the
  // first second (the consider update) while the fixes hold the heading, then learns it.
  EkfOptions options;
  options.odometry_learning_delay_s = 1.0;
  PoseEkf ekf(options);
  const Eigen::Matrix3d R = Eigen::Vector3d(1e-4, 1e-4, 1e-5).asDiagonal();
  ekf.initialise(geometry::Pose2(), R, 0.0);
  double bias_at_delay = 0.0, variance_at_delay = 0.0;
  for (int k = 1; k <= 50; ++k) {
    for (int i = 0; i < 5; ++i) ekf.predictWithOdometry(0.0, 0.02, 0.02);
    ekf.setTime(0.1 * k);
    ekf.update(geometry::Pose2(), R);
    EXPECT_LT(std::abs(ekf.pose().yaw), 0.002 + 3.0 * std::sqrt(ekf.covariance()(2, 2))) << k;
    if (k == 9) {
      bias_at_delay = ekf.yawRateBias();
      variance_at_delay = ekf.yawRateBiasVariance();
    }
  }
  EXPECT_EQ(bias_at_delay, 0.0);
  EXPECT_GE(variance_at_delay, options.yaw_rate_bias_sigma * options.yaw_rate_bias_sigma);
  EXPECT_NEAR(ekf.yawRateBias(), 0.02, 0.005);
  EXPECT_LT(ekf.yawRateBiasVariance(), 0.1 * variance_at_delay);
}

TEST(PoseEkf, WithoutTheOdometryStatesTheSameDriveIsOverconfident) {
  // The same drive with bias and scale fixed (prior and walk 0): the odometry errors are
  // noise the filter does not know of, and most fix frames fall outside the bound.
  EkfOptions options;
  options.yaw_rate_bias_sigma = options.yaw_rate_bias_walk = 0.0;
  options.speed_scale_sigma = options.speed_scale_walk = 0.0;
  const SimulatedDrive d = drive(options, {0.02, 1.015}, 5, 60.0, 7);
  EXPECT_EQ(d.ekf.yawRateBias(), 0.0);
  EXPECT_EQ(d.ekf.speedScale(), 1.0);
  EXPECT_LT(fractionInside(d.nees, kNeesBound), 0.5);
}

TEST(PoseEkf, OdometryErrorPriorsMakeDeadReckoningUncertaintyGrowWithTime) {
  EkfOptions options;
  options.yaw_rate_sigma = options.speed_sigma = 0.0;
  options.yaw_rate_bias_walk = options.speed_scale_walk = 0.0;
  PoseEkf ekf(options);
  ekf.initialise({0.0, 0.0, 0.0}, Eigen::Matrix3d::Zero(), 0.0);
  // Straight ahead at 1 m/s for 2 s: the heading error is b t (variance sigma_b^2 t^2), the
  // distance error (s - 1) t.
  for (int i = 0; i < 100; ++i) ekf.predictWithOdometry(1.0, 0.0, 0.02);
  const double t = 2.0, sb = options.yaw_rate_bias_sigma, ss = options.speed_scale_sigma;
  EXPECT_NEAR(ekf.covariance()(2, 2), sb * sb * t * t, 1e-12);
  EXPECT_NEAR(ekf.fullCovariance()(2, 3), -sb * sb * t, 1e-12);
  EXPECT_NEAR(ekf.covariance()(0, 0), ss * ss * t * t, 1e-12);
  // The bias and scale themselves grow only by their random walks, also without odometry.
  EkfOptions walking;
  walking.yaw_rate_bias_walk = 0.01;
  walking.speed_scale_walk = 0.002;
  PoseEkf w(walking);
  w.initialise({0.0, 0.0, 0.0}, Eigen::Matrix3d::Zero(), 0.0);
  const double bias_before = w.yawRateBiasVariance(), scale_before = w.speedScaleVariance();
  w.predictWithoutOdometry(4.0);
  EXPECT_NEAR(w.yawRateBiasVariance() - bias_before, 0.01 * 0.01 * 4.0, 1e-15);
  EXPECT_NEAR(w.speedScaleVariance() - scale_before, 0.002 * 0.002 * 4.0, 1e-15);
}

TEST(PoseEkf, ReinitialisingKeepsTheOdometryEstimatesAndResetForgetsThem) {
  PoseEkf ekf = drive(EkfOptions{}, {0.02, 1.015}, 5, 30.0, 11).ekf;
  const double bias = ekf.yawRateBias(), scale = ekf.speedScale();
  const Eigen::Matrix2d odometry = ekf.fullCovariance().bottomRightCorner<2, 2>();
  ekf.initialise({5.0, 5.0, 1.0}, Eigen::Matrix3d::Identity(), 0.0);
  EXPECT_EQ(ekf.yawRateBias(), bias);
  EXPECT_EQ(ekf.speedScale(), scale);
  EXPECT_TRUE((ekf.fullCovariance().bottomRightCorner<2, 2>() - odometry).isZero(0.0));
  EXPECT_TRUE((ekf.fullCovariance().topRightCorner<3, 2>().isZero(0.0)));
  ekf.reset();
  EXPECT_FALSE(ekf.initialised());
  EXPECT_EQ(ekf.yawRateBias(), 0.0);
  EXPECT_EQ(ekf.speedScale(), 1.0);
  const EkfOptions defaults;
  EXPECT_NEAR(ekf.yawRateBiasVariance(),
              defaults.yaw_rate_bias_sigma * defaults.yaw_rate_bias_sigma, 1e-15);
  EXPECT_NEAR(ekf.speedScaleVariance(), defaults.speed_scale_sigma * defaults.speed_scale_sigma,
              1e-15);
}

TEST(PoseEkf, PoseUpdateEqualsTheTextbookKalmanUpdateOfTheFullState) {
  PoseEkf ekf;
  ekf.initialise({1.0, 2.0, 0.1}, Eigen::Vector3d(0.04, 0.09, 0.01).asDiagonal(), 0.0);
  for (int i = 0; i < 20; ++i) ekf.predictWithOdometry(1.5, 0.1, 0.05);
  const PoseEkf::StateMatrix P = ekf.fullCovariance();
  const geometry::Pose2 x = ekf.pose();
  const double bias = ekf.yawRateBias(), scale = ekf.speedScale();
  const Eigen::Matrix3d R = Eigen::Vector3d(0.01, 0.02, 0.001).asDiagonal();
  const Eigen::Vector3d innovation(0.1, -0.05, 0.02);
  Eigen::Matrix<double, 3, PoseEkf::kStateSize> H;
  H.setZero();
  H.leftCols<3>().setIdentity();
  const Eigen::Matrix<double, PoseEkf::kStateSize, 3> K =
      P * H.transpose() * (H * P * H.transpose() + R).inverse();
  const PoseEkf::StateVector dx = K * innovation;
  const PoseEkf::StateMatrix expected = (PoseEkf::StateMatrix::Identity() - K * H) * P;
  ekf.update({x.x + innovation(0), x.y + innovation(1), x.yaw + innovation(2)}, R);
  EXPECT_NEAR(ekf.pose().x, x.x + dx(0), 1e-12);
  EXPECT_NEAR(ekf.pose().y, x.y + dx(1), 1e-12);
  EXPECT_NEAR(ekf.pose().yaw, x.yaw + dx(2), 1e-12);
  EXPECT_NEAR(ekf.yawRateBias(), bias + dx(3), 1e-12);
  EXPECT_NEAR(ekf.speedScale(), scale + dx(4), 1e-12);
  EXPECT_TRUE(ekf.fullCovariance().isApprox(expected, 1e-9));
}

TEST(PoseEkf, OdometryErrorJacobiansMatchCentralDifferences) {
  // With only the bias and scale uncertain (identity) the predicted covariance is
  // F P F^T, whose cross terms P'(pose, bias / scale) are the Jacobian columns.
  constexpr double kSpeed = 2.0, kRate = 0.3, kDt = 0.1, kStep = 1e-6;
  EkfOptions o;
  o.yaw_rate_sigma = o.speed_sigma = 0.0;
  o.yaw_rate_bias_walk = o.speed_scale_walk = 0.0;
  o.yaw_rate_bias_sigma = o.speed_scale_sigma = 1.0;
  const geometry::Pose2 start(0.5, -0.2, 0.7);
  PoseEkf ekf(o);
  ekf.initialise(start, Eigen::Matrix3d::Zero(), 0.0);
  ekf.predictWithOdometry(kSpeed, kRate, kDt);
  // The motion with a given bias and scale: the filter at b = 0, s = 1 fed the inputs that
  // bias and scale turn the measured ones into.
  auto moved = [&](double bias, double scale) {
    PoseEkf e;
    e.initialise(start, Eigen::Matrix3d::Zero(), 0.0);
    e.predictWithOdometry(scale * kSpeed, kRate - bias, kDt);
    return e.pose();
  };
  auto difference = [&](const geometry::Pose2& plus,
                        const geometry::Pose2& minus) -> Eigen::Vector3d {
    return Eigen::Vector3d(plus.x - minus.x, plus.y - minus.y,
                           geometry::wrapAngle(plus.yaw - minus.yaw)) /
           (2.0 * kStep);
  };
  const Eigen::Vector3d by_bias = difference(moved(kStep, 1.0), moved(-kStep, 1.0));
  const Eigen::Vector3d by_scale = difference(moved(0.0, 1.0 + kStep), moved(0.0, 1.0 - kStep));
  const Eigen::Matrix<double, 3, 2> analytic = ekf.fullCovariance().topRightCorner<3, 2>();
  EXPECT_NEAR(analytic(2, 0), by_bias(2), 1e-8);
  EXPECT_NEAR(analytic(0, 0), by_bias(0), 1e-8);
  EXPECT_NEAR(analytic(1, 0), by_bias(1), 1e-8);
  EXPECT_NEAR(analytic(0, 1), by_scale(0), 1e-8);
  EXPECT_NEAR(analytic(1, 1), by_scale(1), 1e-8);
  EXPECT_NEAR(analytic(2, 1), 0.0, 1e-12);
}

double smallestEigenvalue(const Eigen::Matrix3d& m) {
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(0.5 * (m + m.transpose()))
      .eigenvalues()
      .minCoeff();
}

TEST(PoseEkf, CovarianceMinimumLiesBelowBoth) {
  std::mt19937 rng(3);
  std::normal_distribution<double> n(0.0, 1.0);
  for (int trial = 0; trial < 50; ++trial) {
    Eigen::Matrix3d a, b;
    for (auto* m : {&a, &b})
      for (int i = 0; i < 9; ++i) (*m)(i / 3, i % 3) = n(rng);
    const Eigen::Matrix3d A = a * a.transpose() + 1e-3 * Eigen::Matrix3d::Identity();
    const Eigen::Matrix3d B = b * b.transpose();
    const Eigen::Matrix3d m = covarianceMinimum(A, B);
    const double scale = A.norm() + B.norm();
    EXPECT_GT(smallestEigenvalue(A - m), -1e-9 * scale);
    EXPECT_GT(smallestEigenvalue(B - m), -1e-9 * scale);
    EXPECT_GT(smallestEigenvalue(m), -1e-9 * scale);
  }
  const Eigen::Matrix3d A = Eigen::Vector3d(1.0, 2.0, 3.0).asDiagonal();
  EXPECT_LT((covarianceMinimum(A, 2.0 * A) - A).norm(), 1e-12);        // B above A: A
  EXPECT_LT((covarianceMinimum(A, 0.5 * A) - 0.5 * A).norm(), 1e-12);  // B below A: B
}

TEST(PoseEkf, RepeatingAFixDoesNotShrinkBelowItsMapPart) {
  // The same landmarks' fix, frame after frame: its pixel part is new each time, its map part
  // (here 5 cm, 0.5 degrees) is not.
  PoseEkf ekf;
  ekf.initialise(geometry::Pose2(0, 0, 0), Eigen::Vector3d(0.04, 0.04, 0.01).asDiagonal(), 0.0);
  const Eigen::Matrix3d map_part = Eigen::Vector3d(0.05 * 0.05, 0.05 * 0.05, 7.6e-5).asDiagonal();
  const Eigen::Matrix3d pixel_part = Eigen::Vector3d(1e-4, 1e-4, 1e-6).asDiagonal();
  for (int i = 0; i < 200; ++i) ekf.update(geometry::Pose2(0, 0, 0), pixel_part + map_part, map_part);
  EXPECT_GT(smallestEigenvalue(ekf.covariance() - map_part), -1e-12);
  // Without the map part stated, 200 fusions average it away.
  PoseEkf naive;
  naive.initialise(geometry::Pose2(0, 0, 0), Eigen::Vector3d(0.04, 0.04, 0.01).asDiagonal(), 0.0);
  for (int i = 0; i < 200; ++i) naive.update(geometry::Pose2(0, 0, 0), pixel_part + map_part);
  EXPECT_LT(naive.covariance()(0, 0), 0.1 * map_part(0, 0));
}

}  // namespace
}  // namespace parkloc::localize

namespace parkloc::localize {
namespace {

// A fix's map term whose landmark error moves it as the landmark's position does.
MapErrorTerm positionTerm(const std::string& id, double sigma) {
  MapErrorTerm t;
  t.landmark_id = id;
  t.J_fix_map(0, 0) = t.J_fix_map(1, 1) = 1.0;
  t.variance << sigma * sigma, sigma * sigma, 0.0, 0.0, 0.0;
  return t;
}

EkfOptions withMapStates(int landmarks) {
  EkfOptions o;
  o.map_error_landmarks = landmarks;
  return o;
}

TEST(PoseEkfMapErrors, RepeatedFixesOfOneLandmarkNeverAverageItsMapError) {
  // A still vehicle and n fixes of one landmark: the pixel noise averages (R / n), the
  // landmark's map error (sigma^2) stays.
  PoseEkf ekf(withMapStates(8));
  const Eigen::Matrix3d R = Eigen::Vector3d(4e-4, 4e-4, 1e-5).asDiagonal();
  const MapErrorTerm term = positionTerm("A", 0.1);
  ekf.initialise({1.0, 2.0, 0.0}, R, {term}, 0.0);
  const int n = 25;
  for (int i = 1; i < n; ++i) ekf.update({1.0, 2.0, 0.0}, R, {term});
  const Eigen::Matrix3d expected =
      R / n + Eigen::Vector3d(0.01, 0.01, 0.0).asDiagonal().toDenseMatrix();
  EXPECT_TRUE(ekf.covariance().isApprox(expected, 1e-9)) << ekf.covariance();
  // As independent fixes they would claim R_total / n.
  EXPECT_GT(ekf.covariance()(0, 0), 10.0 * (R(0, 0) + 0.01) / n);
}

TEST(PoseEkfMapErrors, FixesOfDifferentLandmarksAverageTheirErrors) {
  PoseEkf ekf(withMapStates(8));
  const Eigen::Matrix3d R = Eigen::Vector3d(4e-4, 4e-4, 1e-5).asDiagonal();
  const Eigen::Matrix3d M = Eigen::Vector3d(0.01, 0.01, 0.0).asDiagonal();
  ekf.initialise({0.0, 0.0, 0.0}, R, {positionTerm("A", 0.1)}, 0.0);
  ekf.update({0.0, 0.0, 0.0}, R, {positionTerm("B", 0.1)});
  const Eigen::Matrix2d expected = 0.5 * (R + M).topLeftCorner<2, 2>();
  EXPECT_TRUE(ekf.covariance().topLeftCorner(2, 2).isApprox(expected, 1e-9)) << ekf.covariance();
  // The landmarks' errors are estimated: A's and B's fixes disagreeing by 20 cm puts each
  // landmark's error +-10 cm (half the disagreement to each, equal sigmas).
  PoseEkf split(withMapStates(8));
  split.initialise({0.1, 0.0, 0.0}, R, {positionTerm("A", 0.1)}, 0.0);
  split.update({-0.1, 0.0, 0.0}, R, {positionTerm("B", 0.1)});
  ASSERT_EQ(split.mapErrorLandmarks().size(), 2u);
  EXPECT_NEAR(split.pose().x, 0.0, 1e-9);
  EXPECT_NEAR(split.mapError(0)(0), 0.1 * 0.01 / (0.01 + R(0, 0)), 1e-9);
  EXPECT_NEAR(split.mapError(1)(0), -0.1 * 0.01 / (0.01 + R(0, 0)), 1e-9);
}

TEST(PoseEkfMapErrors, GateDistanceOfANewLandmarkIsThatOfItsWholeCovariance) {
  PoseEkf with(withMapStates(8)), without;
  const Eigen::Matrix3d P = Eigen::Vector3d(1e-3, 2e-3, 1e-4).asDiagonal();
  with.initialise({0.0, 0.0, 0.0}, P, 0.0);
  without.initialise({0.0, 0.0, 0.0}, P, 0.0);
  const Eigen::Matrix3d R = Eigen::Vector3d(4e-4, 4e-4, 1e-5).asDiagonal();
  const MapErrorTerm term = positionTerm("A", 0.1);
  const geometry::Pose2 fix(0.2, -0.1, 0.01);
  const Eigen::Matrix3d whole =
      R + term.J_fix_map * term.variance.asDiagonal() * term.J_fix_map.transpose();
  EXPECT_NEAR(with.mahalanobis2(fix, R, {term}), without.mahalanobis2(fix, whole), 1e-9);
  // Fusing it moves the pose exactly as the plain filter with the whole covariance does.
  with.update(fix, R, {term});
  without.update(fix, whole);
  EXPECT_NEAR(with.pose().x, without.pose().x, 1e-12);
  EXPECT_TRUE(with.covariance().isApprox(without.covariance(), 1e-9));
  // A second fix of the same landmark is then closer than as a stranger: its error is known.
  EXPECT_LT(with.mahalanobis2(fix, R, {term}), without.mahalanobis2(fix, whole));
}

TEST(PoseEkfMapErrors, KeepsTheLandmarksSeenLastAndStaysPositiveDefinite) {
  PoseEkf ekf(withMapStates(2));
  const Eigen::Matrix3d R = Eigen::Vector3d(4e-4, 4e-4, 1e-5).asDiagonal();
  ekf.initialise({0.0, 0.0, 0.0}, R, {positionTerm("A", 0.1)}, 0.0);
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, 0.02);
  const std::vector<std::string> seen = {"B", "A", "C", "D", "C"};
  for (const std::string& id : seen) {
    ekf.predictWithOdometry(1.0, 0.05, 0.5);
    ekf.update({ekf.pose().x + noise(rng), ekf.pose().y + noise(rng), ekf.pose().yaw}, R,
               {positionTerm(id, 0.1)});
  }
  EXPECT_EQ(ekf.mapErrorLandmarks(), (std::vector<std::string>{"C", "D"}));
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(ekf.covariance());
  EXPECT_GT(eigen.eigenvalues().minCoeff(), 0.0);
  // A re-initialisation forgets them.
  ekf.initialise({0.0, 0.0, 0.0}, R, 1.0);
  EXPECT_TRUE(ekf.mapErrorLandmarks().empty());
}

TEST(PoseEkfMapErrors, WithoutMapStatesTheTermsJoinTheFixCovariance) {
  PoseEkf a, b;
  a.initialise({0.0, 0.0, 0.0}, Eigen::Matrix3d::Identity() * 1e-2, 0.0);
  b.initialise({0.0, 0.0, 0.0}, Eigen::Matrix3d::Identity() * 1e-2, 0.0);
  const Eigen::Matrix3d R = Eigen::Vector3d(4e-4, 4e-4, 1e-5).asDiagonal();
  const MapErrorTerm term = positionTerm("A", 0.1);
  a.update({0.1, 0.0, 0.0}, R, {term});
  b.update({0.1, 0.0, 0.0}, R + Eigen::Vector3d(0.01, 0.01, 0.0).asDiagonal().toDenseMatrix());
  EXPECT_TRUE(a.mapErrorLandmarks().empty());
  EXPECT_NEAR(a.pose().x, b.pose().x, 1e-12);
}

}  // namespace
}  // namespace parkloc::localize
