#include "mapping/stencil_height.h"

#include <gtest/gtest.h>

namespace parkloc::mapping {
namespace {

LandmarkEstimate number(const std::string& text, double height,
                        map::TextClass cls = map::TextClass::kParkingNumber) {
  LandmarkEstimate l;
  l.text = text;
  l.cls = cls;
  l.parameters = {0.0, 0.0, 0.0, 1.0, height};
  return l;
}

// Six numbers of one stencil (0.44-0.46 m, their glyphs' spread), one boxed with a bay line
// (0.62 m): that one takes the median, the others keep their own heights.
TEST(StencilHeight, AHeightFarOffTheLevelsStencilTakesTheMedian) {
  std::vector<LandmarkEstimate> landmarks = {number("101", 0.44), number("102", 0.45),
                                             number("103", 0.46), number("104", 0.45),
                                             number("105", 0.62), number("106", 0.44)};
  const std::vector<std::string> set = applyStencilHeight(landmarks, {});
  ASSERT_EQ(set, std::vector<std::string>{"105"});
  EXPECT_NEAR(landmarks[4].parameters[kHeight], 0.45, 1e-12);
  EXPECT_DOUBLE_EQ(landmarks[0].parameters[kHeight], 0.44);
  EXPECT_DOUBLE_EQ(landmarks[2].parameters[kHeight], 0.46);
  EXPECT_DOUBLE_EQ(landmarks[4].parameters[kWidth], 1.0);  // the width goes with the text
}

// Each class has its own stencil; a class of too few landmarks has no median to go by; a
// tolerance of 0 leaves every height as estimated.
TEST(StencilHeight, EachClassHasItsOwnAndFewOrNoneLeaveHeightsAlone) {
  std::vector<LandmarkEstimate> landmarks = {number("101", 0.45),
                                             number("102", 0.45),
                                             number("103", 0.45),
                                             number("104", 0.45),
                                             number("105", 0.45),
                                             number("EXIT", 0.60, map::TextClass::kOther),
                                             number("SLOW", 0.90, map::TextClass::kOther)};
  EXPECT_TRUE(applyStencilHeight(landmarks, {}).empty());
  EXPECT_DOUBLE_EQ(landmarks[6].parameters[kHeight], 0.90);

  landmarks[4].parameters[kHeight] = 0.30;
  StencilOptions off;
  off.tolerance = 0.0;
  EXPECT_TRUE(applyStencilHeight(landmarks, off).empty());
  EXPECT_DOUBLE_EQ(landmarks[4].parameters[kHeight], 0.30);
  StencilOptions many;
  many.min_landmarks = 6;
  EXPECT_TRUE(applyStencilHeight(landmarks, many).empty());
  EXPECT_EQ(applyStencilHeight(landmarks, {}), std::vector<std::string>{"105"});
}

}  // namespace
}  // namespace parkloc::mapping
