#include "localize/track_lifecycle.h"

#include <fmt/format.h>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace parkloc::localize {

double positionSigma(const Eigen::Matrix3d& covariance) {
  const Eigen::Matrix2d p = covariance.topLeftCorner<2, 2>();
  return std::sqrt(
      std::max(0.0, Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(p, Eigen::EigenvaluesOnly)
                        .eigenvalues()
                        .maxCoeff()));
}

double fixDistance2(const PoseEkf& ekf, const PoseFix& fix) {
  if (ekf.mapErrorStates() && !fix.map_terms.empty())
    return ekf.mahalanobis2(fix.pose, fix.pixel_part, fix.map_terms, fix.carried);
  return ekf.mahalanobis2(fix.pose, fix.covariance, fix.carried);
}

bool isTracking(const PoseEkf& ekf, const TrackingOptions& options) {
  return ekf.initialised() && positionSigma(ekf.covariance()) <= options.lost_position_sigma_m;
}

void TrackLifecycle::reset() {
  search_window_.clear();
  disagreeing_fixes_ = 0;
  disagreeing_with_consensus_ = false;
  fused_.clear();
  tentative_ = false;
  confirming_reads_.clear();
}

void TrackLifecycle::startAt(const geometry::Pose2& pose, PoseEkf& ekf) const {
  const double sigma = options_.initial_position_sigma_m;
  const double yaw_sigma = options_.initial_yaw_sigma_deg * M_PI / 180.0;
  ekf.initialise(
      pose, Eigen::Vector3d(sigma * sigma, sigma * sigma, yaw_sigma * yaw_sigma).asDiagonal(), 0.0);
}

void TrackLifecycle::start(const PoseFix& fix, PoseEkf& ekf, double timestamp) {
  if (ekf.mapErrorStates() && !fix.map_terms.empty())
    ekf.initialise(fix.pose, fix.pixel_part, fix.map_terms, timestamp);
  else
    ekf.initialise(fix.pose, fix.covariance, timestamp);
  fused_.clear();
  disagreeing_fixes_ = 0;
  disagreeing_with_consensus_ = false;
  confirming_reads_ = fix.read_landmarks;
  tentative_ = static_cast<int>(confirming_reads_.size()) < options_.confirm_read_landmarks;
}

void TrackLifecycle::noteConfirmingReads(const PoseFix& fix, FrameResult& result) {
  if (!tentative_) return;
  for (const std::string& id : fix.read_landmarks)
    if (std::find(confirming_reads_.begin(), confirming_reads_.end(), id) ==
        confirming_reads_.end())
      confirming_reads_.push_back(id);
  if (static_cast<int>(confirming_reads_.size()) >= options_.confirm_read_landmarks) {
    tentative_ = false;
    result.warnings.push_back(fmt::format("track confirmed: {} landmarks read consistently",
                                          confirming_reads_.size()));
  }
}

