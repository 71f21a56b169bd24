#include "geometry/text_polygon.h"

#include <gtest/gtest.h>

namespace parkloc::geometry {
namespace {

TEST(TextPolygon, ApparentHeightIsAreaOverReadingLength) {
  // An axis-aligned 100 x 10 box, and a sheared sliver: long side edges, 5 px across.
  EXPECT_NEAR(apparentHeightPx({Eigen::Vector2d(0, 0), {100, 0}, {100, 10}, {0, 10}}), 10.0, 1e-9);
  EXPECT_NEAR(apparentHeightPx({Eigen::Vector2d(0, 0), {100, 0}, {160, 5}, {60, 5}}), 5.0, 1e-9);
}

TEST(TextPolygon, ReadingLengthIsTheMeanOfTopAndBottom) {
  // A trapezoid: top 100 px, bottom 60 px.
  EXPECT_NEAR(readingLengthPx({Eigen::Vector2d(0, 0), {100, 0}, {80, 10}, {20, 10}}), 80.0, 1e-9);
}

TEST(TextPolygon, ADegeneratePolygonHasNoHeight) {
  const Eigen::Vector2d p(3, 4);
  EXPECT_EQ(apparentHeightPx({p, p, p, p}), 0.0);
  // Collinear corners: a reading length but no area.
  EXPECT_EQ(apparentHeightPx({Eigen::Vector2d(0, 0), {10, 0}, {20, 0}, {5, 0}}), 0.0);
}

}  // namespace
}  // namespace parkloc::geometry
