#include "mapping/survey_poses.h"

#include <fmt/format.h>

#include <algorithm>
#include <optional>

#include "common/error.h"
#include "localize/search_window.h"

namespace parkloc::mapping {

SurveyPoses deadReckon(const std::vector<OdometrySample>& odometry,
                       const std::vector<double>& timestamps, const std::string& drive,
                       double gap_s) {
  if (timestamps.empty()) throw InputError(fmt::format("drive {}: no frame sets", drive));
  if (odometry.empty())
    throw InputError(fmt::format(
        "drive {}: no wheel odometry (odometry.csv): the poses between the texts cannot be "
        "told",
        drive));
  if (odometry.front().timestamp > timestamps.front() + gap_s ||
      odometry.back().timestamp < timestamps.back() - gap_s)
    throw InputError(
        fmt::format("drive {}: odometry covers {:.2f}..{:.2f} s, the frame sets {:.2f}..{:.2f} s",
                    drive, odometry.front().timestamp, odometry.back().timestamp,
                    timestamps.front(), timestamps.back()));
  SurveyPoses poses;
  poses.timestamps = timestamps;
  poses.map_from_vehicle.push_back(geometry::Pose2());
  for (size_t i = 1; i < timestamps.size(); ++i) {
    const double t0 = timestamps[i - 1], t1 = timestamps[i];
    // The sample that holds at t0 (the last at or before it; before the first sample, the
    // first holds backwards) and those that arrive in (t0, t1].
    std::optional<OdometrySample> held;
    std::vector<OdometrySample> arriving;
    for (const OdometrySample& s : odometry) {
      if (s.timestamp <= t0)
        held = s;
      else if (s.timestamp <= t1)
        arriving.push_back(s);
    }
    if (!held) held = odometry.front();
    const std::optional<geometry::Pose2> step = localize::integrateOdometry(held, arriving, t0, t1);
    if (!step)
      throw InputError(
          fmt::format("drive {}: frame sets at {:.6f} and {:.6f} out of order", drive, t0, t1));
    poses.motion.push_back(*step);
    poses.map_from_vehicle.push_back(poses.map_from_vehicle.back() * *step);
    poses.distance_m += step->translation().norm();
  }
  return poses;
}

}  // namespace parkloc::mapping