bool TrackLifecycle::countDisagreeing(const FrameFixes& fixes, PoseEkf& ekf,
                                      FrameResult& result) {
  // A kidnapped vehicle (or a filter that went wrong): several consecutive fixes that agree
  // with each other but not with the filter re-initialise it.
  const PoseFix& disagreeing = *fixes.disagreeing;
  const geometry::Pose2& fix = disagreeing.pose;
  bool consistent = disagreeing_fixes_ > 0;
  if (consistent) {
    const geometry::Pose2 moved = predicted_at_last_disagreeing_fix_.inverse() * ekf.pose();
    const geometry::Pose2 expected = last_disagreeing_fix_ * moved;
    consistent =
        (expected.translation() - fix.translation()).norm() < options_.reinit_consistency_m &&
        std::abs(geometry::wrapAngle(expected.yaw - fix.yaw)) <
            options_.reinit_consistency_deg * M_PI / 180.0;
  }
  // A tentative track rests on one reading: reads that place the vehicle elsewhere weigh as
  // much as it does, and the fits that agree with it read nothing.
  const bool from_reads = tentative_ && !disagreeing.read_landmarks.empty();
  const int landmarks = from_reads ? static_cast<int>(disagreeing.read_landmarks.size())
                                   : fixes.disagreeing_landmarks;
  disagreeing_fixes_ = consistent ? disagreeing_fixes_ + 1 : 1;
  disagreeing_with_consensus_ = (consistent && disagreeing_with_consensus_) || landmarks >= 2;
  last_disagreeing_fix_ = fix;
  predicted_at_last_disagreeing_fix_ = ekf.pose();
  const int needed = std::max(1, from_reads ? options_.tentative_reinit_after_rejected_fixes
                                            : options_.reinit_after_rejected_fixes);
  if (disagreeing_fixes_ < (disagreeing_with_consensus_ ? needed : 2 * needed)) return false;
  const int count = disagreeing_fixes_;
  const bool was_tentative = tentative_;
  start(disagreeing, ekf, result.timestamp);
  result.reinitialised = true;
  result.status = TrackingStatus::kOk;
  result.warnings.push_back(fmt::format("re-initialised from {} consecutive disagreeing fixes{}",
                                        count, was_tentative ? " (tentative track)" : ""));
  return true;
}

void TrackLifecycle::apply(const FrameFixes& fixes, bool was_tracking, PoseEkf& ekf,
                           MotionPrediction& motion, FrameResult& result) {
  if (fixes.agreeing && !was_tracking) {
    // First fix, or re-localisation after the filter got lost.
    start(*fixes.agreeing, ekf, result.timestamp);
    for (const std::string& id : fixes.agreeing->landmarks) ++fused_[id];
    result.fused_fixes.push_back(
        {fixes.agreeing->pose, fixes.agreeing->pixel_part, fixes.agreeing->map_terms});
    result.reinitialised = true;
    motion.forgetFixes();
    motion.noteFix(result.timestamp, ekf);
    result.status = TrackingStatus::kOk;
    return;
  }
  // A tentative track also hears the reads that disagree with it while fits agree.
  if (fixes.disagreeing && (!fixes.agreeing || tentative_)) {
    if (countDisagreeing(fixes, ekf, result)) return;
  }
  if (!fixes.agreeing) return;
  const PoseFix& fix = *fixes.agreeing;
  if (ekf.mapErrorStates() && !fix.map_terms.empty()) {
    ekf.update(fix.pose, fix.pixel_part, fix.map_terms, fix.carried);
  } else {
    double uses = 0.0;
    for (const std::string& id : fix.landmarks)
      uses += std::min(fused_[id], options_.map_reuse_cap - 1);
    const double n = 1.0 + (fix.landmarks.empty() ? 0.0 : uses / fix.landmarks.size());
    ekf.update(fix.pose, fix.covariance + (n - 1.0) * fix.map_part, fix.floor, fix.carried);
  }
  for (const std::string& id : fix.landmarks) ++fused_[id];
  result.fused_fixes.push_back({fix.pose, fix.pixel_part, fix.map_terms});
  motion.noteFix(result.timestamp, ekf);
  noteConfirmingReads(fix, result);
  if (!fixes.disagreeing) {
    disagreeing_fixes_ = 0;
    disagreeing_with_consensus_ = false;
  }
  result.status = TrackingStatus::kOk;
}

void TrackLifecycle::report(const PoseEkf& ekf, FrameResult& result) const {
  if (!ekf.initialised()) return;
  result.has_pose = true;
  result.pose = ekf.pose();
  result.covariance = ekf.covariance();
  result.odometry = FrameResult::OdometryEstimate{
      ekf.yawRateBias(), std::sqrt(std::max(0.0, ekf.yawRateBiasVariance())), ekf.speedScale(),
      std::sqrt(std::max(0.0, ekf.speedScaleVariance()))};
  result.tentative = tentative_;
  if (result.status != TrackingStatus::kOk)
    result.status =
        isTracking(ekf, options_) ? TrackingStatus::kDeadReckoning : TrackingStatus::kLost;
}

}  // namespace parkloc::localize
