#include "ocr/db_postprocess.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace parkloc::ocr {
namespace {

// Mean probability inside the polygon, over its bounding box (PaddleOCR's "fast" score).
float meanInside(const cv::Mat& probability, const std::vector<cv::Point2f>& polygon) {
  cv::Rect box = cv::boundingRect(polygon) & cv::Rect(0, 0, probability.cols, probability.rows);
  if (box.area() <= 0) return 0.f;
  cv::Mat mask = cv::Mat::zeros(box.size(), CV_8U);
  std::vector<cv::Point> shifted;
  for (const auto& p : polygon) shifted.emplace_back(cvRound(p.x - box.x), cvRound(p.y - box.y));
  cv::fillPoly(mask, std::vector<std::vector<cv::Point>>{shifted}, cv::Scalar(1));
  return static_cast<float>(cv::mean(probability(box), mask)[0]);
}

}  // namespace

cv::RotatedRect unclipRect(const cv::RotatedRect& rect, double unclip_ratio) {
  const double w = rect.size.width, h = rect.size.height;
  const double perimeter = 2.0 * (w + h);
  if (perimeter <= 0.0) return rect;
  // Offsetting a rectangle outward by D (round joins) has the rectangle grown by D on
  // every side as its minimum-area box.
  const double distance = w * h * unclip_ratio / perimeter;
  return {rect.center,
          cv::Size2f(static_cast<float>(w + 2 * distance), static_cast<float>(h + 2 * distance)),
          rect.angle};
}

Quad reunclipQuad(const Quad& grown, double from_ratio, double to_ratio) {
  const double w = quadWidth(grown), h = quadHeight(grown);
  if (w <= 0.0 || h <= 0.0 || from_ratio <= 0.0) return grown;
  // unclipRect grows a w0 x h0 kernel by d = r w0 h0 / (2 (w0 + h0)) on every side; with
  // w0 = w - 2d and h0 = h - 2d that is (4r + 8) d^2 - 2 (r + 1) (w + h) d + r w h = 0, whose
  // smaller root leaves a kernel of positive size.
  const double r = from_ratio;
  const double a = 4.0 * r + 8.0, b = -2.0 * (r + 1.0) * (w + h), c = r * w * h;
  const double discriminant = b * b - 4.0 * a * c;
  if (discriminant < 0.0) return grown;
  const double d = (-b - std::sqrt(discriminant)) / (2.0 * a);
  const double w0 = w - 2.0 * d, h0 = h - 2.0 * d;
  if (w0 <= 0.0 || h0 <= 0.0) return grown;
  const double d_to = to_ratio * w0 * h0 / (2.0 * (w0 + h0));
  return expandQuad(grown, static_cast<float>((w0 + 2.0 * d_to) / w),
                    static_cast<float>((h0 + 2.0 * d_to) / h));
}

std::vector<DbBox> dbBoxesFromProbability(const cv::Mat& probability, const DbOptions& options) {
  CV_Assert(probability.type() == CV_32F);
  cv::Mat binary = probability > options.binary_threshold;
  if (options.dilate) cv::dilate(binary, binary, cv::Mat::ones(2, 2, CV_8U));
  std::vector<std::vector<cv::Point>> contours;
  cv::findContours(binary, contours, cv::RETR_LIST, cv::CHAIN_APPROX_SIMPLE);
  if (static_cast<int>(contours.size()) > options.max_candidates)
    contours.resize(static_cast<size_t>(options.max_candidates));

  std::vector<DbBox> boxes;
  for (const auto& contour : contours) {
    if (contour.size() < 3) continue;
    const cv::RotatedRect rect = cv::minAreaRect(contour);
    if (std::min(rect.size.width, rect.size.height) < options.min_size) continue;
    cv::Point2f corners[4];
    rect.points(corners);
    const float score = meanInside(probability, {corners, corners + 4});
    if (score < options.box_threshold) continue;
    const cv::RotatedRect grown = unclipRect(rect, options.unclip_ratio);
    if (std::min(grown.size.width, grown.size.height) < options.min_size + 2) continue;
    boxes.push_back({quadFromRotatedRect(grown), score});
  }
  return boxes;
}

std::vector<size_t> readingPriority(const std::vector<DbBox>& boxes, float confident_score) {
  std::vector<size_t> order(boxes.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  auto rank = [&](size_t i) {
    return std::make_pair(boxes[i].score >= confident_score,
                          quadWidth(boxes[i].quad) * quadHeight(boxes[i].quad));
  };
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return rank(a) > rank(b); });
  return order;
}

}  // namespace parkloc::ocr
