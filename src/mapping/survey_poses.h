#pragma once
// The drive's vehicle poses at its frame sets by wheel odometry alone (dead reckoning from the
// first frame set, the map's origin), and the odometry's motion between consecutive frame
// sets: the first guess of the poses and the odometry factors of the estimation.
#include <string>
#include <vector>

#include "common/odometry_sample.h"
#include "geometry/pose.h"

namespace parkloc::mapping {

struct SurveyPoses {
  std::vector<double> timestamps;
  std::vector<geometry::Pose2> map_from_vehicle;  // one per frame set, the first the identity
  // motion[i]: frame set i+1 in the vehicle frame of frame set i.
  std::vector<geometry::Pose2> motion;
  double distance_m = 0.0;  // path length
};

// Throws InputError naming `drive` when it has no odometry or the odometry does not cover
// its frame sets (it starts after the first or ends before the last by more than `gap_s`).
SurveyPoses deadReckon(const std::vector<OdometrySample>& odometry,
                       const std::vector<double>& timestamps, const std::string& drive,
                       double gap_s = 0.5);

}  // namespace parkloc::mapping
