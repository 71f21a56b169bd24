#include "ocr/ground_view.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "geometry/ground_projection.h"

namespace parkloc::ocr {

// Everything here is in metres on the floor, and the view's pixels are `resolution` metres
// whatever the camera's image size and lens: a number shows as large in every rig's view as the
// floor detector learnt it; the calibration alone maps view pixels to raw ones.
GroundViewOptions extentsFor(const geometry::RigCamera& camera, const GroundViewOptions& options) {
  GroundViewOptions out = options;
  if (options.reference_focal_px <= 0.0 || !(camera.model.fx > 0.0)) return out;
  const double scale = std::min(camera.model.fx / options.reference_focal_px,
                                std::max(1.0, options.max_extent_scale));
  out.far *= scale;
  out.half_width *= scale;
  return out;
}

GroundView::GroundView(const geometry::RigCamera& camera, const GroundViewOptions& view_options)
    : camera_(camera), options_(extentsFor(camera, view_options)) {
  const GroundViewOptions& options = options_;
  const Eigen::Vector3d axis = camera.vehicle_from_camera.linear().col(2);
  Eigen::Vector2d forward = axis.head<2>();
  if (forward.norm() < 1e-6) forward = Eigen::Vector2d::UnitX();  // looking straight down
  forward.normalize();
  // The floor ahead of the camera: `near` to `far` along its heading, `half_width` to each
  // side. The view is axis-aligned with the vehicle (x to the right of the view, y up), seen
  // from above: painted numbers at the slot ends read along the aisle, i.e. along the
  // vehicle's x axis, so they appear horizontal (or upside down) in every camera's view,
  // which suits the detector far better than text standing at 90 degrees.
  const Eigen::Vector2d side(-forward.y(), forward.x());
  const Eigen::Vector2d foot = camera.vehicle_from_camera.translation().head<2>();
  Eigen::Vector2d lo(1e9, 1e9), hi(-1e9, -1e9);
  for (double d : {options.near, options.far})
    for (double l : {-options.half_width, options.half_width}) {
      const Eigen::Vector2d g = foot + forward * d + side * l;
      lo = lo.cwiseMin(g);
      hi = hi.cwiseMax(g);
    }
  right_ = Eigen::Vector2d::UnitX();
  toward_ = -Eigen::Vector2d::UnitY();
  origin_ = Eigen::Vector2d(lo.x(), hi.y());

  auto roundUp32 = [](double v) {
    return std::max(32, static_cast<int>(std::ceil(v / 32.0)) * 32);
  };
  buildMaps(roundUp32((hi.x() - lo.x()) / options.resolution),
            roundUp32((hi.y() - lo.y()) / options.resolution));
  // Cropped to the rows and columns where the camera sees the floor, and a margin: the
  // detector's time goes with the view's area, and the floor under the vehicle's body and,
  // for the front and rear cameras, beside it is hidden. The margin (0.48 m, a number's length)
  // keeps a number that the body cuts off the view's edge, where the detector finds text worse.
  cv::Mat seen(size(), CV_8U, cv::Scalar(0));
  for (int r = 0; r < seen.rows; ++r)
    for (int c = 0; c < seen.cols; ++c) {
      const cv::Point2f view_pixel(c, r);
      const cv::Point2f raw(map_x_.at<float>(r, c), map_y_.at<float>(r, c));
      seen.at<uint8_t>(r, c) = seesTheFloor(raw, groundFromView(view_pixel));
    }
  constexpr double kMarginM = 0.48;
  const int kMarginPx = static_cast<int>(std::lround(kMarginM / options.resolution));
  const cv::Rect box = (cv::boundingRect(seen) + cv::Size(2 * kMarginPx, 2 * kMarginPx) -
                        cv::Point(kMarginPx, kMarginPx)) &
                       rect();
  if (box.area() > 0 && box.size() != size()) {
    origin_ = groundFromView(cv::Point2f(box.x, box.y));
    buildMaps(roundUp32(box.width), roundUp32(box.height));
  }
}

void GroundView::buildMaps(int cols, int rows) {
  map_x_.create(rows, cols, CV_32F);
  map_y_.create(rows, cols, CV_32F);
  const geometry::Rigid3 camera_from_vehicle = camera_.vehicle_from_camera.inverse();
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      const Eigen::Vector2d g = groundFromView(cv::Point2f(c, r));
      const auto px =
          camera_.model.project(camera_from_vehicle * Eigen::Vector3d(g.x(), g.y(), 0.0));
      map_x_.at<float>(r, c) = px ? static_cast<float>(px->x()) : -1e4f;
      map_y_.at<float>(r, c) = px ? static_cast<float>(px->y()) : -1e4f;
    }
}

