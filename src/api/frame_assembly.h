#pragma once
// Frame sets from images and odometry as they arrive: the live counterpart of io/frame_sets.h,
// which groups a recorded drive knowing every capture time in advance. Here no later image is
// known, so a set closes as soon as it can no longer grow: it holds every camera, or an image
// arrives that cannot join it (its camera is already in the set, or it was captured more than
// the tolerance after the set's first image). Sets therefore span at most twice the tolerance
// and come out in the order they close. The rules for late images and odometry are those
// include/parkloc/parkloc.h states to the user.
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "common/odometry_sample.h"
#include "localize/frame_types.h"

namespace parkloc::api {

class FrameAssembly {
 public:
  FrameAssembly(std::vector<std::string> cameras, double tolerance_s);

  // The frame sets this image closes, oldest first (none, one, or two when the image closes
  // the open set and, on a one-camera rig, its own).
  std::vector<localize::FrameInput> addImage(const std::string& camera, double timestamp,
                                             const cv::Mat& image);
  void addOdometry(const OdometrySample& sample);
  // The open set, complete or not; empty when none is open.
  std::optional<localize::FrameInput> flush();
  void reset();

  // What was dropped since the last call, one line each.
  std::vector<std::string> takeWarnings();

 private:
  localize::FrameInput close();

  std::vector<std::string> cameras_;
  double tolerance_s_;
  std::optional<localize::FrameInput> open_;
  double open_anchor_ = 0.0;  // capture time of the open set's first image
  std::optional<double> last_closed_;  // time of the last set handed out
  std::deque<OdometrySample> odometry_;
  std::optional<double> last_odometry_;
  std::vector<std::string> warnings_;
};

}  // namespace parkloc::api
