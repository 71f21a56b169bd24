#include "sim/ink_through_camera.h"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace parkloc::sim {
namespace {

// A grey floor (luma 100) with noise of `sigma` per channel and "A12" painted at luma 160,
// 16 px tall, and the polygon around it.
struct Painted {
  cv::Mat image;
  geometry::TextPolygon polygon;
};

Painted paintedText(double sigma) {
  Painted p;
  p.image = cv::Mat(120, 200, CV_8UC3, cv::Scalar::all(100));
  cv::putText(p.image, "A12", cv::Point(70, 68), cv::FONT_HERSHEY_SIMPLEX, 0.6,
              cv::Scalar::all(160), 2, cv::LINE_AA);
  cv::Mat noise(p.image.size(), CV_16SC3);
  cv::theRNG().state = 7;
  cv::randn(noise, cv::Scalar::all(0), cv::Scalar::all(sigma));
  cv::Mat sum;
  p.image.convertTo(sum, CV_16SC3);
  sum += noise;
  sum.convertTo(p.image, CV_8UC3);
  p.polygon = {Eigen::Vector2d(66, 50), Eigen::Vector2d(112, 50), Eigen::Vector2d(112, 72),
               Eigen::Vector2d(66, 72)};
  return p;
}

cv::Mat jpeg(const cv::Mat& image, int quality) {
  std::vector<uint8_t> bytes;
  cv::imencode(".jpg", image, bytes, {cv::IMWRITE_JPEG_QUALITY, quality});
  return cv::imdecode(bytes, cv::IMREAD_COLOR);
}

const InkContrast kScene{60.0, 3.0};

TEST(InkThroughCamera, AnUntouchedImageKeepsTheScenesContrast) {
  const Painted p = paintedText(3.0);
  const InkThroughCamera r = inkThroughCamera(kScene, {p.image, p.image, p.image}, p.polygon);
  EXPECT_GT(r.pixels, 500);
  EXPECT_NEAR(r.gain, 1.0, 1e-9);
  EXPECT_NEAR(r.codec_kept, 1.0, 1e-9);
  EXPECT_NEAR(r.codec_rms, 0.0, 1e-6);
  EXPECT_NEAR(r.contrast.luma_levels, 60.0, 1e-9);
  // Only the 8-bit rounding is added to the sensor's noise.
  const double luma = 3.0 * kLumaNoisePerChannelNoise;
  EXPECT_NEAR(r.contrast.channel_noise * kLumaNoisePerChannelNoise,
              std::sqrt(luma * luma + 1.0 / 12.0), 1e-6);
}

TEST(InkThroughCamera, AToneCurveScalesContrastAndNoiseAlike) {
  const Painted p = paintedText(3.0);
  cv::Mat squeezed;
  p.image.convertTo(squeezed, CV_8UC3, 0.5, 60.0);  // a veil and half the slope
  const InkThroughCamera r = inkThroughCamera(kScene, {p.image, squeezed, squeezed}, p.polygon);
  EXPECT_NEAR(r.gain, 0.5, 0.02);
  EXPECT_NEAR(r.contrast.luma_levels, 30.0, 1.5);
  // The noise halves too (up to the rounding), so the text's SNR hardly moves.
  EXPECT_LT(r.contrast.channel_noise, 0.6 * 3.0 + 0.5);
  const double before = featureSnr(p.polygon, 3, kScene);
  const double after = featureSnr(p.polygon, 3, r.contrast);
  EXPECT_GT(after, 0.8 * before);
}

TEST(InkThroughCamera, AHardCodecAddsItsErrorToTheNoise) {
  const Painted p = paintedText(3.0);
  const InkThroughCamera light =
      inkThroughCamera(kScene, {p.image, p.image, jpeg(p.image, 95)}, p.polygon);
  const InkThroughCamera hard =
      inkThroughCamera(kScene, {p.image, p.image, jpeg(p.image, 8)}, p.polygon);
  EXPECT_GT(light.codec_kept, 0.9);
  EXPECT_LT(light.codec_rms, 3.0);
  EXPECT_LT(hard.codec_kept, light.codec_kept - 0.05);
  EXPECT_GT(hard.codec_rms, 2.0 * light.codec_rms);
  EXPECT_LT(featureSnr(p.polygon, 3, hard.contrast),
            0.7 * featureSnr(p.polygon, 3, light.contrast));
}

TEST(InkThroughCamera, ATextOutsideTheImageKeepsTheScenesContrast) {
  const Painted p = paintedText(3.0);
  geometry::TextPolygon outside = p.polygon;
  for (Eigen::Vector2d& c : outside) c += Eigen::Vector2d(500, 0);
  cv::Mat black(p.image.size(), CV_8UC3, cv::Scalar::all(0));
  const InkThroughCamera r = inkThroughCamera(kScene, {p.image, black, black}, outside);
  EXPECT_EQ(r.pixels, 0);
  EXPECT_DOUBLE_EQ(r.contrast.luma_levels, kScene.luma_levels);
  EXPECT_DOUBLE_EQ(r.contrast.channel_noise, kScene.channel_noise);
}

TEST(InkThroughCamera, CrushedShadowsLeaveNoContrast) {
  const Painted p = paintedText(3.0);
  cv::Mat crushed(p.image.size(), CV_8UC3, cv::Scalar::all(0));  // everything below the black level
  const InkThroughCamera r = inkThroughCamera(kScene, {p.image, crushed, crushed}, p.polygon);
  EXPECT_NEAR(r.gain, 0.0, 1e-9);
  EXPECT_DOUBLE_EQ(r.contrast.luma_levels, 0.0);
  EXPECT_LT(featureSnr(p.polygon, 3, r.contrast), 1e-9);
}

TEST(InkThroughCamera, RejectsStagesOfDifferentSizes) {
  const Painted p = paintedText(3.0);
  cv::Mat small(10, 10, CV_8UC3, cv::Scalar::all(0));
  EXPECT_THROW(inkThroughCamera(kScene, {p.image, small, p.image}, p.polygon), cv::Exception);
}

}  // namespace
}  // namespace parkloc::sim
