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
    return ekf.mahalanobis2(fix.pose, fix.pixel_part, fix.map_terms);
  return ekf.mahalanobis2(fix.pose, fix.covariance);
}

bool isTracking(const PoseEkf& ekf, const TrackingOptions& options) {
  return ekf.initialised() && positionSigma(ekf.covariance()) <= options.lost_position_sigma_m;
}

void TrackLifecycle::reset() {
  search_window_.clear();
  disagreeing_fixes_ = 0;
  disagreeing_with_consensus_ = false;
  fused_.clear();
}

void TrackLifecycle::startAt(const geometry::Pose2& pose, PoseEkf& ekf) const {
  const double sigma = options_.initial_position_sigma_m;
  const double yaw_sigma = options_.initial_yaw_sigma_deg * M_PI / 180.0;
  ekf.initialise(
      pose, Eigen::Vector3d(sigma * sigma, sigma * sigma, yaw_sigma * yaw_sigma).asDiagonal(), 0.0);
}

void TrackLifecycle::apply(const FrameFixes& fixes, bool was_tracking, PoseEkf& ekf,
                           MotionPrediction& motion, FrameResult& result) {
  if (fixes.agreeing) {
    const PoseFix& fix = *fixes.agreeing;
    const bool map_states = ekf.mapErrorStates() && !fix.map_terms.empty();
    if (was_tracking && map_states) {
      ekf.update(fix.pose, fix.pixel_part, fix.map_terms);
    } else if (was_tracking) {
      double uses = 0.0;
      for (const std::string& id : fix.landmarks) uses += std::min(fused_[id], options_.map_reuse_cap - 1);
      const double n = 1.0 + (fix.landmarks.empty() ? 0.0 : uses / fix.landmarks.size());
      ekf.update(fix.pose, fix.covariance + (n - 1.0) * fix.map_part, fix.floor);
    } else {
      fused_.clear();
      // First fix, or re-localisation after the filter got lost.
      if (map_states)
        ekf.initialise(fix.pose, fix.pixel_part, fix.map_terms, result.timestamp);
      else
        ekf.initialise(fix.pose, fix.covariance, result.timestamp);
      result.reinitialised = true;
      motion.forgetFixes();
    }
    for (const std::string& id : fix.landmarks) ++fused_[id];
    result.fused_fixes.push_back({fix.pose, fix.pixel_part, fix.map_terms});
    motion.noteFix(result.timestamp, ekf);
    disagreeing_fixes_ = 0;
    disagreeing_with_consensus_ = false;
    result.status = TrackingStatus::kOk;
    return;
  }
  if (!fixes.disagreeing) return;
  // A kidnapped vehicle (or a filter that went wrong): several consecutive fixes that agree
  // with each other but not with the filter re-initialise it.
  const geometry::Pose2& fix = fixes.disagreeing->pose;
  bool consistent = disagreeing_fixes_ > 0;
  if (consistent) {
    const geometry::Pose2 moved = predicted_at_last_disagreeing_fix_.inverse() * ekf.pose();
    const geometry::Pose2 expected = last_disagreeing_fix_ * moved;
    consistent =
        (expected.translation() - fix.translation()).norm() < options_.reinit_consistency_m &&
        std::abs(geometry::wrapAngle(expected.yaw - fix.yaw)) <
            options_.reinit_consistency_deg * M_PI / 180.0;
  }
  disagreeing_fixes_ = consistent ? disagreeing_fixes_ + 1 : 1;
  disagreeing_with_consensus_ =
      (consistent && disagreeing_with_consensus_) || fixes.disagreeing_landmarks >= 2;
  last_disagreeing_fix_ = fix;
  predicted_at_last_disagreeing_fix_ = ekf.pose();
  const int needed = std::max(1, options_.reinit_after_rejected_fixes);
  if (disagreeing_fixes_ >= (disagreeing_with_consensus_ ? needed : 2 * needed)) {
    const PoseFix& d = *fixes.disagreeing;
    if (ekf.mapErrorStates() && !d.map_terms.empty())
      ekf.initialise(fix, d.pixel_part, d.map_terms, result.timestamp);
    else
      ekf.initialise(fix, d.covariance, result.timestamp);
    fused_.clear();
    result.reinitialised = true;
    result.status = TrackingStatus::kOk;
    result.warnings.push_back(
        fmt::format("re-initialised from {} consecutive disagreeing fixes", disagreeing_fixes_));
    disagreeing_fixes_ = 0;
    disagreeing_with_consensus_ = false;
  }
}

void TrackLifecycle::report(const PoseEkf& ekf, FrameResult& result) const {
  if (!ekf.initialised()) return;
  result.has_pose = true;
  result.pose = ekf.pose();
  result.covariance = ekf.covariance();
  if (result.status != TrackingStatus::kOk)
    result.status =
        isTracking(ekf, options_) ? TrackingStatus::kDeadReckoning : TrackingStatus::kLost;
}

}  // namespace parkloc::localize
