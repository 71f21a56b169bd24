#include "eval/trajectory_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/pose.h"

namespace parkloc::eval {
namespace {

void summarizeFrames(TrajectoryError& e) {
  std::vector<double> position, ax, ay, yaw;
  for (const FrameError& f : e.frames) {
    position.push_back(f.position);
    ax.push_back(std::fabs(f.dx));
    ay.push_back(std::fabs(f.dy));
    yaw.push_back(std::fabs(f.yaw) * 180.0 / M_PI);
  }
  e.position_m = summarize(position);
  e.abs_x_m = summarize(ax);
  e.abs_y_m = summarize(ay);
  e.abs_yaw_deg = summarize(yaw);
}

}  // namespace

std::vector<std::pair<size_t, size_t>> associateTimestamps(const std::vector<double>& first,
                                                           const std::vector<double>& second,
                                                           double max_difference) {
  std::vector<std::pair<size_t, size_t>> pairs;
  std::vector<bool> used(second.size(), false);
  for (size_t i = 0; i < first.size(); ++i) {
    // The closest stamps sit around the insertion point of first[i].
    const auto it = std::lower_bound(second.begin(), second.end(), first[i]);
    const size_t centre = static_cast<size_t>(it - second.begin());
    size_t best = second.size();
    double best_difference = std::numeric_limits<double>::infinity();
    const size_t begin = centre >= 2 ? centre - 2 : 0;
    const size_t end = std::min(second.size(), centre + 2);
    for (size_t j = begin; j < end; ++j) {
      const double difference = std::fabs(second[j] - first[i]);
      if (!used[j] && difference <= max_difference && difference < best_difference) {
        best = j;
        best_difference = difference;
      }
    }
    if (best < second.size()) {
      used[best] = true;
      pairs.emplace_back(i, best);
    }
  }
  return pairs;
}

TrajectoryError trajectoryError(const std::vector<io::StampedPose>& estimate,
                                const std::vector<io::StampedPose>& truth,
                                const TrajectoryErrorOptions& options) {
  std::vector<double> estimate_stamps, truth_stamps;
  for (const auto& p : estimate) estimate_stamps.push_back(p.timestamp);
  for (const auto& p : truth) truth_stamps.push_back(p.timestamp);
  TrajectoryError e;
  e.estimated_poses = estimate.size();
  e.truth_poses = truth.size();
  for (const auto& [i, j] :
       associateTimestamps(estimate_stamps, truth_stamps, options.max_time_difference)) {
    const Eigen::Vector3d d = estimate[i].pose.translation() - truth[j].pose.translation();
    FrameError f;
    f.timestamp = truth[j].timestamp;
    f.dx = d.x();
    f.dy = d.y();
    f.dz = options.planar ? 0.0 : d.z();
    f.position = std::sqrt(f.dx * f.dx + f.dy * f.dy + f.dz * f.dz);
    const double yaw_estimate = geometry::Pose2::fromRigid3(estimate[i].pose).yaw;
    const double yaw_truth = geometry::Pose2::fromRigid3(truth[j].pose).yaw;
    f.yaw = geometry::wrapAngle(yaw_estimate - yaw_truth);
    e.frames.push_back(f);
  }
  summarizeFrames(e);
  return e;
}

TrajectoryError errorFromFrames(std::vector<FrameError> frames) {
  TrajectoryError e;
  e.frames = std::move(frames);
  summarizeFrames(e);
  return e;
}

TrajectoryError subsetError(const TrajectoryError& all, const std::vector<bool>& keep) {
  TrajectoryError e;
  e.estimated_poses = all.estimated_poses;
  e.truth_poses = all.truth_poses;
  for (size_t i = 0; i < all.frames.size() && i < keep.size(); ++i) {
    if (keep[i]) e.frames.push_back(all.frames[i]);
  }
  summarizeFrames(e);
  return e;
}

}  // namespace parkloc::eval
