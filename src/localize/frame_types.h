#pragma once
// What the pipeline takes in and gives out per frame set: the camera images (or text
// instances) with the wheel odometry since the last frame set, and the pose with everything
// the pipeline did to reach it (instances, associations, status, stage timings, warnings).
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "common/odometry_sample.h"
#include "geometry/pose.h"
#include "localize/map_error_term.h"
#include "ocr/text_spotter.h"

namespace parkloc::localize {

// ---------------------------------------------------------------------------------------
// Input

struct CameraInput {
  std::string camera;  // rig camera name
  // 8-bit BGR; empty when the image is missing or corrupt (the pipeline goes on with the
  // other cameras and reports it in FrameResult::warnings).
  cv::Mat image;
  // When set, these instances are used as they are and no spotting runs (oracle OCR from
  // ground-truth labels, or instances spotted elsewhere).
  std::optional<std::vector<ocr::TextInstance>> instances;
  // When the image was captured, when not at the frame set's time (cameras not triggered
  // together; localize/capture_time.h).
  std::optional<double> capture_time;
};

struct FrameInput {
  double timestamp = 0.0;
  std::vector<CameraInput> cameras;
  // Wheel odometry samples with timestamp in (previous frame, this frame]; the pipeline
  // integrates them up to `timestamp`. Non-finite samples are skipped with a warning.
  std::vector<OdometrySample> odometry;
};

// ---------------------------------------------------------------------------------------
// Output

enum class TrackingStatus {
  kNotInitialised,  // no fix yet: no pose
  kOk,              // a measurement update this frame
  kDeadReckoning,   // no measurement this frame; prediction only
  kLost,            // uncertainty beyond TrackingOptions::lost_position_sigma_m, or re-localising
};
std::string toString(TrackingStatus status);

// Why an instance was or was not used.
enum class AssociationVerdict {
  kAccepted,
  kWrongClass,     // not a class used for localization
  kLowScore,       // recognition score below AssociationOptions::min_recognition_score
  kNotInMap,       // exact matching failed (paper section 3.3)
  kAnomaly,        // AFM box-plot outlier (paper section 3.3)
  kGated,          // in the map but far from where the predicted pose puts it
  kFlipped,        // reading order disagrees with the map heading (180-degree reading)
  kSolverOutlier,  // down-weighted to (near) zero by the robust solver
  kNoGeometry,     // polygon cannot be cast onto the ground / face (horizon, behind)
  kAmbiguous,      // the text names several landmarks (pillar faces, levels) and no pose
                   // tells which one
  kUnconfirmed,    // a second opinion (ocr::TextInstance::second_opinion) with no tracked
                   // pose to confirm it: it may start no fix
  kPartial,        // read by the part the image shows (ocr::TextInstance::partial): the
                   // polygon is not the text's
};
std::string toString(AssociationVerdict verdict);

struct Association {
  std::string camera;
  int instance_index = -1;  // index into FrameResult::cameras[...].instances
  std::string text;
  std::string landmark_id;  // empty when no landmark matched
  AssociationVerdict verdict = AssociationVerdict::kNotInMap;
  // Squared Mahalanobis distance of the landmark centre against the prediction (-1 when
  // not gated, e.g. not initialised).
  double mahalanobis2 = -1.0;
  // Mean reprojection residual of the corners after the solve, pixels (-1 when the solve
  // did not use the instance).
  double residual_px = -1.0;
};

struct CameraResult {
  std::string camera;
  bool image_ok = true;    // false: missing or corrupt, skipped
  bool full_frame = true;  // spotted on the full frame (else map-guided regions)
  int regions = 0;         // map-guided regions requested
  std::vector<ocr::TextInstance> instances;
};

// Wall-clock time of each stage for this frame, milliseconds. The stages run one after
// the other inside process(), so their sum never exceeds total_ms.
struct StageTimings {
  double roi_ms = 0.0;          // read planning: map-guided regions, budget, reads or fits
  double spotting_ms = 0.0;     // OCR, all cameras (0 when every camera brought instances)
  double association_ms = 0.0;  // level estimate, exact matching, AFM, gating
  double solver_ms = 0.0;       // SE(2) solve or paper projection + averaging
  double filter_ms = 0.0;       // EKF predict + update
  double total_ms = 0.0;
  // CPU time of the whole process during process(), all threads (OCR engine threads
  // included, and the search worker's while it runs meanwhile), milliseconds: unlike wall
  // time it does not grow with the machine's load.
  double cpu_ms = 0.0;
};

// Texts spotted on a worker (search_worker.h: full frames, or the reads at predicted places)
// and fused in this frame set, at the time their images were captured (late_fusion.h).
struct BackgroundFusion {
  double capture_timestamp = 0.0;  // the frame set whose images they come from
  std::vector<CameraResult> cameras;  // rig order; the worker's cameras hold its texts
  std::vector<Association> associations;
  std::optional<geometry::Pose2> measurement;  // the fix they gave, at the capture time
  double worker_ms = 0.0;      // the worker's wall time on them
  double worker_cpu_ms = 0.0;  // ... and its CPU time
};

// A pose fix the filter fused, as its map-error model sees it: z = pose + sum J_fix_map e +
// v, v ~ N(0, pixel_covariance), e each landmark's map error (map_error_term.h). Evaluation
// smooths a whole drive from these and the odometry (eval/drive_smoother.h).
struct FusedFix {
  geometry::Pose2 pose;
  Eigen::Matrix3d pixel_covariance = Eigen::Matrix3d::Zero();
  std::vector<MapErrorTerm> map_terms;
};

struct FrameResult {
  double timestamp = 0.0;
  TrackingStatus status = TrackingStatus::kNotInitialised;
  bool has_pose = false;  // false only before the first fix
  geometry::Pose2 pose;   // map_from_vehicle
  // Covariance of (x, y, yaw), m^2 / rad^2. In paper mode the yaw entries are large (the
  // paper estimates no heading).
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  // The single-frame solver fix, before the filter, when there was one.
  std::optional<geometry::Pose2> measurement;
  std::optional<Eigen::Matrix3d> measurement_covariance;
  bool solver_converged = false;
  int solver_iterations = 0;
  bool reinitialised = false;  // the filter was reset from the solver this frame
  // The filter's odometry error estimates with the pose (pose_ekf.h): the yaw-rate bias
  // (rad/s) and the speed scale, each with its 1 sigma. A wrong bias turns the heading while
  // the filter dead-reckons between fixes.
  struct OdometryEstimate {
    double yaw_rate_bias = 0.0, yaw_rate_bias_sigma = 0.0;
    double speed_scale = 1.0, speed_scale_sigma = 0.0;
  };
  std::optional<OdometryEstimate> odometry;
  // The pose rests on a single landmark's reading, not yet confirmed by a second one read
  // consistently with it (track_lifecycle.h): it may come from one misreading.
  bool tentative = false;
  std::vector<FusedFix> fused_fixes;  // fixes that updated or started the filter
  // The level driven on (level_estimate.h): the most probable one, its probability, and
  // whether it is decided. An undecided level with a pose: the levels share the places seen.
  std::string level;
  double level_probability = 0.0;
  bool level_decided = false;

  std::vector<CameraResult> cameras;
  std::vector<Association> associations;
  // Cameras whose full frame went to a worker this frame set (their CameraResult holds only
  // what the critical path spotted), and what the search worker gave back and was fused.
  std::vector<std::string> background_cameras;
  std::optional<BackgroundFusion> background;
  // Cameras whose reads at predicted places went to the read worker this frame set
  // (RealtimeOptions::background_reads), and what the read worker gave back and was fused
  // here: reads of an earlier frame set, or full frames while there was no track to read for
  // (CameraResult::full_frame).
  std::vector<std::string> deferred_read_cameras;
  std::optional<BackgroundFusion> deferred_reads;
  StageTimings timings;
  std::vector<std::string> warnings;
};

}  // namespace parkloc::localize
