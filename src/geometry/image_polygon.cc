#include "geometry/image_polygon.h"

#include <opencv2/imgproc.hpp>

namespace parkloc::geometry {
namespace {

std::vector<cv::Point2f> convexHull(const std::vector<cv::Point2f>& polygon) {
  if (polygon.size() < 3) return {};
  std::vector<cv::Point2f> hull;
  cv::convexHull(polygon, hull);
  return hull;
}

}  // namespace

double polygonArea(const std::vector<cv::Point2f>& polygon) {
  if (polygon.size() < 3) return 0.0;
  return cv::contourArea(polygon);
}

double intersectionArea(const std::vector<cv::Point2f>& a, const std::vector<cv::Point2f>& b) {
  const std::vector<cv::Point2f> hull_a = convexHull(a), hull_b = convexHull(b);
  if (polygonArea(hull_a) <= 0.0 || polygonArea(hull_b) <= 0.0) return 0.0;
  std::vector<cv::Point2f> overlap;
  return static_cast<double>(cv::intersectConvexConvex(hull_a, hull_b, overlap, true));
}

double polygonIoU(const std::vector<cv::Point2f>& a, const std::vector<cv::Point2f>& b) {
  const double area_a = polygonArea(convexHull(a)), area_b = polygonArea(convexHull(b));
  const double overlap = intersectionArea(a, b);
  const double united = area_a + area_b - overlap;
  return united > 0.0 ? overlap / united : 0.0;
}

double polygonIoU(const Quad& a, const Quad& b) {
  return polygonIoU(std::vector<cv::Point2f>(a.begin(), a.end()),
                    std::vector<cv::Point2f>(b.begin(), b.end()));
}

std::vector<cv::Point2f> clippedToImage(const std::vector<cv::Point2f>& polygon, cv::Size size) {
  const std::vector<cv::Point2f> hull = convexHull(polygon);
  if (polygonArea(hull) <= 0.0 || size.width <= 0 || size.height <= 0) return {};
  const float right = size.width - 0.5f, bottom = size.height - 0.5f;
  const std::vector<cv::Point2f> image = {
      {-0.5f, -0.5f}, {right, -0.5f}, {right, bottom}, {-0.5f, bottom}};
  std::vector<cv::Point2f> inside;
  if (cv::intersectConvexConvex(hull, image, inside, true) <= 0.f) return {};
  return inside;
}

}  // namespace parkloc::geometry
