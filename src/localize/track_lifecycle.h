#pragma once
// The track's lifecycle in parkloc's pipeline: not initialised -> tracking -> (dead
// reckoning) -> lost -> re-localised.
//
//  - Not initialised: the texts of the last few frame sets are solved together (the search
//    window, search_window.h) until a fix is certain enough to start the filter.
//  - Tracking: a fix within the filter's gate is fused (EKF update); without one the filter
//    dead-reckons on odometry.
//  - Lost: the position uncertainty grew beyond lost_position_sigma_m; the next certain fix
//    starts the filter again.
//  - Kidnapped: fixes that agree with each other but not with the filter (a vehicle moved
//    without odometry, or a filter gone wrong) re-initialise it after a few frame sets.
//  - Tentative: a filter started (or re-initialised) from a fix that rests on fewer than
//    confirm_read_landmarks landmarks read by OCR may rest on one misreading. Under a wrong
//    pose the map predicts texts where other texts are painted, and fitting their ink at
//    the predicted place (which labels it with the expected text) seems to confirm it. So
//    the track stays tentative until enough distinct landmarks have been read consistently
//    with it; until then the spotter reads its regions against the whole map's texts and
//    sweeps one camera's full frame every frame set (read_planning.h), a fix from reads
//    that disagree is sought even when the fits agree (parkloc_measurement.h), and a
//    consistent one re-initialises the filter at once.
#include <Eigen/Core>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "geometry/pose.h"
#include "localize/frame_types.h"
#include "localize/motion_prediction.h"
#include "localize/pose_ekf.h"
#include "localize/search_window.h"

namespace parkloc::localize {

struct TrackingOptions {
  // The track is lost when the filter's 1-sigma position uncertainty (largest axis, metres)
  // grows beyond this: its prediction can no longer guide reading or gate associations.
  double lost_position_sigma_m = 2.0;
  // A first fix (or a re-localisation) starts the filter only when its 1-sigma position
  // (metres) is within this, the error no frame may exceed: a fix from one distant, thin text
  // that may be misread (one misplaced corner moves it by decimetres) waits for more texts in
  // the search window instead. 0: any fix.
  double first_fix_max_sigma_m = 0.5;
  // A fix is fused only within this squared Mahalanobis distance (3 dof) of the prediction;
  // fixes beyond count towards re-initialisation. 16.3: 99.9 %.
  double fix_gate_chi2 = 16.3;
  // Consecutive consistent fixes outside the gate that re-initialise the filter when one of
  // them rests on two or more landmarks; twice as many when each rests on a single landmark
  // (which a misreading can move).
  int reinit_after_rejected_fixes = 3;
  // A filter started from a fix with fewer than this many distinct landmarks read by OCR
  // among its inliers is tentative until that many have been read and accepted with it; a
  // corner fit at the predicted place does not count (it reads nothing). <= 1: every track
  // is confirmed from its start.
  int confirm_read_landmarks = 2;
  // While tentative, consecutive consistent fixes from reads outside the gate that
  // re-initialise the filter when one rests on two or more read landmarks; twice as many
  // when each rests on one (a single misreading can make one).
  int tentative_reinit_after_rejected_fixes = 1;
  // Two fixes outside the gate are consistent when the second lies within this distance
  // (metres) and heading (degrees) of the first carried along by the filter's motion.
  double reinit_consistency_m = 1.0;
  double reinit_consistency_deg = 10.0;
  // The uncertainty of PipelineOptions::initial_pose (1 sigma): a pose known from a previous
  // drive or a parking spot, to about a decimetre and a couple of degrees.
  double initial_position_sigma_m = 0.1;
  double initial_yaw_sigma_deg = 2.0;
  // A landmark's map error is one error, however many frames see it: after its landmarks were
  // fused n times on average, a fix's map part weighs as n times its variance, so that the
  // filter takes each landmark's map information about once (the information split among the
  // fixes that repeat it) instead of averaging one survey error as if it were noise. n counts
  // fusions since the filter started, up to this. 1: every fix as independent.
  int map_reuse_cap = 20;
};

// The 1-sigma position uncertainty along the worst axis, metres.
double positionSigma(const Eigen::Matrix3d& covariance);
// The filter's pose is good enough to predict regions and gate associations.
bool isTracking(const PoseEkf& ekf, const TrackingOptions& options);

// A pose fix and its covariance as the filter sees it.
struct PoseFix {
  geometry::Pose2 pose;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  // The map's share of `covariance`, which the next frames' fixes of the same landmarks
  // repeat, and the landmarks it comes from (the solve's inliers).
  Eigen::Matrix3d map_part = Eigen::Matrix3d::Zero();
  std::vector<std::string> landmarks;
  // Those of them read by OCR (LandmarkObservation::read).
  std::vector<std::string> read_landmarks;
  // Fusing the fix does not take the filter below this (PoseEkf::update).
  Eigen::Matrix3d floor = Eigen::Matrix3d::Zero();
  // For a filter with map error states (EkfOptions::map_error_landmarks): how each inlier
  // landmark's map error moves the fix, and the covariance the fix has beside them.
  std::vector<MapErrorTerm> map_terms;
  Eigen::Matrix3d pixel_part = Eigen::Matrix3d::Zero();
  // A fix measured earlier and carried to the present (late_fusion.h): how the carry's motion
  // depends on the filter's bias and scale (PoseEkf::odometrySensitivitySince); zero for a fix
  // of the present.
  OdometrySensitivity carried = OdometrySensitivity::Zero();
};

// The fix's distance from the filter's prediction (squared Mahalanobis), through the map
// error states where the filter has them.
double fixDistance2(const PoseEkf& ekf, const PoseFix& fix);

// What parkloc's measurement made of one frame set.
struct FrameFixes {
  std::optional<PoseFix> agreeing;     // to fuse (or to start the filter with)
  std::optional<PoseFix> disagreeing;  // a good fix outside the filter's gate
  int disagreeing_landmarks = 0;       // landmarks among its inliers
};

class TrackLifecycle {
 public:
  TrackLifecycle(const TrackingOptions& options, size_t search_window_frames)
      : options_(options), search_window_(search_window_frames) {}
  void reset();

