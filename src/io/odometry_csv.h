#pragma once
// Wheel odometry as CSV with header "timestamp,speed,yaw_rate": seconds, metres per second
// (forward positive), radians per second (counter-clockwise positive).
#include <string>
#include <vector>

namespace parkloc::io {

struct OdometrySample {
  double timestamp = 0.0;
  double speed = 0.0;
  double yaw_rate = 0.0;
};

// Throws InputError naming the file and line for malformed rows, NaN values or timestamps
// out of order.
std::vector<OdometrySample> loadOdometry(const std::string& path);
void saveOdometry(const std::vector<OdometrySample>& samples, const std::string& path);

}  // namespace parkloc::io
