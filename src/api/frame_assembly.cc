#include "api/frame_assembly.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace parkloc::api {

FrameAssembly::FrameAssembly(std::vector<std::string> cameras, double tolerance_s)
    : cameras_(std::move(cameras)), tolerance_s_(tolerance_s) {}

std::vector<localize::FrameInput> FrameAssembly::addImage(const std::string& camera,
                                                          double timestamp, const cv::Mat& image) {
  std::vector<localize::FrameInput> closed;
  if (std::find(cameras_.begin(), cameras_.end(), camera) == cameras_.end()) {
    warnings_.push_back(fmt::format("image of camera '{}' dropped: not in the calibration", camera));
    return closed;
  }
  if (!image.empty() && image.type() != CV_8UC3) {
    // The spotter reads 8-bit BGR only; this camera's image is missing from its set.
    warnings_.push_back(fmt::format("image of camera '{}' at {:.6f} s dropped: not 8-bit BGR",
                                    camera, timestamp));
    return closed;
  }
  if (!std::isfinite(timestamp)) {
    warnings_.push_back(fmt::format("image of camera '{}' dropped: capture time {}", camera,
                                    timestamp));
    return closed;
  }
  // Sets go to the pipeline in time order: an image from before the last processed set, or
  // from before the open set's window, missed its set.
  const bool before_window = open_ && timestamp < open_anchor_ - tolerance_s_;
  if ((last_closed_ && timestamp <= *last_closed_) || before_window) {
    warnings_.push_back(fmt::format(
        "image of camera '{}' at {:.6f} s dropped: it arrived after its frame set was processed",
        camera, timestamp));
    return closed;
  }
  if (open_) {
    const bool has_camera =
        std::any_of(open_->cameras.begin(), open_->cameras.end(),
                    [&](const localize::CameraInput& c) { return c.camera == camera; });
    if (has_camera || timestamp > open_anchor_ + tolerance_s_) closed.push_back(close());
  }
  if (!open_) {
    open_.emplace();
    open_->timestamp = timestamp;
    open_anchor_ = timestamp;
  }
  localize::CameraInput input;
  input.camera = camera;
  input.image = image;
  input.capture_time = timestamp;
  open_->cameras.push_back(std::move(input));
  open_->timestamp = std::min(open_->timestamp, timestamp);
  if (open_->cameras.size() == cameras_.size()) closed.push_back(close());
  return closed;
}

void FrameAssembly::addOdometry(const OdometrySample& sample) {
  const bool finite = std::isfinite(sample.timestamp) && std::isfinite(sample.speed) &&
                      std::isfinite(sample.yaw_rate);
  if (!finite) {
    warnings_.push_back(fmt::format("odometry sample at {} s dropped: non-finite value",
                                    sample.timestamp));
    return;
  }
  if (last_odometry_ && sample.timestamp <= *last_odometry_) {
    warnings_.push_back(fmt::format(
        "odometry sample at {:.6f} s dropped: not after the previous one at {:.6f} s",
        sample.timestamp, *last_odometry_));
    return;
  }
  last_odometry_ = sample.timestamp;
  // The pipeline integrates a set's samples from the previous set's time on: one from before
  // that would be integrated twice or backwards.
  if (last_closed_ && sample.timestamp <= *last_closed_) {
    warnings_.push_back(fmt::format(
        "odometry sample at {:.6f} s dropped: its frame set at {:.6f} s was already processed",
        sample.timestamp, *last_closed_));
    return;
  }
  odometry_.push_back(sample);
}

std::optional<localize::FrameInput> FrameAssembly::flush() {
  if (!open_) return std::nullopt;
  return close();
}

void FrameAssembly::reset() {
  open_.reset();
  last_closed_.reset();
  odometry_.clear();
  last_odometry_.reset();
}

std::vector<std::string> FrameAssembly::takeWarnings() {
  std::vector<std::string> out;
  out.swap(warnings_);
  return out;
}

localize::FrameInput FrameAssembly::close() {
  localize::FrameInput frame = std::move(*open_);
  open_.reset();
  while (!odometry_.empty() && odometry_.front().timestamp <= frame.timestamp) {
    frame.odometry.push_back(odometry_.front());
    odometry_.pop_front();
  }
  last_closed_ = frame.timestamp;
  return frame;
}

}  // namespace parkloc::api
