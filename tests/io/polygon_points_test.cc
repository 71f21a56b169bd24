#include "io/polygon_points.h"

#include <gtest/gtest.h>

namespace parkloc::io {
namespace {

TEST(PolygonPoints, ALabelPolygonKeepsItsCornerOrderBothWays) {
  const geometry::TextPolygon polygon = {Eigen::Vector2d(1.5, 2), {11, 2.25}, {10.75, 6}, {1, 5.5}};
  const PointQuad q = pointQuad(polygon);
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_FLOAT_EQ(q[i].x, static_cast<float>(polygon[i].x())) << i;
    EXPECT_FLOAT_EQ(q[i].y, static_cast<float>(polygon[i].y())) << i;
  }
  const geometry::TextPolygon back = textPolygon(q);
  for (size_t i = 0; i < 4; ++i) EXPECT_EQ(back[i], polygon[i]) << i;  // exact in float
}

}  // namespace
}  // namespace parkloc::io
