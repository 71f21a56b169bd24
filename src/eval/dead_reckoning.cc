#include "eval/dead_reckoning.h"

#include <cmath>

namespace parkloc::eval {

void DeadReckoning::step(double dt) {
  if (dt <= 0.0) return;
  const double dyaw = yaw_rate_ * dt;
  // Arc length speed * dt along a circle of turn dyaw; its chord in the start frame.
  double forward = speed_ * dt, left = 0.0;
  if (std::fabs(dyaw) > 1e-9) {
    const double radius = speed_ / yaw_rate_;
    forward = radius * std::sin(dyaw);
    left = radius * (1.0 - std::cos(dyaw));
  }
  const Eigen::Vector2d p = pose_ * Eigen::Vector2d(forward, left);
  pose_ = geometry::Pose2(p.x(), p.y(), pose_.yaw + dyaw);
  time_ += dt;
}

void DeadReckoning::advance(const std::vector<OdometrySample>& samples, double until) {
  for (const OdometrySample& s : samples) {
    if (s.timestamp <= time_ || s.timestamp > until) continue;
    if (!std::isfinite(s.speed) || !std::isfinite(s.yaw_rate)) continue;
    if (!have_sample_) {
      speed_ = s.speed;
      yaw_rate_ = s.yaw_rate;
      have_sample_ = true;
    }
    step(s.timestamp - time_);
    speed_ = s.speed;
    yaw_rate_ = s.yaw_rate;
  }
  step(until - time_);
}

}  // namespace parkloc::eval