cv::Mat GroundView::render(const cv::Mat& raw) const {
  cv::Mat view;
  cv::remap(raw, view, map_x_, map_y_, cv::INTER_LINEAR, cv::BORDER_CONSTANT, cv::Scalar::all(0));
  return view;
}

cv::Mat GroundView::render(const cv::Mat& raw, const cv::Rect& window) const {
  const cv::Rect inside = window & rect();
  cv::Mat view;
  if (inside.empty()) return view;
  cv::remap(raw, view, map_x_(inside), map_y_(inside), cv::INTER_LINEAR, cv::BORDER_CONSTANT,
            cv::Scalar::all(0));
  return view;
}

Eigen::Vector2d GroundView::groundFromView(const cv::Point2f& v) const {
  return origin_ + right_ * (v.x * options_.resolution) + toward_ * (v.y * options_.resolution);
}

cv::Point2f GroundView::viewFromGround(const Eigen::Vector2d& vehicle_xy) const {
  // right_ and toward_ are orthonormal, so the inverse is a projection onto each axis.
  const Eigen::Vector2d d = (vehicle_xy - origin_) / options_.resolution;
  return cv::Point2f(static_cast<float>(d.dot(right_)), static_cast<float>(d.dot(toward_)));
}

bool GroundView::hiddenByTheBody(const Eigen::Vector2d& vehicle_xy) const {
  return camera_.body &&
         geometry::bodyBlocks(*camera_.body, camera_.vehicle_from_camera.translation(),
                              Eigen::Vector3d(vehicle_xy.x(), vehicle_xy.y(), 0.0));
}

bool GroundView::seesTheFloor(const cv::Point2f& raw_pixel,
                              const Eigen::Vector2d& vehicle_xy) const {
  return camera_.model.inImage({raw_pixel.x, raw_pixel.y}, /*margin=*/0.5) &&
         !hiddenByTheBody(vehicle_xy);
}

bool GroundView::seesTheFloorAt(const cv::Point2f& view_pixel) const {
  const auto raw = rawFromView(view_pixel);
  return raw && seesTheFloor(*raw, groundFromView(view_pixel));
}

std::optional<cv::Point2f> GroundView::rawFromView(const cv::Point2f& v) const {
  const Eigen::Vector2d g = groundFromView(v);
  const auto px = camera_.model.project(camera_.vehicle_from_camera.inverse() *
                                        Eigen::Vector3d(g.x(), g.y(), 0.0));
  if (!px) return std::nullopt;
  return cv::Point2f(static_cast<float>(px->x()), static_cast<float>(px->y()));
}

std::optional<cv::Point2f> GroundView::viewFromRaw(const cv::Point2f& raw_pixel) const {
  const auto floor = geometry::pixelToPlane(camera_, Eigen::Vector2d(raw_pixel.x, raw_pixel.y),
                                            geometry::Plane::ground());
  if (!floor) return std::nullopt;
  return viewFromGround(floor->head<2>());
}

std::optional<Quad> GroundView::rawFromView(const Quad& view_quad) const {
  Quad out;
  for (size_t k = 0; k < out.size(); ++k) {
    const auto p = rawFromView(view_quad[k]);
    if (!p) return std::nullopt;
    out[k] = *p;
  }
  return out;
}

std::optional<Quad> GroundView::viewFromRaw(const Quad& raw_quad) const {
  Quad out;
  for (size_t k = 0; k < out.size(); ++k) {
    const auto p = viewFromRaw(raw_quad[k]);
    if (!p) return std::nullopt;
    out[k] = *p;
  }
  return out;
}

}  // namespace parkloc::ocr
