#include "ocr/visible_part.h"

#include <gtest/gtest.h>

namespace parkloc::ocr {
namespace {

// A text 100 px long and 20 px high, tilted, read left to right.
Quad tiltedText() {
  const cv::Point2f origin(50.f, 40.f), along(80.f, 60.f), across(-12.f, 16.f);
  return {origin, origin + along, origin + along + across, origin + across};
}

void expectNear(const cv::Point2f& a, const cv::Point2f& b, float tolerance) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
}

TEST(VisiblePart, ATextWhollySeenKeepsItsQuad) {
  const Quad q = tiltedText();
  const auto part = visiblePart(q, [](const cv::Point2f&) { return true; });
  ASSERT_TRUE(part);
  for (int k = 0; k < 4; ++k) expectNear(part->quad[k], q[k], 1e-3f);
  EXPECT_FLOAT_EQ(part->length_fraction, 1.f);
  EXPECT_FLOAT_EQ(part->height_fraction, 1.f);
}

TEST(VisiblePart, ATextCutByAnEdgeKeepsTheSeenSpanInReadingOrder) {
  // An image edge at x = 90 cuts the text across its length: the part left of it is seen.
  const Quad q = tiltedText();
  const auto part = visiblePart(q, [](const cv::Point2f& p) { return p.x < 90.f; });
  ASSERT_TRUE(part);
  // Along the text, x grows 80 px over the length and falls 12 px over the height: at mid
  // height the edge is (90 - 50 + 6) / 80 = 0.575 of the way along.
  EXPECT_NEAR(part->length_fraction, 0.575f, 1.f / 32.f + 1e-3f);
  EXPECT_FLOAT_EQ(part->height_fraction, 1.f);
  expectNear(part->quad[0], q[0], 1e-3f);  // the start of the text stays
  expectNear(part->quad[3], q[3], 1e-3f);
  const cv::Point2f along = part->quad[1] - part->quad[0];
  EXPECT_GT(along.x, 0.f);  // still read the same way
}

TEST(VisiblePart, ACutAlongTheLengthShortensTheHeight) {
  // The text's top half lies beyond an edge parallel to the reading direction.
  const Quad q = {cv::Point2f(0.f, 0.f), {100.f, 0.f}, {100.f, 20.f}, {0.f, 20.f}};
  const auto part = visiblePart(q, [](const cv::Point2f& p) { return p.y > 10.f; });
  ASSERT_TRUE(part);
  EXPECT_FLOAT_EQ(part->length_fraction, 1.f);
  EXPECT_FLOAT_EQ(part->height_fraction, 0.5f);
  expectNear(part->quad[0], {0.f, 10.f}, 1e-3f);
  expectNear(part->quad[2], {100.f, 20.f}, 1e-3f);
}

TEST(VisiblePart, NothingSeenGivesNothing) {
  EXPECT_FALSE(visiblePart(tiltedText(), [](const cv::Point2f&) { return false; }));
}

}  // namespace
}  // namespace parkloc::ocr
