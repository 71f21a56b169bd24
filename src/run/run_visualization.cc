#include "run/run_visualization.h"

#include <fmt/format.h>

#include <algorithm>
#include <Eigen/Eigenvalues>
#include <opencv2/imgproc.hpp>

namespace parkloc::run {
namespace {

constexpr int kViewWidth = 640;
constexpr int kViewHeight = 400;

cv::Scalar verdictColour(localize::AssociationVerdict v) {
  switch (v) {
    case localize::AssociationVerdict::kAccepted:
      return {60, 220, 60};
    case localize::AssociationVerdict::kWrongClass:
      return {200, 200, 200};
    default:
      return {40, 40, 230};
  }
}

void drawCamera(cv::Mat& canvas, const cv::Rect& where, const cv::Mat& image,
                const localize::CameraResult& camera, const localize::FrameResult& result) {
  cv::Mat view = canvas(where);
  double scale = 1.0;
  if (image.empty()) {
    view.setTo(cv::Scalar(60, 60, 60));
  } else {
    scale = std::min(static_cast<double>(where.width) / image.cols,
                     static_cast<double>(where.height) / image.rows);
    cv::Mat resized;
    cv::resize(image, resized, cv::Size(), scale, scale, cv::INTER_AREA);
    resized.copyTo(view(cv::Rect(0, 0, resized.cols, resized.rows)));
    if (!image.empty() && image.cols > 0) scale = static_cast<double>(resized.cols) / image.cols;
  }
  if (image.empty()) scale = static_cast<double>(where.width) / 1280.0;
  for (size_t i = 0; i < camera.instances.size(); ++i) {
    const auto& t = camera.instances[i];
    localize::AssociationVerdict verdict = localize::AssociationVerdict::kWrongClass;
    for (const auto& a : result.associations)
      if (a.camera == camera.camera && a.instance_index == static_cast<int>(i)) verdict = a.verdict;
    std::vector<cv::Point> polygon;
    for (const auto& p : t.polygon)
      polygon.emplace_back(static_cast<int>(p.x * scale), static_cast<int>(p.y * scale));
    const cv::Scalar colour = verdictColour(verdict);
    cv::polylines(view, polygon, true, colour, 2, cv::LINE_AA);
    cv::circle(view, polygon[0], 3, colour, cv::FILLED);  // reading order starts here
    std::string label = t.text;
    if (verdict != localize::AssociationVerdict::kAccepted) label += " (" + toString(verdict) + ")";
    cv::putText(view, label, polygon[0] + cv::Point(0, -4), cv::FONT_HERSHEY_SIMPLEX, 0.45, colour,
                1, cv::LINE_AA);
  }
  std::string title =
      camera.camera +
      (camera.full_frame ? "  full frame" : fmt::format("  {} regions", camera.regions));
  const auto handed = [&](const std::vector<std::string>& cameras) {
    return std::find(cameras.begin(), cameras.end(), camera.camera) != cameras.end();
  };
  if (handed(result.background_cameras)) title += "  full frame to the worker";
  if (handed(result.deferred_read_cameras)) title += "  reads to the worker";
  if (!camera.image_ok) title += "  (no image)";
  cv::putText(view, title, {8, 20}, cv::FONT_HERSHEY_SIMPLEX, 0.55, {255, 255, 255}, 1,
              cv::LINE_AA);
}

void drawTrajectory(cv::Mat& view, const BirdsEyeView& bev,
                    const std::vector<geometry::Pose2>& poses, const cv::Scalar& colour) {
  for (size_t i = 1; i < poses.size(); ++i)
    cv::line(view, bev.toPixel(poses[i - 1].translation()), bev.toPixel(poses[i].translation()),
             colour, 2, cv::LINE_AA);
}

void drawVehicle(cv::Mat& view, const BirdsEyeView& bev, const geometry::Pose2& pose,
                 const cv::Scalar& colour) {
  // A 4.7 x 1.85 m footprint, rear axle 1.0 m from the rear.
  const std::array<Eigen::Vector2d, 4> corners{
      Eigen::Vector2d(3.7, 0.925), Eigen::Vector2d(3.7, -0.925), Eigen::Vector2d(-1.0, -0.925),
      Eigen::Vector2d(-1.0, 0.925)};
  std::vector<cv::Point> polygon;
  for (const auto& c : corners) polygon.push_back(bev.toPixel(pose * c));
  cv::polylines(view, polygon, true, colour, 2, cv::LINE_AA);
}

}  // namespace

cv::Point2f BirdsEyeView::toPixel(const Eigen::Vector2d& p) const {
  const double scale = size_px / std::max(bounds.width, bounds.height);
  return {static_cast<float>((p.x() - bounds.x) * scale),
          static_cast<float>(size_px - (p.y() - bounds.y) * scale)};
}

BirdsEyeView BirdsEyeView::fitting(const map::HdMap& map, const std::vector<geometry::Pose2>& poses,
                                   int size_px) {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  auto grow = [&](const Eigen::Vector2d& p) {
    x0 = std::min(x0, p.x());
    y0 = std::min(y0, p.y());
    x1 = std::max(x1, p.x());
    y1 = std::max(y1, p.y());
  };
  // The driven area (with 15 m around it) when known, else the whole map.
  for (const auto& p : poses) grow(p.translation());
  if (poses.empty())
    for (const auto& l : map.landmarks()) grow(l.position.head<2>());
  if (x0 > x1) x0 = y0 = 0.0, x1 = y1 = 10.0;
  const double margin = poses.empty() ? 2.0 : 15.0;
  x0 -= margin, y0 -= margin, x1 += margin, y1 += margin;
  const double side = std::max(x1 - x0, y1 - y0);
  BirdsEyeView view;
  view.bounds = cv::Rect2d(0.5 * (x0 + x1) - 0.5 * side, 0.5 * (y0 + y1) - 0.5 * side, side, side);
  view.size_px = size_px;
  return view;
}

cv::Mat drawRunFrame(const VisualizationInput& input, const map::HdMap& map,
                     const BirdsEyeView& bev) {
  const localize::FrameResult& result = *input.result;
  cv::Mat canvas(2 * kViewHeight, 2 * kViewWidth + bev.size_px, CV_8UC3, cv::Scalar(30, 30, 30));
  // Two columns and as many rows as the rig needs (a rig has 2 to 6 cameras) in the height of
  // two 640x400 views, so every rig's video has the same frame size.
  const int rows = std::max(2, static_cast<int>((result.cameras.size() + 1) / 2));
  const int tile_height = 2 * kViewHeight / rows;
  for (size_t c = 0; c < result.cameras.size(); ++c) {
    const cv::Rect where(static_cast<int>(c % 2) * kViewWidth,
                         static_cast<int>(c / 2) * tile_height, kViewWidth, tile_height);
    drawCamera(canvas, where, c < input.images.size() ? input.images[c] : cv::Mat(),
               result.cameras[c], result);
  }

  cv::Mat view =
      canvas(cv::Rect(2 * kViewWidth, 0, bev.size_px, std::min(bev.size_px, canvas.rows)));
  view.setTo(cv::Scalar(245, 245, 245));
  for (const auto& l : map.landmarks()) {
    std::vector<cv::Point> polygon;
    for (const auto& c : l.corners()) polygon.push_back(bev.toPixel(c.head<2>()));
    const cv::Scalar colour = l.cls == map::TextClass::kParkingNumber ? cv::Scalar(150, 120, 60)
                                                                      : cv::Scalar(60, 120, 150);
    cv::polylines(view, polygon, true, colour, 1, cv::LINE_AA);
  }
  // Landmarks fused this frame set: green from the frame set's own spotting, orange from a
  // worker's texts of an earlier frame set (late fusion).
  const auto markAccepted = [&](const std::vector<localize::Association>& associations,
                                const cv::Scalar& colour, int radius) {
    for (const auto& a : associations) {
      if (a.verdict != localize::AssociationVerdict::kAccepted || a.landmark_id.empty()) continue;
      if (const auto* l = map.findById(a.landmark_id))
        cv::circle(view, bev.toPixel(l->position.head<2>()), radius, colour, 2, cv::LINE_AA);
    }
  };
  markAccepted(result.associations, {60, 200, 60}, 5);
  if (result.background) markAccepted(result.background->associations, {0, 140, 255}, 8);
  if (result.deferred_reads) markAccepted(result.deferred_reads->associations, {0, 140, 255}, 8);
  drawTrajectory(view, bev, input.truth_so_far, {120, 120, 120});
  drawTrajectory(view, bev, input.estimated_so_far, {40, 40, 220});
  if (input.truth_now) drawVehicle(view, bev, *input.truth_now, {120, 120, 120});
  if (result.has_pose) {
    drawVehicle(view, bev, result.pose, {40, 40, 220});
    // 3-sigma position ellipse.
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(
        result.covariance.topLeftCorner<2, 2>());
    const double scale = bev.size_px / std::max(bev.bounds.width, bev.bounds.height);
    const Eigen::Vector2d axis = eigen.eigenvectors().col(1);
    const cv::Size axes(
        std::max(1, static_cast<int>(3 * std::sqrt(std::max(0.0, eigen.eigenvalues()[1])) * scale)),
        std::max(1,
                 static_cast<int>(3 * std::sqrt(std::max(0.0, eigen.eigenvalues()[0])) * scale)));
    cv::ellipse(view, bev.toPixel(result.pose.translation()), axes,
                -std::atan2(axis.y(), axis.x()) * 180.0 / M_PI, 0, 360, {40, 40, 220}, 1,
                cv::LINE_AA);
  }
  std::string status = fmt::format("t {:.2f} s  {}", result.timestamp, toString(result.status));
  if (result.has_pose && input.truth_now)
    status += fmt::format("  error {:.3f} m",
                          (result.pose.translation() - input.truth_now->translation()).norm());
  status += fmt::format("  {:.1f} ms", result.timings.total_ms);
  cv::putText(view, status, {10, 24}, cv::FONT_HERSHEY_SIMPLEX, 0.6, {20, 20, 20}, 1, cv::LINE_AA);
  cv::putText(view, "red: estimate   grey: truth   orange: fused late", {10, 48},
              cv::FONT_HERSHEY_SIMPLEX, 0.5, {20, 20, 20}, 1, cv::LINE_AA);
  if (input.pose_age_ms)
    cv::putText(view,
                fmt::format("real time: pose age {:.1f} ms, {} frame sets dropped so far",
                            *input.pose_age_ms, input.dropped_so_far),
                {10, 72}, cv::FONT_HERSHEY_SIMPLEX, 0.5, {20, 20, 20}, 1, cv::LINE_AA);
  return canvas;
}

}  // namespace parkloc::run
