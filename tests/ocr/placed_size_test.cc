#include "ocr/placed_size.h"

#include <gtest/gtest.h>

#include <cmath>

namespace parkloc::ocr {
namespace {

// A box in reading order, `length` long and `height` tall, centred at (cx, cy), reading along
// +x.
Quad box(float cx, float cy, float length, float height) {
  const float l = length / 2, h = height / 2;
  return {cv::Point2f(cx - l, cy - h), {cx + l, cy - h}, {cx + l, cy + h}, {cx - l, cy + h}};
}

TEST(PlacedSize, ABoxOfTheTextsSizeIsKept) {
  const Quad q = box(50, 20, 120, 30);
  const PlacedSizeFit fit = fitToPlacedSize(q, 115, 28, true);
  EXPECT_EQ(fit.verdict, PlacedSize::kKept);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(fit.quad[k], q[k]);
}

TEST(PlacedSize, ATooTallBoxIsCutToTheTextsHeightAboutItsCentreLine) {
  const PlacedSizeFit fit = fitToPlacedSize(box(50, 20, 120, 60), 120, 30, true);
  EXPECT_EQ(fit.verdict, PlacedSize::kTightened);
  EXPECT_NEAR(quadHeight(fit.quad), 30, 1e-4);
  EXPECT_NEAR(quadWidth(fit.quad), 120, 1e-4);
  EXPECT_NEAR(quadCentre(fit.quad).x, 50, 1e-4);
  EXPECT_NEAR(quadCentre(fit.quad).y, 20, 1e-4);
}

TEST(PlacedSize, ATooLongWholeMatchIsCutToTheTextsLength) {
  const PlacedSizeFit fit = fitToPlacedSize(box(0, 0, 150, 30), 100, 30, true);
  EXPECT_EQ(fit.verdict, PlacedSize::kTightened);
  EXPECT_NEAR(quadWidth(fit.quad), 100, 1e-4);
  EXPECT_NEAR(quadHeight(fit.quad), 30, 1e-4);
}

TEST(PlacedSize, ABoxIsNeverGrown) {
  const PlacedSizeFit fit = fitToPlacedSize(box(0, 0, 80, 20), 100, 30, true);
  EXPECT_EQ(fit.verdict, PlacedSize::kKept);
  EXPECT_NEAR(quadWidth(fit.quad), 80, 1e-4);
  EXPECT_NEAR(quadHeight(fit.quad), 20, 1e-4);
}

TEST(PlacedSize, AWholeMatchFarShorterThanItsTextIsRefused) {
  EXPECT_EQ(fitToPlacedSize(box(0, 0, 40, 30), 100, 30, true).verdict, PlacedSize::kRefused);
  EXPECT_EQ(fitToPlacedSize(box(0, 0, 55, 30), 100, 30, true).verdict, PlacedSize::kKept);
}

TEST(PlacedSize, APartsLengthIsNotCheckedItsHeightIs) {
  // A number cut by the border, matched by the part that shows: short, and not refused.
  EXPECT_EQ(fitToPlacedSize(box(0, 0, 30, 30), 100, 30, false).verdict, PlacedSize::kKept);
  const PlacedSizeFit tall = fitToPlacedSize(box(0, 0, 30, 60), 100, 30, false);
  EXPECT_EQ(tall.verdict, PlacedSize::kTightened);
  EXPECT_NEAR(quadHeight(tall.quad), 30, 1e-4);
  EXPECT_NEAR(quadWidth(tall.quad), 30, 1e-4);
}

TEST(PlacedSize, ATiltedBoxIsTightenedAlongItsOwnAxes) {
  // The same box turned by 30 degrees: reading order follows the text, not the image axes.
  const float c = std::cos(0.5236f), s = std::sin(0.5236f);
  Quad q = box(0, 0, 120, 60);
  for (auto& p : q) p = {c * p.x - s * p.y, s * p.x + c * p.y};
  const PlacedSizeFit fit = fitToPlacedSize(q, 120, 30, true);
  EXPECT_EQ(fit.verdict, PlacedSize::kTightened);
  EXPECT_NEAR(quadHeight(fit.quad), 30, 1e-3);
  EXPECT_NEAR(quadWidth(fit.quad), 120, 1e-3);
}

TEST(PlacedSize, AnUnknownSizeChecksNothing) {
  EXPECT_EQ(fitToPlacedSize(box(0, 0, 10, 60), 0, 0, true).verdict, PlacedSize::kKept);
}

TEST(PlacedSize, ABoxThatMatchedNothingAlongTheTextItLiesOnIsHeldToItsSize) {
  const cv::Point2f along_x(1, 0);
  // Twice too tall and 1.5 times too long: tightened about its centre, like a whole match.
  const PlacedSizeFit big = fitUnmatchedToPlacedSize(box(50, 20, 150, 60), 100, 30, along_x);
  EXPECT_EQ(big.verdict, PlacedSize::kTightened);
  EXPECT_NEAR(quadWidth(big.quad), 100, 1e-3);
  EXPECT_NEAR(quadHeight(big.quad), 30, 1e-3);
  EXPECT_NEAR(quadCentre(big.quad).x, 50, 1e-3);
  // Under half the text's length: a fragment of it, refused.
  EXPECT_EQ(fitUnmatchedToPlacedSize(box(0, 0, 40, 30), 100, 30, along_x).verdict,
            PlacedSize::kRefused);
  // Read either way round, the same.
  EXPECT_EQ(fitUnmatchedToPlacedSize(box(0, 0, 40, 30), 100, 30, -along_x).verdict,
            PlacedSize::kRefused);
  // Its size is the text's: kept.
  EXPECT_EQ(fitUnmatchedToPlacedSize(box(0, 0, 100, 30), 100, 30, along_x).verdict,
            PlacedSize::kKept);
}

TEST(PlacedSize, ABoxThatMatchedNothingAcrossTheTextIsKeptAsItIs) {
  // The box reads 45 degrees off the text (over 30): not the text's box, whatever its size.
  const cv::Point2f diagonal(1, 1);
  const PlacedSizeFit fit = fitUnmatchedToPlacedSize(box(0, 0, 40, 90), 100, 30, diagonal);
  EXPECT_EQ(fit.verdict, PlacedSize::kKept);
  EXPECT_EQ(fit.quad, box(0, 0, 40, 90));
  // Within 30 degrees it is held: a 25 degree tilt.
  const cv::Point2f tilted(std::cos(0.436f), std::sin(0.436f));
  EXPECT_EQ(fitUnmatchedToPlacedSize(box(0, 0, 40, 30), 100, 30, tilted).verdict,
            PlacedSize::kRefused);
}

}  // namespace
}  // namespace parkloc::ocr
