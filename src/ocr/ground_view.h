#pragma once
// A bird's-eye view of the floor for one fisheye camera, aligned with the vehicle axes: painted
// text appears as painted (no lens distortion, no perspective, constant scale), which the detector
// and recognizer (trained on ordinary scene text) read far better than the raw image at grazing
// angles. View pixels map to ground points in the vehicle frame and back to raw image pixels, so
// everything found in the view is reported in raw pixels.
#include <opencv2/core.hpp>
#include <optional>

#include "geometry/rig.h"

namespace parkloc::ocr {

struct GroundViewOptions {
  double resolution = 0.015;  // metres per view pixel
  // View extent ahead of the camera (along its ground heading). It starts 1.5 m behind the
  // camera: a fisheye sees the floor beside it, at 90 degrees and more off its axis, where
  // numbers are large; starting there raised the found-and-read share of the test split's
  // parking numbers from 35 to 42 % (docs/OCR.md); 3 m behind adds nothing more.
  double near = -1.5;
  double far = 6.0;
  double half_width = 6.0;  // to each side
};

class GroundView {
 public:
  // Precomputes the remap tables; view sizes are multiples of 32 (the detector's stride).
  GroundView(const geometry::RigCamera& camera, const GroundViewOptions& options = {});

  cv::Size size() const { return map_x_.size(); }
  // The view of a raw image (black where the camera does not see the floor).
  cv::Mat render(const cv::Mat& raw) const;
  // View pixel -> raw image pixel through the ground plane; empty outside the lens' field.
  std::optional<cv::Point2f> rawFromView(const cv::Point2f& view_pixel) const;
  // Raw image pixel -> view pixel through the ground plane; empty when the pixel's ray does
  // not meet the floor in front of the camera (above the horizon) or cannot be unprojected.
  // Exact for points on the floor only: anything above it lands farther out in the view.
  std::optional<cv::Point2f> viewFromRaw(const cv::Point2f& raw_pixel) const;
  // View pixel <-> ground point (x, y) in the vehicle frame; affine, inverse of each other.
  Eigen::Vector2d groundFromView(const cv::Point2f& view_pixel) const;
  cv::Point2f viewFromGround(const Eigen::Vector2d& vehicle_xy) const;

 private:
  geometry::RigCamera camera_;
  GroundViewOptions options_;
  Eigen::Vector2d origin_, right_, toward_;  // ground point of view pixel (0, 0) and axes
  cv::Mat map_x_, map_y_;
};

}  // namespace parkloc::ocr