  // Starts the filter at a known pose (PipelineOptions::initial_pose).
  void startAt(const geometry::Pose2& pose, PoseEkf& ekf) const;

  SearchWindow& searchWindow() { return search_window_; }

  // Fuses the frame set's fix, starts the filter with it, or counts a disagreeing fix
  // towards re-initialisation; sets result.status (kOk on a fix), result.reinitialised and
  // warnings.
  void apply(const FrameFixes& fixes, bool was_tracking, PoseEkf& ekf, MotionPrediction& motion,
             FrameResult& result);

  // The filter's pose and status into the result (the status from the filter when no fix
  // came this frame set).
  void report(const PoseEkf& ekf, FrameResult& result) const;

  // The filter rests on fewer read landmarks than confirm_read_landmarks.
  bool tentative() const { return tentative_; }

 private:
  TrackingOptions options_;
  SearchWindow search_window_;
  // Fusions of each landmark since the filter started (map_reuse_cap).
  std::map<std::string, int> fused_;
  // Re-localisation: consecutive fixes that disagree with the filter.
  int disagreeing_fixes_ = 0;
  bool disagreeing_with_consensus_ = false;  // one of them had two or more landmarks
  geometry::Pose2 last_disagreeing_fix_;
  geometry::Pose2 predicted_at_last_disagreeing_fix_;
  // The tentative track and the distinct landmarks read consistently with it so far.
  bool tentative_ = false;
  std::vector<std::string> confirming_reads_;

  // The filter starts (or restarts) from `fix`: tentative unless it rests on enough reads.
  void start(const PoseFix& fix, PoseEkf& ekf, double timestamp);
  // Counts a disagreeing fix towards re-initialisation; true when it re-initialised.
  bool countDisagreeing(const FrameFixes& fixes, PoseEkf& ekf, FrameResult& result);
  // Reads accepted with the tentative track; confirms it when there are enough.
  void noteConfirmingReads(const PoseFix& fix, FrameResult& result);
};

}  // namespace parkloc::localize
