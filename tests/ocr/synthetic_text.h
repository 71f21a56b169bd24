#pragma once
// Test scenes for the OCR module: a line of text rendered with FreeType (DejaVu Sans Bold),
// flat or painted on the floor and seen through a fisheye camera of the default rig.
#include <Eigen/Geometry>
#include <algorithm>
#include <opencv2/freetype.hpp>
#include <opencv2/imgproc.hpp>
#include <string>

#include "geometry/rig.h"
#include "ocr/quad.h"

namespace parkloc::ocr::testing {

inline const char* kTestFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf";

// The text's ink, cropped tight: white on black, 8-bit, `ink_height` rows tall.
inline cv::Mat renderInk(const std::string& text, int ink_height) {
  auto ft = cv::freetype::createFreeType2();
  ft->loadFontData(kTestFont, 0);
  const int font_height = ink_height * 2;
  int baseline = 0;
  const cv::Size size = ft->getTextSize(text, font_height, -1, &baseline);
  cv::Mat canvas3 = cv::Mat::zeros(size.height * 3, size.width + font_height, CV_8UC3);
  ft->putText(canvas3, text, {font_height / 2, size.height * 2}, font_height, cv::Scalar::all(255),
              -1, cv::LINE_AA, true);
  cv::Mat canvas;
  cv::cvtColor(canvas3, canvas, cv::COLOR_BGR2GRAY);
  const cv::Rect ink = cv::boundingRect(canvas);
  cv::Mat out;
  cv::resize(canvas(ink), out,
             {std::max(1, ink.width * ink_height / std::max(ink.height, 1)), ink_height}, 0, 0,
             cv::INTER_AREA);
  return out;
}

// A text line on a plain background, `margin` pixels of background around the ink.
inline cv::Mat renderTextLine(const std::string& text, int ink_height, int margin,
                              cv::Scalar ink = {30, 30, 30}, cv::Scalar paper = {235, 235, 235}) {
  const cv::Mat alpha = renderInk(text, ink_height);
  cv::Mat image(alpha.rows + 2 * margin, alpha.cols + 2 * margin, CV_8UC3, paper);
  cv::Mat roi = image(cv::Rect(margin, margin, alpha.cols, alpha.rows));
  cv::Mat a;
  alpha.convertTo(a, CV_32F, 1.0 / 255);
  cv::Mat a3;
  cv::merge(std::vector<cv::Mat>{a, a, a}, a3);
  cv::Mat fg(roi.size(), CV_32FC3, ink), bg;
  roi.convertTo(bg, CV_32FC3);
  cv::Mat blended = fg.mul(a3) + bg.mul(cv::Scalar::all(1.0) - a3);
  blended.convertTo(roi, CV_8UC3);
  return image;
}

struct FisheyeScene {
  cv::Mat image;
  Quad truth;  // projected corners of the text's ink box, reading order
};

// White paint on grey concrete: text of `width` x `height` metres whose centre lies at
// `centre` on the ground (vehicle frame) and that reads along `heading` (radians from the
// vehicle's x axis), seen by `camera`. Concrete at 95 x brightness grey levels, paint
// `ink_contrast` x brightness above it, sensor noise of 6 grey levels.
inline FisheyeScene renderFloorText(const geometry::RigCamera& camera, const std::string& text,
                                    const Eigen::Vector2d& centre, double heading, double width,
                                    double height, double brightness = 1.0,
                                    double ink_contrast = 140.0) {
  const auto& model = camera.model;
  const cv::Mat ink = renderInk(text, 160);
  const double ppm_x = ink.cols / width, ppm_y = ink.rows / height;
  const Eigen::Vector2d along(std::cos(heading), std::sin(heading));
  const Eigen::Vector2d up(-along.y(), along.x());
  const Eigen::Vector3d origin = camera.vehicle_from_camera.translation();
  const Eigen::Matrix3d R = camera.vehicle_from_camera.linear();

  cv::Mat map_x(model.height, model.width, CV_32F, cv::Scalar(-1e4f));
  cv::Mat map_y(model.height, model.width, CV_32F, cv::Scalar(-1e4f));
  // Only pixels near the text need the ray cast; project a ring around it for the bounds.
  std::vector<cv::Point2f> ring;
  for (int i = 0; i < 64; ++i) {
    const double a = 2 * CV_PI * i / 64;
    const Eigen::Vector2d g =
        centre + along * (0.8 * width * std::cos(a)) + up * (0.8 * width * std::sin(a));
    const auto px =
        model.project(camera.vehicle_from_camera.inverse() * Eigen::Vector3d(g.x(), g.y(), 0));
    if (px) ring.emplace_back(static_cast<float>(px->x()), static_cast<float>(px->y()));
  }
  const cv::Rect bounds = cv::boundingRect(ring) & cv::Rect(0, 0, model.width, model.height);
  for (int y = bounds.y; y < bounds.y + bounds.height; ++y)
    for (int x = bounds.x; x < bounds.x + bounds.width; ++x) {
      const auto ray = model.unproject({x, y});
      if (!ray) continue;
      const Eigen::Vector3d d = R * *ray;
      if (d.z() >= -1e-6) continue;
      const double t = -origin.z() / d.z();
      const Eigen::Vector2d g = (origin + t * d).head<2>() - centre;
      map_x.at<float>(y, x) = static_cast<float>((g.dot(along) + width / 2) * ppm_x - 0.5);
      map_y.at<float>(y, x) = static_cast<float>((height / 2 - g.dot(up)) * ppm_y - 0.5);
    }
  cv::Mat alpha;
  cv::remap(ink, alpha, map_x, map_y, cv::INTER_LINEAR, cv::BORDER_CONSTANT, cv::Scalar(0));
  cv::Mat a;
  alpha.convertTo(a, CV_32F, brightness / 255.0);
  cv::Mat floor(model.height, model.width, CV_32F);
  cv::RNG rng(12345);
  rng.fill(floor, cv::RNG::NORMAL, 0.0, 6.0);
  floor = floor + 95.0 * brightness;
  cv::Mat gray = floor + a * ink_contrast;
  cv::Mat gray8;
  gray.convertTo(gray8, CV_8U);
  FisheyeScene scene;
  cv::cvtColor(gray8, scene.image, cv::COLOR_GRAY2BGR);
  const Eigen::Vector2d corners[4] = {
      centre - along * width / 2 + up * height / 2, centre + along * width / 2 + up * height / 2,
      centre + along * width / 2 - up * height / 2, centre - along * width / 2 - up * height / 2};
  for (int k = 0; k < 4; ++k) {
    const auto px = model.project(camera.vehicle_from_camera.inverse() *
                                  Eigen::Vector3d(corners[k].x(), corners[k].y(), 0));
    scene.truth[k] = px ? cv::Point2f(px->x(), px->y()) : cv::Point2f(-1, -1);
  }
  return scene;
}

}  // namespace parkloc::ocr::testing
