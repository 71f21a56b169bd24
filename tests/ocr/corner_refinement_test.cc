// The spotter keeps a corner fit only when it is plausible for the box it refines.
#include "ocr/corner_refinement.h"

#include <gtest/gtest.h>

namespace parkloc::ocr {
namespace {

Quad box(float x0, float y0, float x1, float y1) {
  return {cv::Point2f(x0, y0), cv::Point2f(x1, y0), cv::Point2f(x1, y1), cv::Point2f(x0, y1)};
}

TEST(PlausibleRefinement, ATightenedBoxIsKept) {
  const Quad detected = box(100, 100, 300, 150);
  EXPECT_TRUE(plausibleRefinement(detected, box(110, 110, 290, 140)));
  EXPECT_TRUE(plausibleRefinement(detected, box(95, 95, 305, 155)));  // a little larger
}

TEST(PlausibleRefinement, AFitThatLostPartOfTheTextIsNot) {
  // Blurred ink broken in two: the fit covers the left half only.
  const Quad detected = box(100, 100, 300, 150);
  EXPECT_FALSE(plausibleRefinement(detected, box(105, 105, 200, 145)));
  EXPECT_TRUE(plausibleRefinement(detected, box(105, 105, 250, 145)));  // 72 % kept
  CornerRefinementOptions lenient;
  lenient.min_length_share = 0.f;
  EXPECT_TRUE(plausibleRefinement(detected, box(105, 105, 200, 145), lenient));
}

TEST(PlausibleRefinement, AFitOutsideTheGrownBoxIsNot) {
  const Quad detected = box(100, 100, 300, 150);
  EXPECT_FALSE(plausibleRefinement(detected, box(100, 100, 300, 200)));  // runs off below
  EXPECT_FALSE(plausibleRefinement(detected, box(200, 100, 400, 150)));  // shifted along
}

}  // namespace
}  // namespace parkloc::ocr
