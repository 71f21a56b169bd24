#pragma once
// Is the covariance that `parkloc run` reports honest? The consistency test of a filter
// (normalized estimation error squared, NEES, of x, y, yaw against the chi-square bound)
// and an integrity monitor as GNSS integrity monitoring does it: a protection level from the
// covariance against an alert limit, and the count of frames where the error exceeded the
// alert limit while no alert was raised (missed detections).
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "geometry/pose.h"
#include "io/tum.h"

namespace parkloc::eval {

// One line of frames.jsonl, the parts the consistency test needs. Ground truth is
// interpolated at the frame's timestamp.
struct ReportedFrame {
  double timestamp = 0.0;
  std::string status;  // "ok", "dead_reckoning", "lost", "not_initialised", ...
  bool has_pose = false;
  geometry::Pose2 pose;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();  // x, y, yaw
};

// Reads frames.jsonl as `parkloc run` writes it. Throws InputError (file, line, field).
std::vector<ReportedFrame> loadReportedFrames(const std::string& path);

struct ConsistencyOptions {
  // 95 % quantile of chi-square with 3 degrees of freedom.
  double nees_bound = 7.815;
  // Protection level = k * sqrt(largest eigenvalue of the position covariance). With the
  // largest eigenvalue the 2-D error is bounded by a chi-square with 2 dof, so
  // P(error > PL) <= exp(-k^2 / 2): k = 4.29 is an integrity risk of 1e-4 per frame.
  double protection_k = 4.29;
  double alert_limit_m = 0.5;
  // A frame in this status is an alert in itself (the pipeline says it does not know).
  std::vector<std::string> alert_statuses{"lost"};
};

struct FrameConsistency {
  double timestamp = 0.0;
  Eigen::Vector3d error = Eigen::Vector3d::Zero();  // estimate - truth: x, y, yaw (wrapped)
  double position_error_m = 0.0;
  double nees = 0.0;  // infinite when the covariance is singular
  double protection_level_m = 0.0;
  bool inside_bound = false;
  bool alert = false;   // protection level > alert limit, or an alert status
  bool missed = false;  // error > alert limit and no alert
};

struct ConsistencyResult {
  std::vector<FrameConsistency> frames;  // frames with a pose and ground truth
  size_t frames_total = 0;
  size_t frames_without_pose = 0;
  // Frames after the first pose that have neither a pose nor an alert status: the
  // pipeline must never leave a frame without an answer.
  size_t frames_unanswered = 0;
  size_t frames_without_truth = 0;
  size_t inside_bound = 0;
  double fraction_inside = 0.0;
  double mean_nees = 0.0;  // over finite values; 3 for a consistent filter
  double median_nees = 0.0;
  size_t alerts = 0;
  size_t over_alert_limit = 0;  // frames with error > alert limit
  size_t missed_detections = 0;
  size_t false_alerts = 0;  // alert while error <= alert limit
  // Episodes of error > alert limit (runs of consecutive frames), and those whose first
  // frame raised no alert (the flag came late or never).
  size_t episodes = 0;
  size_t late_episodes = 0;
  double mean_position_error_m = 0.0;
  double max_position_error_m = 0.0;
  double mean_protection_level_m = 0.0;
};

// e^T P^-1 e; +infinity when P is not positive definite.
double nees(const Eigen::Vector3d& error, const Eigen::Matrix3d& covariance);
// k * sqrt(largest eigenvalue of the 2x2 position block).
double protectionLevel(const Eigen::Matrix3d& covariance, double k);

ConsistencyResult evaluateConsistency(const std::vector<ReportedFrame>& frames,
                                      const std::vector<io::StampedPose>& truth,
                                      const ConsistencyOptions& options = {});

}  // namespace parkloc::eval
