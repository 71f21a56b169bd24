#pragma once
// The annotated frame of `parkloc run --video`: the rig's camera views with the spotted
// text (green: used, red: rejected, with the reason) and a bird's-eye view of the map with
// the estimated and (when known) true trajectory.
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "geometry/pose.h"
#include "localize/pipeline.h"
#include "map/hd_map.h"

namespace parkloc::run {

struct BirdsEyeView {
  cv::Rect2d bounds;  // map area shown (metres)
  int size_px = 800;  // square canvas
  // Map point -> canvas pixel (north up).
  cv::Point2f toPixel(const Eigen::Vector2d& p) const;
  static BirdsEyeView fitting(const map::HdMap& map, const std::vector<geometry::Pose2>& poses,
                              int size_px = 800);
};

struct VisualizationInput {
  const localize::FrameResult* result = nullptr;
  // Camera images in the order of result->cameras (empty Mat: drawn grey).
  std::vector<cv::Mat> images;
  std::vector<geometry::Pose2> estimated_so_far;
  std::vector<geometry::Pose2> truth_so_far;
  std::optional<geometry::Pose2> truth_now;
  // A real-time replay's pose age (output time less release time) and the frame sets dropped
  // so far; unset offline.
  std::optional<double> pose_age_ms;
  size_t dropped_so_far = 0;
};

// A 8-bit BGR frame: the camera views in two columns 640 px wide (two rows of 400 px for up to
// four cameras, three of 266 px for five or six) and the bird's-eye view.
cv::Mat drawRunFrame(const VisualizationInput& input, const map::HdMap& map,
                     const BirdsEyeView& view);

}  // namespace parkloc::run
