#include "geometry/seen_span.h"

#include <gtest/gtest.h>

namespace parkloc::geometry {
namespace {

TEST(SeenSpan, ATextWhollySeenSpansItAll) {
  const auto span = seenSpan([](double, double) { return true; });
  ASSERT_TRUE(span);
  EXPECT_EQ(span->u0, 0.0);
  EXPECT_EQ(span->u1, 1.0);
  EXPECT_EQ(span->v0, 0.0);
  EXPECT_EQ(span->v1, 1.0);
}

TEST(SeenSpan, NothingSeenIsNoSpan) {
  EXPECT_FALSE(seenSpan([](double, double) { return false; }));
}

TEST(SeenSpan, ACutAcrossTheReadingDirectionEndsTheSpanAtItsLastSeenColumn) {
  // Seen up to u = 0.6: columns of 1/32 whose centres lie below it, the last (centre 18.5/32)
  // ending at 19/32.
  const auto span = seenSpan([](double u, double) { return u < 0.6; });
  ASSERT_TRUE(span);
  EXPECT_EQ(span->u0, 0.0);
  EXPECT_DOUBLE_EQ(span->u1, 19.0 / 32.0);
  EXPECT_EQ(span->v0, 0.0);
  EXPECT_EQ(span->v1, 1.0);
}

TEST(SeenSpan, AnObliqueCutKeepsTheColumnsSeenAtLeastHalfway) {
  // The edge runs from u = 0.5 at the top (v = 0) to u = 0.7 at the bottom (v = 1): a column
  // is at least half seen up to u = 0.6, and its rows are judged over those columns.
  const auto span = seenSpan([](double u, double v) { return u < 0.5 + 0.2 * v; });
  ASSERT_TRUE(span);
  EXPECT_NEAR(span->u1, 0.6, 1.0 / 32.0);
  EXPECT_EQ(span->v0, 0.0);
  EXPECT_EQ(span->v1, 1.0);
}

TEST(SeenSpan, ACutAlongTheReadingDirectionEndsTheSpanAcrossIt) {
  const SeenSpanOptions options;
  const auto span = seenSpan([](double, double v) { return v > 0.25; }, options);
  ASSERT_TRUE(span);
  EXPECT_EQ(span->u0, 0.0);
  EXPECT_EQ(span->u1, 1.0);
  EXPECT_DOUBLE_EQ(span->v0, 2.0 / options.samples_v);
  EXPECT_EQ(span->v1, 1.0);
}

}  // namespace
}  // namespace parkloc::geometry
