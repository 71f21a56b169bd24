#include "sim/ink_through_camera.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

namespace parkloc::sim {
namespace {

cv::Mat lumaOf(const cv::Mat& bgr, const cv::Rect& box) {
  cv::Mat grey, out;
  cv::cvtColor(bgr(box), grey, cv::COLOR_BGR2GRAY);
  grey.convertTo(out, CV_64F);
  return out;
}

}  // namespace

InkThroughCamera inkThroughCamera(const InkContrast& scene, const CameraStages& stages,
                                  const geometry::TextPolygon& polygon) {
  CV_Assert(stages.scene.type() == CV_8UC3 && stages.developed.type() == CV_8UC3 &&
            stages.final.type() == CV_8UC3);
  CV_Assert(stages.scene.size() == stages.developed.size() &&
            stages.scene.size() == stages.final.size());
  std::vector<cv::Point> corners;
  for (const Eigen::Vector2d& p : polygon)
    corners.emplace_back(static_cast<int>(std::lround(p.x())),
                         static_cast<int>(std::lround(p.y())));
  const cv::Rect box = cv::boundingRect(corners) & cv::Rect(cv::Point(0, 0), stages.scene.size());
  InkThroughCamera out;
  out.contrast = scene;
  if (box.area() <= 0) return out;
  cv::Mat mask(box.size(), CV_8U, cv::Scalar(0));
  for (cv::Point& c : corners) c -= box.tl();
  cv::fillConvexPoly(mask, corners, cv::Scalar(255));
  // The least-squares slope of y on x over the text's pixels, and the residual's mean square.
  struct Fit {
    double slope = 1.0, residual = 0.0;
  };
  const auto fit = [&mask](const cv::Mat& x, const cv::Mat& y) {
    double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0, syy = 0;
    for (int r = 0; r < mask.rows; ++r)
      for (int c = 0; c < mask.cols; ++c) {
        if (!mask.at<uint8_t>(r, c)) continue;
        const double a = x.at<double>(r, c), b = y.at<double>(r, c);
        n += 1;
        sx += a;
        sy += b;
        sxx += a * a;
        sxy += a * b;
        syy += b * b;
      }
    Fit f;
    if (n < 1) return f;
    const double vx = sxx / n - (sx / n) * (sx / n), vy = syy / n - (sy / n) * (sy / n),
                 cxy = sxy / n - (sx / n) * (sy / n);
    // Under a quarter of a level's spread x shows nothing to scale: slope 1.
    if (vx > 0.25) f.slope = std::max(0.0, cxy / vx);
    f.residual = std::max(0.0, vy - 2.0 * f.slope * cxy + f.slope * f.slope * vx);
    return f;
  };
  out.pixels = cv::countNonZero(mask);
  if (out.pixels < 4) return out;
  const cv::Mat s = lumaOf(stages.scene, box), d = lumaOf(stages.developed, box),
                f = lumaOf(stages.final, box);
  // The image processor maps levels smoothly: its slope scales ink and noise alike.
  out.gain = fit(s, d).slope;
  // The codec keeps the strokes' pattern in proportion to its slope (flat blocks: near 0);
  // what else it changes is noise to the reader.
  const Fit codec = fit(d, f);
  out.codec_kept = codec.slope;
  out.codec_rms = std::sqrt(codec.residual);
  const double kept = out.gain * out.codec_kept;
  const double scene_noise = scene.channel_noise * kLumaNoisePerChannelNoise;
  const double noise = std::sqrt(std::pow(kept * scene_noise, 2) + 1.0 / 12.0);
  out.contrast.luma_levels = kept * scene.luma_levels;
  out.contrast.channel_noise = noise / kLumaNoisePerChannelNoise;
  // The codec's error is its blocks' (8 px): as large as a reading feature, not averaged. Part
  // of the residual is the sensor's noise that the codec smoothed away, no harm to reading: up
  // to the developed noise's variance is taken off.
  const double blocks =
      std::sqrt(std::max(0.0, codec.residual - std::pow(out.gain * scene_noise, 2)));
  out.contrast.block_noise = std::hypot(scene.block_noise, blocks);
  return out;
}

}  // namespace parkloc::sim
