#pragma once
// Absolute trajectory error as the evo tool computes it (evo_ape, translation part, no
// alignment: estimate and ground truth are both in the map frame): associate poses by
// timestamp, then per-frame position error, its statistics, the signed error along the map's
// x and y axes (the paper's Figure 7) and the yaw error.
#include <utility>
#include <vector>

#include "eval/statistics.h"
#include "io/tum.h"

namespace parkloc::eval {

// evo's `associate`: each `first` timestamp is paired with the closest `second` timestamp
// within `max_difference` seconds, one to one (a second stamp is used at most once). Returns
// index pairs in the order of `first`. Both inputs must be sorted ascending.
std::vector<std::pair<size_t, size_t>> associateTimestamps(const std::vector<double>& first,
                                                           const std::vector<double>& second,
                                                           double max_difference = 0.01);

struct FrameError {
  double timestamp = 0.0;
  double dx = 0.0, dy = 0.0, dz = 0.0;  // estimate minus truth, map frame, metres
  double position = 0.0;                // |translation error|, metres
  double yaw = 0.0;                     // estimate minus truth, wrapped, radians
};

struct TrajectoryError {
  std::vector<FrameError> frames;  // associated frames, in time order
  size_t estimated_poses = 0;
  size_t truth_poses = 0;
  Summary position_m;   // |error|, metres
  Summary abs_x_m;      // |dx|
  Summary abs_y_m;      // |dy|
  Summary abs_yaw_deg;  // |yaw error| in degrees
};

struct TrajectoryErrorOptions {
  double max_time_difference = 0.01;  // seconds, for association
  bool planar = true;                 // ignore z (vehicle poses on a garage level)
};

TrajectoryError trajectoryError(const std::vector<io::StampedPose>& estimate,
                                const std::vector<io::StampedPose>& truth,
                                const TrajectoryErrorOptions& options = {});

// Statistics of already associated frames (e.g. several drives put together).
TrajectoryError errorFromFrames(std::vector<FrameError> frames);

// The statistics of an arbitrary subset of frames (e.g. a condition of Table 8).
TrajectoryError subsetError(const TrajectoryError& all, const std::vector<bool>& keep);

}  // namespace parkloc::eval
