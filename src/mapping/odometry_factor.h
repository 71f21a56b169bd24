#pragma once
// The odometry factor: the relative motion between two consecutive frame sets' poses against
// the one wheel odometry measured, in the first pose's frame (forward, left, yaw), each over
// its sigma. Autodiff (the residual is a few lines of trigonometry).
#include <ceres/autodiff_cost_function.h>

#include <cmath>

#include "geometry/pose.h"

namespace parkloc::mapping {

struct OdometrySigmas {
  double forward = 0.0;
  double left = 0.0;
  double yaw = 0.0;
};

class OdometryFactor {
 public:
  OdometryFactor(const geometry::Pose2& motion, const OdometrySigmas& sigmas)
      : motion_(motion), sigmas_(sigmas) {}

  template <typename T>
  bool operator()(const T* from, const T* to, T* residuals) const {
    using std::atan2;
    using std::cos;
    using std::sin;
    const T c = cos(from[2]), s = sin(from[2]);
    const T dx = to[0] - from[0], dy = to[1] - from[1];
    const T forward = c * dx + s * dy;
    const T left = -s * dx + c * dy;
    const T dyaw = to[2] - from[2] - T(motion_.yaw);
    residuals[0] = (forward - T(motion_.x)) / T(sigmas_.forward);
    residuals[1] = (left - T(motion_.y)) / T(sigmas_.left);
    residuals[2] = atan2(sin(dyaw), cos(dyaw)) / T(sigmas_.yaw);
    return true;
  }

  static ceres::CostFunction* create(const geometry::Pose2& motion, const OdometrySigmas& s) {
    return new ceres::AutoDiffCostFunction<OdometryFactor, 3, 3, 3>(new OdometryFactor(motion, s));
  }

 private:
  geometry::Pose2 motion_;
  OdometrySigmas sigmas_;
};

}  // namespace parkloc::mapping
