#include "eval/conditions.h"

#include <gtest/gtest.h>

namespace parkloc::eval {
namespace {

TEST(Conditions, RotationBins) {
  EXPECT_EQ(rotationSubset(0.0), std::nullopt);
  EXPECT_EQ(rotationSubset(29.0), std::nullopt);
  EXPECT_EQ(rotationSubset(31.0), "rot45");
  EXPECT_EQ(rotationSubset(-50.0), "rot45");
  EXPECT_EQ(rotationSubset(95.0), "rot90");
  EXPECT_EQ(rotationSubset(-80.0), "rot90");
  EXPECT_EQ(rotationSubset(135.0), std::nullopt);
  EXPECT_EQ(rotationSubset(140.0), std::nullopt);
  EXPECT_EQ(rotationSubset(152.0), "rot180");
  EXPECT_EQ(rotationSubset(-175.0), "rot180");
  EXPECT_EQ(rotationSubset(540.0), "rot180");
}

}  // namespace
}  // namespace parkloc::eval
