#pragma once
// Where a tracking vehicle expects to be when a frame set arrives: the pose its localization
// estimated at the frame set before, carried forward by wheel odometry. Text spotting can then
// read each floor box against the few numbers the map places near it (map/placed_texts.h).
// Only what was known before the frame is used: its own estimate never is.
#include <optional>
#include <vector>

#include "geometry/pose.h"
#include "io/odometry_csv.h"
#include "io/tum.h"

namespace parkloc::eval {

struct PosePredictionOptions {
  // An estimate older than this predicts nothing: the run had lost its fix.
  double max_age_s = 0.5;
  // An estimate this close to the frame's own time is the frame's (timestamps in files are
  // rounded); the one before it is used.
  double same_time_s = 1e-6;
};

class PosePrediction {
 public:
  // `estimates`: a localization run's poses (TUM, sorted by time); `odometry`: the drive's.
  PosePrediction(std::vector<io::StampedPose> estimates, std::vector<OdometrySample> odometry,
                 const PosePredictionOptions& options = {});

  // The map_from_vehicle pose predicted for `timestamp` from the last estimate before it;
  // empty when there is none recent enough.
  std::optional<geometry::Pose2> at(double timestamp) const;

 private:
  std::vector<io::StampedPose> estimates_;
  std::vector<OdometrySample> odometry_;
  PosePredictionOptions options_;
};

}  // namespace parkloc::eval
