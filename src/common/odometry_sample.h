#pragma once
// One wheel-odometry reading: the vehicle's forward speed and yaw rate at a time. The
// estimator's motion input (localize); io/odometry_csv.h reads and writes it.
namespace parkloc {

struct OdometrySample {
  double timestamp = 0.0;  // seconds
  double speed = 0.0;      // metres per second, forward positive
  double yaw_rate = 0.0;   // radians per second, counter-clockwise positive
};

}  // namespace parkloc
