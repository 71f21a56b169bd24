#include "localize/pose_ekf.h"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <cmath>

namespace parkloc::localize {
namespace {

Eigen::Vector3d innovation(const geometry::Pose2& fix, const geometry::Pose2& pose) {
  return {fix.x - pose.x, fix.y - pose.y, geometry::wrapAngle(fix.yaw - pose.yaw)};
}

}  // namespace

void PoseEkf::initialise(const geometry::Pose2& pose, const Eigen::Matrix3d& covariance,
                         double time) {
  pose_ = pose;
  covariance_ = covariance;
  time_ = time;
  initialised_ = true;
}

void PoseEkf::predictWithOdometry(double speed, double yaw_rate, double dt) {
  if (!(dt > 0.0)) return;
  const double yaw0 = pose_.yaw;
  const double dyaw = yaw_rate * dt;
  // Arc of the unicycle; its chord for small turns (sin(x)/x -> 1).
  const double half = 0.5 * dyaw;
  const double chord = std::abs(half) < 1e-9 ? 1.0 : std::sin(half) / half;
  const double distance = speed * dt * chord;
  const double heading = yaw0 + half;
  pose_ = geometry::Pose2(pose_.x + distance * std::cos(heading),
                          pose_.y + distance * std::sin(heading), yaw0 + dyaw);

  // Jacobians of the motion (chord approximation) w.r.t. the state and the inputs.
  Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
  F(0, 2) = -distance * std::sin(heading);
  F(1, 2) = distance * std::cos(heading);
  Eigen::Matrix<double, 3, 2> G;
  G << dt * std::cos(heading), -0.5 * distance * dt * std::sin(heading),  //
      dt * std::sin(heading), 0.5 * distance * dt * std::cos(heading),    //
      0.0, dt;
  const double speed_sigma =
      std::hypot(options_.speed_sigma, options_.speed_scale_sigma * std::abs(speed));
  const Eigen::Vector2d input_variance(speed_sigma * speed_sigma,
                                       options_.yaw_rate_sigma * options_.yaw_rate_sigma);
  covariance_ = F * covariance_ * F.transpose() + G * input_variance.asDiagonal() * G.transpose();
}

void PoseEkf::predictWithoutOdometry(double dt) {
  if (!(dt > 0.0)) return;
  const double p = options_.no_odometry_position_sigma, y = options_.no_odometry_yaw_sigma;
  covariance_.diagonal() += Eigen::Vector3d(p * p * dt, p * p * dt, y * y * dt);
}

double PoseEkf::mahalanobis2(const geometry::Pose2& fix, const Eigen::Matrix3d& R) const {
  const Eigen::Vector3d nu = innovation(fix, pose_);
  const Eigen::Matrix3d S = covariance_ + R;
  return nu.dot(S.ldlt().solve(nu));
}

void PoseEkf::update(const geometry::Pose2& fix, const Eigen::Matrix3d& R) {
  const Eigen::Vector3d nu = innovation(fix, pose_);
  const Eigen::Matrix3d S = covariance_ + R;
  const Eigen::Matrix3d K = covariance_ * S.inverse();
  const Eigen::Vector3d dx = K * nu;
  pose_ = geometry::Pose2(pose_.x + dx.x(), pose_.y + dx.y(), pose_.yaw + dx.z());
  // Joseph form keeps the covariance symmetric positive definite.
  const Eigen::Matrix3d I_K = Eigen::Matrix3d::Identity() - K;
  covariance_ = I_K * covariance_ * I_K.transpose() + K * R * K.transpose();
  covariance_ = 0.5 * (covariance_ + covariance_.transpose()).eval();
}

}  // namespace parkloc::localize
