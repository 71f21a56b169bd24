#include "ocr/tracked_text_fit.h"

#include <gtest/gtest.h>

#include "synthetic_text.h"

namespace parkloc::ocr {
namespace {

double maxCornerError(const Quad& a, const Quad& b) {
  double e = 0.0;
  for (int k = 0; k < 4; ++k) e = std::max(e, static_cast<double>(cv::norm(a[k] - b[k])));
  return e;
}

Quad shifted(const Quad& q, cv::Point2f by) {
  Quad out = q;
  for (auto& p : out) p += by;
  return out;
}

class TrackedTextFitTest : public ::testing::Test {
 protected:
  geometry::Rig rig = geometry::defaultRig();
  const geometry::RigCamera* left = rig.find("left");
  // A 1.2 x 0.45 m number on the floor beside the car, upside down in the left camera.
  testing::FisheyeScene scene =
      testing::renderFloorText(*left, "B2-117", {2.0, 2.6}, M_PI, 1.2, 0.45);
};

TEST_F(TrackedTextFitTest, FitsTheInkAroundAPredictionAFewPixelsOff) {
  for (const cv::Point2f off : {cv::Point2f(0, 0), cv::Point2f(4, -3), cv::Point2f(-6, 2)}) {
    const auto fit = fitTrackedText(scene.image, shifted(scene.truth, off), left);
    ASSERT_TRUE(fit.has_value()) << off;
    EXPECT_LT(maxCornerError(*fit, scene.truth), 2.0) << off;
  }
}

TEST_F(TrackedTextFitTest, FitsDimTextUnderSensorNoise) {
  // Weak light (a validation drive's level): concrete at 48 grey levels, paint only 12
  // above it, noise of 6. A fit that demands 20 levels of contrast finds nothing here, so
  // the track starves and the pose dead-reckons away (57 cm mean error on g09_B2_d0).
  const auto dim =
      testing::renderFloorText(*left, "B2-117", {2.0, 2.6}, M_PI, 1.2, 0.45, 0.5, 24.0);
  const auto fit = fitTrackedText(dim.image, shifted(dim.truth, {3, -2}), left);
  ASSERT_TRUE(fit.has_value());
  EXPECT_LT(maxCornerError(*fit, dim.truth), 3.0);
}

TEST(TrackedTextFit, WithoutACameraFitsTheInkBoxInTheRectifiedCrop) {
  // Upright text as on a pillar face seen head-on: 40 px tall ink, 30 px margin.
  const cv::Mat image = testing::renderTextLine("B2-117", 40, 30);
  const cv::Mat ink = testing::renderInk("B2-117", 40);
  const float x0 = 29.5f, y0 = 29.5f, x1 = x0 + ink.cols, y1 = y0 + ink.rows;
  const Quad truth{cv::Point2f(x0, y0), {x1, y0}, {x1, y1}, {x0, y1}};
  const auto fit = fitTrackedText(image, shifted(truth, {3, -2}), nullptr);
  ASSERT_TRUE(fit.has_value());
  EXPECT_LT(maxCornerError(*fit, truth), 1.5);
}

TEST_F(TrackedTextFitTest, NothingWhereTheFloorIsBare) {
  // The same prediction on bare concrete (the text occluded or worn away).
  cv::Mat bare(scene.image.size(), CV_8UC3);
  cv::randn(bare, cv::Scalar::all(95), cv::Scalar::all(6));
  EXPECT_FALSE(fitTrackedText(bare, scene.truth, left).has_value());
}

TEST_F(TrackedTextFitTest, NothingWhenTheInkIsMuchShorterThanPredicted) {
  // The map predicts a text 1.8 times as long as the ink there.
  EXPECT_FALSE(fitTrackedText(scene.image, expandQuad(scene.truth, 1.8f, 1.0f), left).has_value());
}

TEST_F(TrackedTextFitTest, NothingWhenThePredictionIsFarOff) {
  EXPECT_FALSE(fitTrackedText(scene.image, shifted(scene.truth, {150, 0}), left).has_value());
}

}  // namespace
}  // namespace parkloc::ocr
