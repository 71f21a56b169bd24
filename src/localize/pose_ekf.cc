#include "localize/pose_ekf.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <cmath>
#include <optional>

namespace parkloc::localize {
namespace {

constexpr int kBias = 3, kScale = 4;

Eigen::Vector3d innovation(const geometry::Pose2& fix, const geometry::Pose2& pose) {
  return {fix.x - pose.x, fix.y - pose.y, geometry::wrapAngle(fix.yaw - pose.yaw)};
}

}  // namespace

PoseEkf::PoseEkf(EkfOptions options) : options_(options) { reset(); }

void PoseEkf::reset() {
  initialised_ = false;
  bias_ = 0.0;
  scale_ = 1.0;
  covariance_.setZero();
  covariance_(kBias, kBias) = options_.yaw_rate_bias_sigma * options_.yaw_rate_bias_sigma;
  covariance_(kScale, kScale) = options_.speed_scale_sigma * options_.speed_scale_sigma;
}

void PoseEkf::initialise(const geometry::Pose2& pose, const Eigen::Matrix3d& covariance,
                         double time) {
  pose_ = pose;
  const Eigen::Matrix2d odometry = covariance_.bottomRightCorner<2, 2>();
  covariance_.setZero();
  covariance_.topLeftCorner<3, 3>() = covariance;
  covariance_.bottomRightCorner<2, 2>() = odometry;
  time_ = time;
  initialised_ = true;
}

void PoseEkf::predictWithOdometry(double speed, double yaw_rate, double dt) {
  if (!(dt > 0.0)) return;
  const double yaw0 = pose_.yaw;
  const double dyaw = (yaw_rate - bias_) * dt;
  // Arc of the unicycle; its chord for small turns (sin(x)/x -> 1).
  const double half = 0.5 * dyaw;
  const double chord = std::abs(half) < 1e-9 ? 1.0 : std::sin(half) / half;
  const double measured_distance = speed * dt * chord;
  const double distance = scale_ * measured_distance;
  const double heading = yaw0 + half;
  pose_ = geometry::Pose2(pose_.x + distance * std::cos(heading),
                          pose_.y + distance * std::sin(heading), yaw0 + dyaw);

  // Jacobians of the motion w.r.t. the state and the inputs. The turn changes both the
  // heading of the chord (half of it) and its length (d chord / d half); the bias enters like
  // the yaw rate with the opposite sign, the scale like the speed.
  const double c = std::cos(heading), s = std::sin(heading);
  const double chord_slope = std::abs(half) < 1e-4
                                 ? -half / 3.0
                                 : (half * std::cos(half) - std::sin(half)) / (half * half);
  const Eigen::Vector2d d_position_d_half(scale_ * speed * dt * chord_slope * c - distance * s,
                                          scale_ * speed * dt * chord_slope * s + distance * c);
  StateMatrix F = StateMatrix::Identity();
  F(0, 2) = -distance * s;
  F(1, 2) = distance * c;
  F.block<2, 1>(0, kBias) = -0.5 * dt * d_position_d_half;
  F(2, kBias) = -dt;
  F(0, kScale) = measured_distance * c;
  F(1, kScale) = measured_distance * s;
  Eigen::Matrix<double, kStateSize, 2> G = Eigen::Matrix<double, kStateSize, 2>::Zero();
  G(0, 0) = scale_ * dt * chord * c;
  G(1, 0) = scale_ * dt * chord * s;
  G.block<2, 1>(0, 1) = 0.5 * dt * d_position_d_half;
  G(2, 1) = dt;
  const Eigen::Vector2d input_variance(options_.speed_sigma * options_.speed_sigma,
                                       options_.yaw_rate_sigma * options_.yaw_rate_sigma);
  covariance_ = F * covariance_ * F.transpose() + G * input_variance.asDiagonal() * G.transpose();
  covariance_(kBias, kBias) += options_.yaw_rate_bias_walk * options_.yaw_rate_bias_walk * dt;
  covariance_(kScale, kScale) += options_.speed_scale_walk * options_.speed_scale_walk * dt;
}

void PoseEkf::predictWithoutOdometry(double dt) {
  if (!(dt > 0.0)) return;
  const double p = options_.no_odometry_position_sigma, y = options_.no_odometry_yaw_sigma,
               b = options_.yaw_rate_bias_walk, k = options_.speed_scale_walk;
  covariance_.diagonal() += StateVector(p * p, p * p, y * y, b * b, k * k) * dt;
}

double PoseEkf::mahalanobis2(const geometry::Pose2& fix, const Eigen::Matrix3d& R) const {
  const Eigen::Vector3d nu = innovation(fix, pose_);
  const Eigen::Matrix3d S = covariance() + R;
  return nu.dot(S.ldlt().solve(nu));
}

void PoseEkf::update(const geometry::Pose2& fix, const Eigen::Matrix3d& R) {
  // H = [I 0]: P H^T is the first three columns of P, H P H^T its top-left block.
  const Eigen::Vector3d nu = innovation(fix, pose_);
  const Eigen::Matrix3d S = covariance() + R;
  const Eigen::Matrix<double, kStateSize, 3> K = covariance_.leftCols<3>() * S.inverse();
  const StateVector dx = K * nu;
  pose_ = geometry::Pose2(pose_.x + dx(0), pose_.y + dx(1), pose_.yaw + dx(2));
  bias_ += dx(kBias);
  scale_ += dx(kScale);
  // Joseph form keeps the covariance symmetric positive definite.
  StateMatrix I_KH = StateMatrix::Identity();
  I_KH.leftCols<3>() -= K;
  covariance_ = I_KH * covariance_ * I_KH.transpose() + K * R * K.transpose();
  covariance_ = 0.5 * (covariance_ + covariance_.transpose()).eval();
}

namespace {

// The generalised eigen decomposition of (B, A): with A = L L^T, L^-1 B L^-T = V diag(lambda)
// V^T. Empty when A is not positive definite.
struct GeneralisedEigen {
  Eigen::Matrix3d L, V;
  Eigen::Vector3d lambda;
};
std::optional<GeneralisedEigen> generalisedEigen(const Eigen::Matrix3d& A,
                                                 const Eigen::Matrix3d& B) {
  const Eigen::LLT<Eigen::Matrix3d> llt(A);
  if (llt.info() != Eigen::Success) return std::nullopt;
  const Eigen::Matrix3d L = llt.matrixL();
  const Eigen::Matrix3d L_inv = L.inverse();
  const Eigen::Matrix3d M = L_inv * B * L_inv.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(0.5 * (M + M.transpose()));
  return GeneralisedEigen{L, eigen.eigenvectors(), eigen.eigenvalues()};
}

// L V diag(lambda) V^T L^T: A with its generalised eigenvalues replaced by `lambda`.
Eigen::Matrix3d recompose(const GeneralisedEigen& g, const Eigen::Vector3d& lambda) {
  return g.L * g.V * lambda.asDiagonal() * g.V.transpose() * g.L.transpose();
}

}  // namespace

Eigen::Matrix3d covarianceMinimum(const Eigen::Matrix3d& A, const Eigen::Matrix3d& B) {
  const auto g = generalisedEigen(A, B);
  if (!g) return Eigen::Matrix3d::Zero();
  return recompose(*g, g->lambda.cwiseMax(0.0).cwiseMin(1.0));
}

void PoseEkf::update(const geometry::Pose2& fix, const Eigen::Matrix3d& R,
                     const Eigen::Matrix3d& map_part) {
  const Eigen::Matrix3d before = covariance();
  update(fix, R);
  if (!map_part.allFinite() || map_part.isZero(0.0)) return;
  floorPoseCovariance(covarianceMinimum(before, map_part));
}

void PoseEkf::floorPoseCovariance(const Eigen::Matrix3d& floor) {
  if (!floor.allFinite() || floor.isZero(0.0)) return;
  // With P = L L^T: P' = L V max(Lambda, 1) V^T L^T, where V Lambda V^T = L^-1 floor L^-T.
  // Then P' >= P and P' >= floor; adding P' - P (>= 0) to the pose block keeps the whole
  // state covariance positive semi-definite.
  const Eigen::Matrix3d P = covariance();
  const auto g = generalisedEigen(P, floor);
  if (!g || g->lambda.maxCoeff() <= 1.0) return;
  const Eigen::Matrix3d raised = recompose(*g, g->lambda.cwiseMax(1.0));
  covariance_.topLeftCorner<3, 3>() += raised - P;
  covariance_ = 0.5 * (covariance_ + covariance_.transpose()).eval();
}

}  // namespace parkloc::localize
