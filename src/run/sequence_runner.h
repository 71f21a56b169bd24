#pragma once
// `parkloc run` as a library call: feeds a sequence folder frame set by frame set through
// the pipeline and writes trajectory.tum, frames.jsonl and optionally an annotated video.
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "io/sequence.h"
#include "localize/pipeline.h"
#include "map/map_noise.h"
#include "ocr/text_spotter.h"
#include "run/fault_injection.h"

namespace parkloc::run {

struct RunOptions {
  localize::PipelineOptions pipeline;
  bool oracle = false;     // instances from the ground-truth labels instead of a spotter
  size_t max_frames = 0;   // 0: all frame sets
  std::string out_dir;     // receives trajectory.tum and frames.jsonl (created)
  std::string video_path;  // annotated mp4; empty: none
  std::function<void(size_t done, size_t total)> progress;
  InputFaults faults;  // injected sensor faults (`parkloc run --inject`); none by default
  // Survey error (`parkloc run --map-noise`): the pipeline gets the sequence's map perturbed
  // (map/map_noise.h); the error is still measured against poses.tum. 0: the map as it is.
  map::MapNoise map_noise;
  // Feed the frame sets at their recorded rate, as cameras would (`parkloc run --realtime`):
  // frame set i is released at its capture time after the first one's and dropped when the
  // previous one is still being processed then (its odometry goes to the next one); the
  // search worker's texts are fused when ready (RealtimeOptions::wait_for_worker off), and
  // the spotters are warmed up before the first frame set (RealtimeOptions::warm_up).
  // Reading the images from disk happens before the release, as a camera delivers them.
  bool realtime = false;
};

struct RunSummary {
  size_t frames = 0;
  size_t frames_with_pose = 0;
  std::optional<double> first_fix_time;
  size_t frames_after_first_fix = 0;  // including the first fix
  size_t poses_after_first_fix = 0;
  std::map<std::string, size_t> status_counts;
  size_t frames_with_warnings = 0;
  size_t frames_skipped_by_faults = 0;         // kidnap: frame sets never processed
  std::vector<std::string> sequence_warnings;  // from reading the folder

  // Against poses.tum, over the frames with a pose (empty without ground truth).
  bool has_truth = false;
  double mean_position_error_m = 0.0;
  double p95_position_error_m = 0.0;
  double max_position_error_m = 0.0;
  double mean_yaw_error_deg = 0.0;
  size_t frames_over_half_metre = 0;

  // Per frame set, the pipeline's total (image decoding excluded).
  double latency_median_ms = 0.0;
  double latency_p99_ms = 0.0;

  // RunOptions::realtime: frame sets dropped, and each pose's age (the time process()
  // returned it less the frame set's release time), milliseconds, in frame order.
  size_t frames_dropped = 0;
  std::vector<double> pose_age_ms;
  double pose_age_median_ms = 0.0;
  double pose_age_p95_ms = 0.0;
  double pose_age_p99_ms = 0.0;
  double pose_age_max_ms = 0.0;
  // The first frame set with a pose (index in the drive), and (realtime) when that pose came
  // out, milliseconds after the first frame set's release.
  std::optional<size_t> first_pose_frame;
  double first_pose_output_ms = 0.0;
};

// The ground-truth pose at time t, linearly interpolated; empty outside the trajectory.
std::optional<geometry::Pose2> truthAt(const std::vector<io::StampedPose>& truth, double t);

// The odometry samples with timestamp in (after, until]; `all` in time order, as io::loadOdometry
// gives it.
std::vector<OdometrySample> odometryBetween(const std::vector<OdometrySample>& all, double after,
                                            double until);

// Throws InputError (oracle without labels, spotter missing) and IoError (outputs).
// `workers`: the workers' own spotters (localize::Pipeline).
RunSummary runSequence(const io::Sequence& sequence, ocr::TextSpotter* spotter,
                       const RunOptions& options, localize::WorkerSpotters workers = {});

}  // namespace parkloc::run
