#include "ocr/quad.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace parkloc::ocr {

Quad quadFromRotatedRect(const cv::RotatedRect& rect) {
  const double angle = rect.angle * CV_PI / 180.0;
  cv::Point2f along(static_cast<float>(std::cos(angle)), static_cast<float>(std::sin(angle)));
  float w = rect.size.width, h = rect.size.height;
  if (h > w) {
    along = {-along.y, along.x};
    std::swap(w, h);
  }
  // Forward is the direction with positive x; a vertical box reads bottom to top.
  if (along.x < -1e-6f || (std::abs(along.x) <= 1e-6f && along.y > 0.f)) along = -along;
  const cv::Point2f down(-along.y, along.x);  // image y points down
  const cv::Point2f c = rect.center;
  const cv::Point2f u = along * (w * 0.5f), v = down * (h * 0.5f);
  return {c - u - v, c + u - v, c + u + v, c - u + v};
}

Quad shiftedBy180(const Quad& quad) { return {quad[2], quad[3], quad[0], quad[1]}; }

std::optional<Quad> orientedAlong(const Quad& quad, const cv::Point2f& reading, double max_angle) {
  const cv::Point2f along = 0.5f * (quad[1] + quad[2]) - 0.5f * (quad[0] + quad[3]);
  const double lengths = cv::norm(along) * cv::norm(reading);
  if (!(lengths > 0.0)) return std::nullopt;
  const double cos_angle = along.dot(reading) / lengths;
  if (std::abs(cos_angle) < std::cos(max_angle)) return std::nullopt;
  return cos_angle >= 0.0 ? quad : shiftedBy180(quad);
}

float quadWidth(const Quad& q) {
  return 0.5f * static_cast<float>(cv::norm(q[1] - q[0]) + cv::norm(q[2] - q[3]));
}
float quadHeight(const Quad& q) {
  return 0.5f * static_cast<float>(cv::norm(q[3] - q[0]) + cv::norm(q[2] - q[1]));
}

cv::Point2f quadCentre(const Quad& q) { return (q[0] + q[1] + q[2] + q[3]) * 0.25f; }

Quad expandQuad(const Quad& q, float ratio_x, float ratio_y) {
  const cv::Point2f unit[4] = {{0.f, 0.f}, {1.f, 0.f}, {1.f, 1.f}, {0.f, 1.f}};
  const cv::Mat unit_from_quad = cv::getPerspectiveTransform(q.data(), unit);
  const float ax = 0.5f * ratio_x, ay = 0.5f * ratio_y;
  const Quad expanded = {cv::Point2f(0.5f - ax, 0.5f - ay), cv::Point2f(0.5f + ax, 0.5f - ay),
                         cv::Point2f(0.5f + ax, 0.5f + ay), cv::Point2f(0.5f - ax, 0.5f + ay)};
  return transformQuad(expanded, unit_from_quad.inv());
}

cv::Mat rectifyingHomography(const Quad& quad, int width, int height) {
  // Pixel centres at integers: the outer edges of the output are at -0.5 and size - 0.5.
  const float x0 = -0.5f, y0 = -0.5f, x1 = width - 0.5f, y1 = height - 0.5f;
  const cv::Point2f dst[4] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  return cv::getPerspectiveTransform(quad.data(), dst);
}

cv::Mat rectifiedCrop(const cv::Mat& image, const Quad& quad, int height, int min_width,
                      int max_width) {
  const float h = std::max(quadHeight(quad), 1.f);
  const int width =
      std::clamp(static_cast<int>(std::lround(quadWidth(quad) / h * height)), min_width, max_width);
  cv::Mat crop;
  cv::warpPerspective(image, crop, rectifyingHomography(quad, width, height), {width, height},
                      cv::INTER_LINEAR, cv::BORDER_REPLICATE);
  return crop;
}

Quad transformQuad(const Quad& quad, const cv::Mat& homography) {
  std::vector<cv::Point2f> in(quad.begin(), quad.end()), out;
  cv::perspectiveTransform(in, out, homography);
  return {out[0], out[1], out[2], out[3]};
}

}  // namespace parkloc::ocr
