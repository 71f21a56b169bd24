#include "localize/motion_prediction.h"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>

#include "localize/search_window.h"

namespace parkloc::localize {

std::optional<geometry::Pose2> FrameMotion::sincePreviousFrame() const {
  if (!(time_ok && had_frame && use_odometry)) return std::nullopt;
  return integrateOdometry(held_before, accepted, previous_frame_time, frame_time);
}

void MotionPrediction::reset() {
  have_frame_ = false;
  have_odometry_ = false;
  hold_ = {};
  last_fix_.reset();
  constant_velocity_.reset();
}

FrameMotion MotionPrediction::advance(const FrameInput& frame, PoseEkf& ekf,
                                      std::vector<std::string>& warnings) {
  FrameMotion motion;
  motion.frame_time = frame.timestamp;
  motion.use_odometry = options_.use_odometry;
  bool time_ok = std::isfinite(frame.timestamp);
  if (!time_ok) warnings.push_back("frame timestamp is not finite: no prediction");
  if (time_ok && have_frame_ && frame.timestamp <= last_frame_time_) {
    warnings.push_back(
        fmt::format("frame at {:.6f} is not after the previous one ({:.6f}): "
                    "no prediction",
                    frame.timestamp, last_frame_time_));
    time_ok = false;
  }
  motion.time_ok = time_ok;
  // A filter started from PipelineOptions::initial_pose starts its clock at the first frame.
  if (time_ok && !have_frame_ && ekf.initialised()) ekf.setTime(frame.timestamp);
  if (have_odometry_) motion.held_before = hold_;
  motion.had_frame = have_frame_;
  motion.previous_frame_time = last_frame_time_;

  for (const auto& s : frame.odometry) {
    if (!std::isfinite(s.timestamp) || !std::isfinite(s.speed) || !std::isfinite(s.yaw_rate)) {
      warnings.push_back(fmt::format("odometry sample at {} is not finite: skipped", s.timestamp));
      continue;
    }
    if (have_odometry_ && s.timestamp <= hold_.timestamp) {
      warnings.push_back(fmt::format("odometry sample at {:.6f} not after {:.6f}: skipped",
                                     s.timestamp, hold_.timestamp));
      continue;
    }
    if (time_ok && s.timestamp > frame.timestamp) {
      warnings.push_back(
          fmt::format("odometry sample at {:.6f} is after the frame: used from now", s.timestamp));
    }
    // The filter follows each sample: the held one drives it up to this sample's time.
    if (time_ok && ekf.initialised())
      predictTo(std::min(s.timestamp, frame.timestamp), ekf, warnings);
    hold_ = s;
    have_odometry_ = true;
    motion.accepted.push_back(s);
  }
  if (hold_odometry_to_frame_ && have_odometry_ && time_ok && frame.timestamp > hold_.timestamp)
    hold_.timestamp = frame.timestamp;

  if (time_ok) {
    predictTo(frame.timestamp, ekf, warnings);
    have_frame_ = true;
    last_frame_time_ = frame.timestamp;
  }
  return motion;
}

void MotionPrediction::predictTo(double t, PoseEkf& ekf, std::vector<std::string>& warnings) const {
  if (!ekf.initialised()) return;
  const double dt = t - ekf.time();
  if (!(dt > 0.0)) return;
  if (odometryDrives()) {
    const double age = t - hold_.timestamp;
    // The part of dt the held sample still covers; the rest is a gap.
    const double covered =
        std::min(dt, std::max(0.0, options_.odometry_gap_s - (ekf.time() - hold_.timestamp)));
    if (age > options_.odometry_gap_s)
      warnings.push_back(fmt::format("odometry gap: the last sample is {:.3f} s old", age));
    ekf.predictWithOdometry(hold_.speed, hold_.yaw_rate, dt);
    if (dt > covered) ekf.predictWithoutOdometry(dt - covered);
  } else if (constant_velocity_) {
    ekf.predictWithOdometry(constant_velocity_->speed, constant_velocity_->yaw_rate, dt);
    ekf.predictWithoutOdometry(dt);
  } else {
    ekf.predictWithoutOdometry(dt);
  }
  ekf.setTime(t);
}

void MotionPrediction::noteFix(double t, const PoseEkf& ekf) {
  if (odometryDrives()) return;
  if (last_fix_ && t > last_fix_->first &&
      t - last_fix_->first < options_.constant_velocity_max_gap_s) {
    const double dt = t - last_fix_->first;
    const geometry::Pose2 delta = last_fix_->second.inverse() * ekf.pose();
    OdometrySample m;
    m.timestamp = t;
    m.speed = delta.x / dt;
    m.yaw_rate = delta.yaw / dt;
    constant_velocity_ = m;
  } else {
    constant_velocity_.reset();
  }
  last_fix_ = std::make_pair(t, ekf.pose());
}

}  // namespace parkloc::localize
