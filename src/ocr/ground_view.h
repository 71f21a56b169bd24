#pragma once
// A bird's-eye view of the floor for one fisheye camera, aligned with the vehicle axes: painted
// text appears as painted (no lens distortion, no perspective, constant scale), which the detector
// and recognizer (trained on ordinary scene text) read far better than the raw image at grazing
// angles. View pixels map to ground points in the vehicle frame and back to raw image pixels, so
// everything found in the view is reported in raw pixels.
#include <opencv2/core.hpp>
#include <optional>

#include "geometry/rig.h"
#include "ocr/quad.h"

namespace parkloc::ocr {

struct GroundViewOptions {
  double resolution = 0.015;  // metres per view pixel
  // View extent ahead of the camera (along its ground heading). It starts 1.5 m behind the
  // camera: a fisheye sees the floor beside it, at 90 degrees and more off its axis, where
  // numbers are large (docs/OCR.md). A camera on a vehicle body sees none of that floor past
  // the body, and the view is cropped to what it sees.
  double near = -1.5;
  double far = 6.0;
  double half_width = 6.0;  // to each side
  // `far` and `half_width` were chosen for cameras of this focal length (pixels per radian,
  // the default rig's). A camera that resolves more sees a number as many pixels across
  // proportionally farther away (a text w wide at distance d spans f w / d pixels), so its view
  // reaches farther by fx / reference_focal_px, at most max_extent_scale times: the view's
  // area, and the detector's time, grow with the square. 0: the extents as given.
  double reference_focal_px = 365.0;
  double max_extent_scale = 1.5;
};

// The extents of `options` for `camera` (GroundViewOptions::reference_focal_px).
GroundViewOptions extentsFor(const geometry::RigCamera& camera, const GroundViewOptions& options);

class GroundView {
 public:
  // Precomputes the remap tables; view sizes are multiples of 32 (the detector's stride). The
  // view is the options' rectangle cropped to the part where the camera sees the floor (in the
  // image, not behind the vehicle's body), with a margin of 32 view pixels.
  GroundView(const geometry::RigCamera& camera, const GroundViewOptions& options = {});

  cv::Size size() const { return map_x_.size(); }
  const geometry::RigCamera& camera() const { return camera_; }
  const GroundViewOptions& options() const { return options_; }
  // The view of a raw image: black outside the lens' field; where the vehicle's body hides
  // the floor, whatever the image shows there (the body), as a detector would see it.
  cv::Mat render(const cv::Mat& raw) const;
  // The part of the view inside `window` (view pixels, clipped to the view), rendered alone.
  cv::Mat render(const cv::Mat& raw, const cv::Rect& window) const;
  cv::Rect rect() const { return {cv::Point(0, 0), size()}; }
  // View pixel -> raw image pixel through the ground plane; empty outside the lens' field.
  // Where the vehicle's body hides the floor, the pixel that shows the body.
  std::optional<cv::Point2f> rawFromView(const cv::Point2f& view_pixel) const;
  // Whether the camera sees the floor at a view pixel: inside its image (half a pixel in from
  // the border) and not behind the vehicle's body.
  bool seesTheFloorAt(const cv::Point2f& view_pixel) const;
  // Raw image pixel -> view pixel through the ground plane; empty when the pixel's ray does
  // not meet the floor in front of the camera (above the horizon) or cannot be unprojected.
  // Exact for points on the floor only: anything above it lands farther out in the view.
  std::optional<cv::Point2f> viewFromRaw(const cv::Point2f& raw_pixel) const;
  // The same for each corner of a quad; empty when one of them does not map.
  std::optional<Quad> rawFromView(const Quad& view_quad) const;
  std::optional<Quad> viewFromRaw(const Quad& raw_quad) const;
  // View pixel <-> ground point (x, y) in the vehicle frame; affine, inverse of each other.
  Eigen::Vector2d groundFromView(const cv::Point2f& view_pixel) const;
  cv::Point2f viewFromGround(const Eigen::Vector2d& vehicle_xy) const;

 private:
  bool hiddenByTheBody(const Eigen::Vector2d& vehicle_xy) const;
  // seesTheFloorAt for a view pixel's raw pixel (pixel centres 0 .. size - 1) and ground point.
  bool seesTheFloor(const cv::Point2f& raw_pixel, const Eigen::Vector2d& vehicle_xy) const;
  void buildMaps(int cols, int rows);  // from origin_, right_, toward_

  geometry::RigCamera camera_;
  GroundViewOptions options_;
  Eigen::Vector2d origin_, right_, toward_;  // ground point of view pixel (0, 0) and axes
  cv::Mat map_x_, map_y_;
};

}  // namespace parkloc::ocr
