#pragma once
// Odometry-only dead reckoning: the stand-in of Table 5 for a GNSS-denied system without
// OCR. Integrates wheel speed and yaw rate from a known start; its error grows without bound.
#include <vector>

#include "geometry/pose.h"
#include "io/odometry_csv.h"

namespace parkloc::eval {

class DeadReckoning {
 public:
  DeadReckoning(const geometry::Pose2& start, double start_time)
      : pose_(start), time_(start_time) {}

  // Integrates up to `until` with the samples that arrived (sorted, any before the current
  // time are skipped). Each sample's speed and yaw rate hold until the next one; the motion
  // over a step is the exact arc of a constant-speed, constant-turn-rate vehicle.
  void advance(const std::vector<OdometrySample>& samples, double until);

  const geometry::Pose2& pose() const { return pose_; }
  double time() const { return time_; }

 private:
  void step(double dt);

  geometry::Pose2 pose_;
  double time_ = 0.0;
  double speed_ = 0.0;
  double yaw_rate_ = 0.0;
  bool have_sample_ = false;  // before the first sample, its values hold backwards
};

}  // namespace parkloc::eval
