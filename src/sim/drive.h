#pragma once
// Drives through a garage level: a path of straight pieces and circular arcs (aisles,
// 90-degree turns in the cross aisles, a reverse parking manoeuvre), a speed profile with
// limited acceleration and lateral acceleration, and wheel odometry with the noise and bias
// of a real car.
#include <cstdint>
#include <vector>

#include "geometry/pose.h"
#include "io/odometry_csv.h"
#include "sim/garage.h"

namespace parkloc::sim {

struct DriveState {
  double t = 0.0;
  geometry::Pose2 pose;   // map_from_vehicle (rear axle centre on the ground)
  double speed = 0.0;     // m/s, negative when reversing
  double yaw_rate = 0.0;  // rad/s
};

class Drive {
 public:
  explicit Drive(std::vector<DriveState> states) : states_(std::move(states)) {}
  double duration() const { return states_.empty() ? 0.0 : states_.back().t; }
  const std::vector<DriveState>& states() const { return states_; }
  // Linear interpolation between the dense states (clamped to [0, duration]).
  DriveState at(double t) const;

 private:
  std::vector<DriveState> states_;
};

// Plans the drive `spec` on level `level` of the garage; deterministic in `seed`.
Drive planDrive(const Garage& garage, int level, const DriveSpec& spec, uint64_t seed);

struct OdometryNoise {
  double speed_sigma = 0.02;                        // m/s white noise
  double speed_scale_sigma = 0.005;                 // constant scale error per drive (0.5 %)
  double yaw_rate_sigma = 0.2 * M_PI / 180.0;       // rad/s white noise
  double yaw_rate_bias_sigma = 0.1 * M_PI / 180.0;  // constant bias per drive
};

// Wheel odometry sampled at `rate` Hz from the drive, with white noise and a per-drive
// constant speed scale error and yaw-rate bias. Speed reads exactly 0 at standstill.
std::vector<OdometrySample> simulateOdometry(const Drive& drive, double rate, uint64_t seed,
                                                 const OdometryNoise& noise = {});

}  // namespace parkloc::sim
