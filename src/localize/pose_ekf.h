#pragma once
// Extended Kalman filter on the planar pose (x, y, yaw) with wheel odometry (speed, yaw
// rate) as the motion input and absolute pose fixes as measurements. Beyond the paper, which
// has no temporal fusion: it gives a pose every frame (dead reckoning with a growing
// covariance when no text is seen) and a prediction to gate associations against.
#include <Eigen/Core>
#include <optional>

#include "geometry/pose.h"

namespace parkloc::localize {

struct EkfOptions {
  double speed_sigma = 0.05;        // odometry speed noise, m/s (1 sigma)
  double yaw_rate_sigma = 0.01;     // odometry yaw-rate noise, rad/s
  double speed_scale_sigma = 0.02;  // relative speed (wheel radius) error
  // Random walk when no odometry drives the prediction.
  double no_odometry_position_sigma = 0.5;  // m / sqrt(s)
  double no_odometry_yaw_sigma = 0.1;       // rad / sqrt(s)
};

class PoseEkf {
 public:
  explicit PoseEkf(EkfOptions options = {}) : options_(options) {}

  bool initialised() const { return initialised_; }
  void initialise(const geometry::Pose2& pose, const Eigen::Matrix3d& covariance, double time);
  void reset() { initialised_ = false; }

  // Motion over dt seconds with the given speed and yaw rate (unicycle, exact arc).
  void predictWithOdometry(double speed, double yaw_rate, double dt);
  // No odometry: the pose stays, the covariance grows as a random walk.
  void predictWithoutOdometry(double dt);

  // Squared Mahalanobis distance of a pose fix with covariance R from the prediction.
  double mahalanobis2(const geometry::Pose2& fix, const Eigen::Matrix3d& R) const;
  // Standard EKF update with a direct pose measurement (H = I, yaw innovation wrapped).
  void update(const geometry::Pose2& fix, const Eigen::Matrix3d& R);

  const geometry::Pose2& pose() const { return pose_; }
  const Eigen::Matrix3d& covariance() const { return covariance_; }
  double time() const { return time_; }
  void setTime(double time) { time_ = time; }

 private:
  EkfOptions options_;
  bool initialised_ = false;
  geometry::Pose2 pose_;
  Eigen::Matrix3d covariance_ = Eigen::Matrix3d::Identity();
  double time_ = 0.0;
};

}  // namespace parkloc::localize
