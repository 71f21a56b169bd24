#pragma once
// The odometry factor: the relative motion between two consecutive frame sets' poses against
// the one wheel odometry measured, in the first pose's frame (forward, left, yaw), each over
// its sigma. Wheel odometry errs by a constant share of the distance (the wheel radius, tyre
// pressure) and its gyro by a constant yaw-rate bias; white noise per step cannot model
// either, since both add up along the drive. So the factor corrects the measured motion by the
// drive's odometry calibration, estimated with the poses: the true distance is the measured
// one times (1 + distance_scale), the true yaw change the measured one less yaw_rate_bias
// times the step's duration. Autodiff (the residual is a few lines of trigonometry).
#include <ceres/autodiff_cost_function.h>

#include <cmath>

#include "geometry/pose.h"

namespace parkloc::mapping {

struct OdometrySigmas {
  double forward = 0.0;
  double left = 0.0;
  double yaw = 0.0;
};

// Indices into a drive's odometry calibration parameters.
enum OdometryCalibration { kDistanceScale = 0, kYawRateBias = 1 };

class OdometryFactor {
 public:
  OdometryFactor(const geometry::Pose2& motion, double seconds, const OdometrySigmas& sigmas)
      : motion_(motion), seconds_(seconds), sigmas_(sigmas) {}

  template <typename T>
  bool operator()(const T* from, const T* to, const T* calibration, T* residuals) const {
    using std::atan2;
    using std::cos;
    using std::sin;
    const T c = cos(from[2]), s = sin(from[2]);
    const T dx = to[0] - from[0], dy = to[1] - from[1];
    const T forward = c * dx + s * dy;
    const T left = -s * dx + c * dy;
    const T scale = T(1.0) + calibration[kDistanceScale];
    const T dyaw = to[2] - from[2] - (T(motion_.yaw) - calibration[kYawRateBias] * T(seconds_));
    residuals[0] = (forward - scale * T(motion_.x)) / T(sigmas_.forward);
    residuals[1] = (left - scale * T(motion_.y)) / T(sigmas_.left);
    residuals[2] = atan2(sin(dyaw), cos(dyaw)) / T(sigmas_.yaw);
    return true;
  }

  static ceres::CostFunction* create(const geometry::Pose2& motion, double seconds,
                                     const OdometrySigmas& s) {
    return new ceres::AutoDiffCostFunction<OdometryFactor, 3, 3, 3, 2>(
        new OdometryFactor(motion, seconds, s));
  }

 private:
  geometry::Pose2 motion_;
  double seconds_;
  OdometrySigmas sigmas_;
};

// A weak prior on a drive's odometry calibration: the distance scale and the yaw-rate bias
// near zero, over sigmas that allow what a miscalibrated car shows (so that a drive that sees
// few texts keeps its odometry as measured, and one that sees many learns its error).
struct OdometryCalibrationPrior {
  double distance_scale_sigma = 0.0;
  double yaw_rate_bias_sigma = 0.0;

  template <typename T>
  bool operator()(const T* calibration, T* residuals) const {
    residuals[0] = calibration[kDistanceScale] / T(distance_scale_sigma);
    residuals[1] = calibration[kYawRateBias] / T(yaw_rate_bias_sigma);
    return true;
  }

  static ceres::CostFunction* create(double distance_scale_sigma, double yaw_rate_bias_sigma) {
    return new ceres::AutoDiffCostFunction<OdometryCalibrationPrior, 2, 2>(
        new OdometryCalibrationPrior{distance_scale_sigma, yaw_rate_bias_sigma});
  }
};

}  // namespace parkloc::mapping
