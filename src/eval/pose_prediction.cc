#include "eval/pose_prediction.h"

#include <algorithm>
#include <utility>

#include "eval/dead_reckoning.h"

namespace parkloc::eval {

PosePrediction::PosePrediction(std::vector<io::StampedPose> estimates,
                               std::vector<OdometrySample> odometry,
                               const PosePredictionOptions& options)
    : estimates_(std::move(estimates)), odometry_(std::move(odometry)), options_(options) {
  std::stable_sort(estimates_.begin(), estimates_.end(),
                   [](const auto& a, const auto& b) { return a.timestamp < b.timestamp; });
}

std::optional<geometry::Pose2> PosePrediction::at(double timestamp) const {
  // The first estimate at the frame's own time or later; the one before it is the last known.
  const auto after =
      std::lower_bound(estimates_.begin(), estimates_.end(), timestamp - options_.same_time_s,
                       [](const io::StampedPose& p, double t) { return p.timestamp < t; });
  if (after == estimates_.begin()) return std::nullopt;
  const io::StampedPose& last = *std::prev(after);
  if (timestamp - last.timestamp > options_.max_age_s) return std::nullopt;
  DeadReckoning carried(geometry::Pose2::fromRigid3(last.pose), last.timestamp);
  carried.advance(odometry_, timestamp);
  return carried.pose();
}

}  // namespace parkloc::eval
