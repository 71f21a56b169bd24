#pragma once
// Wheel odometry as CSV with header "timestamp,speed,yaw_rate": seconds, metres per second
// (forward positive), radians per second (counter-clockwise positive); parkloc::OdometrySample
// (common/odometry_sample.h) in memory.
#include <string>
#include <vector>

#include "common/odometry_sample.h"

namespace parkloc::io {

// Throws InputError naming the file and line for malformed rows, NaN values or timestamps
// out of order.
std::vector<OdometrySample> loadOdometry(const std::string& path);
void saveOdometry(const std::vector<OdometrySample>& samples, const std::string& path);

}  // namespace parkloc::io
