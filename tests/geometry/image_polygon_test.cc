#include "geometry/image_polygon.h"

#include <gtest/gtest.h>

namespace parkloc::geometry {
namespace {

Quad box(float x0, float y0, float x1, float y1) {
  return {cv::Point2f(x0, y0), cv::Point2f(x1, y0), cv::Point2f(x1, y1), cv::Point2f(x0, y1)};
}

TEST(PolygonIoU, IdenticalBoxesGiveOne) {
  EXPECT_NEAR(polygonIoU(box(0, 0, 10, 5), box(0, 0, 10, 5)), 1.0, 1e-6);
}

TEST(PolygonIoU, HalfShiftedSquares) {
  // 10x10 squares shifted by 5: intersection 50, union 150.
  EXPECT_NEAR(polygonIoU(box(0, 0, 10, 10), box(5, 0, 15, 10)), 1.0 / 3.0, 1e-6);
}

TEST(PolygonIoU, ContainedBox) {
  // 4x4 inside 10x10: 16 / 100.
  EXPECT_NEAR(polygonIoU(box(0, 0, 10, 10), box(3, 3, 7, 7)), 0.16, 1e-6);
}

TEST(PolygonIoU, DisjointAndDegenerate) {
  EXPECT_EQ(polygonIoU(box(0, 0, 1, 1), box(2, 2, 3, 3)), 0.0);
  EXPECT_EQ(polygonIoU(box(0, 0, 0, 0), box(0, 0, 0, 0)), 0.0);
}

TEST(PolygonIoU, RotatedSquareAgainstAxisAlignedOne) {
  // A square of side 2 and the same square turned 45 degrees about the common centre:
  // the intersection is a regular octagon of area 8 (sqrt(2) - 1), each area 4.
  const Quad square = box(-1, -1, 1, 1);
  const float r = std::sqrt(2.f);
  const Quad diamond = {cv::Point2f(0, -r), cv::Point2f(r, 0), cv::Point2f(0, r),
                        cv::Point2f(-r, 0)};
  const double octagon = 8.0 * (std::sqrt(2.0) - 1.0);
  EXPECT_NEAR(polygonIoU(square, diamond), octagon / (8.0 - octagon), 1e-5);
}

TEST(PolygonIoU, ReadingOrderDoesNotMatter) {
  // An upside-down text lists its corners starting at the bottom right.
  const Quad a = box(0, 0, 10, 4);
  const Quad flipped = {a[2], a[3], a[0], a[1]};
  EXPECT_NEAR(polygonIoU(a, flipped), 1.0, 1e-6);
}

TEST(ClippedToImage, KeepsThePartInsideTheImage) {
  // A 20 x 10 box from x = -10.5: half of it lies left of a 100 x 50 image's edge at -0.5.
  const Quad half_out = box(-10.5f, 10, 9.5f, 20);
  const auto inside = clippedToImage({half_out.begin(), half_out.end()}, {100, 50});
  EXPECT_NEAR(polygonArea(inside), 100.0, 1e-4);
  // Wholly inside: unchanged in area; wholly outside: nothing.
  const Quad in = box(10, 10, 30, 20), out = box(200, 10, 220, 20);
  EXPECT_NEAR(polygonArea(clippedToImage({in.begin(), in.end()}, {100, 50})), 200.0, 1e-4);
  EXPECT_TRUE(clippedToImage({out.begin(), out.end()}, {100, 50}).empty());
}

}  // namespace
}  // namespace parkloc::geometry
