#pragma once
// Stage 1 of the pipeline, motion prediction: takes in the frame set's wheel odometry and
// moves the EKF to the frame set's time. The odometry is held piecewise constant (zero-order
// hold) between samples; a gap in it is predicted as a random walk. Without odometry the
// filter moves by a constant-velocity guess from its last two fixes, with the random walk on
// top for its uncertainty.
#include <optional>
#include <string>
#include <vector>

#include "common/odometry_sample.h"
#include "geometry/pose.h"
#include "localize/frame_types.h"
#include "localize/pose_ekf.h"

namespace parkloc::localize {

struct MotionOptions {
  // Predict the filter with wheel odometry; false: the constant-velocity guess from the last
  // two fixes (or a random walk), as for a vehicle that has no odometry.
  bool use_odometry = true;
  // Odometry older than this (seconds) at a frame set is a gap (a dropped sensor): warned
  // about, and the rest of the interval is predicted as a random walk. Five samples of a
  // 10 Hz odometry.
  double odometry_gap_s = 0.5;
  // The constant-velocity guess uses two fixes at most this far apart (seconds): over a
  // longer interval the vehicle may have turned or stopped, and the random walk alone is the
  // honest prediction.
  double constant_velocity_max_gap_s = 0.5;
  // Use each camera image at its own capture time (localize/capture_time.h); false: every
  // image as if captured at the frame set's time.
  bool use_capture_times = true;
};

// What the motion step saw of one frame set, for the stages after it.
struct FrameMotion {
  // The frame set's time is finite and after the previous one's: the filter was predicted.
  bool time_ok = false;
  bool had_frame = false;  // a frame set came before this one
  double previous_frame_time = 0.0;
  double frame_time = 0.0;
  bool use_odometry = true;                   // MotionOptions::use_odometry
  std::optional<OdometrySample> held_before;  // the sample held at the previous frame set
  std::vector<OdometrySample> accepted;       // this frame set's samples, in order

  // The vehicle's motion since the previous frame set by wheel odometry (the pose now in
  // the vehicle frame then); empty when unknown (no odometry, no previous frame set).
  std::optional<geometry::Pose2> sincePreviousFrame() const;
};

class MotionPrediction {
 public:
  // `hold_odometry_to_frame`: the held sample counts as used up to each frame set (the paper
  // pipeline's odometry heading integrates it up to there), so that a later sample not after
  // the frame set is late and skipped.
  explicit MotionPrediction(MotionOptions options = {}, bool hold_odometry_to_frame = false)
      : options_(options), hold_odometry_to_frame_(hold_odometry_to_frame) {}

  void reset();

  // Checks the frame set's time, takes in its odometry (non-finite and out-of-order samples
  // are skipped with a warning) and predicts an initialised filter to the frame set's time.
  FrameMotion advance(const FrameInput& frame, PoseEkf& ekf, std::vector<std::string>& warnings);

  // After a fix was fused at time t: the constant-velocity guess (without odometry) is the
  // filter's motion since the previous fix.
  void noteFix(double t, const PoseEkf& ekf);
  // The filter was (re-)initialised: the motion from the previous fix means nothing now.
  void forgetFixes() { last_fix_.reset(); }

  const MotionOptions& options() const { return options_; }
  // The odometry sample held at the last frame set (speed and yaw rate now), when odometry
  // drives the prediction.
  std::optional<OdometrySample> heldOdometry() const {
    return odometryDrives() ? std::optional<OdometrySample>(hold_) : std::nullopt;
  }

 private:
  void predictTo(double t, PoseEkf& ekf, std::vector<std::string>& warnings) const;
  bool odometryDrives() const { return options_.use_odometry && have_odometry_; }

  MotionOptions options_;
  bool hold_odometry_to_frame_ = false;
  bool have_frame_ = false;
  double last_frame_time_ = 0.0;
  bool have_odometry_ = false;
  OdometrySample hold_;  // latest odometry sample (zero-order hold)
  // Without odometry: the filtered pose at the last fix, and the motion since the one before.
  std::optional<std::pair<double, geometry::Pose2>> last_fix_;
  std::optional<OdometrySample> constant_velocity_;
};

}  // namespace parkloc::localize
