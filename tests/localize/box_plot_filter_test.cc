#include "localize/box_plot_filter.h"

#include <gtest/gtest.h>

namespace parkloc::localize {
namespace {

TEST(Quartiles, MatchHandComputedLinearInterpolation) {
  // 1..10: positions 2.25, 4.5, 6.75 in the sorted sample (type 7).
  const auto q = computeQuartiles({7, 1, 10, 3, 2, 9, 4, 8, 6, 5});
  ASSERT_TRUE(q);
  EXPECT_DOUBLE_EQ(q->lower, 3.25);
  EXPECT_DOUBLE_EQ(q->median, 5.5);
  EXPECT_DOUBLE_EQ(q->upper, 7.75);
  EXPECT_DOUBLE_EQ(q->iqr(), 4.5);
  // Odd count with repeated values: {2, 4, 4, 5, 9}: positions 1, 2, 3.
  const auto r = computeQuartiles({9, 4, 2, 5, 4});
  EXPECT_DOUBLE_EQ(r->lower, 4.0);
  EXPECT_DOUBLE_EQ(r->median, 4.0);
  EXPECT_DOUBLE_EQ(r->upper, 5.0);
  EXPECT_FALSE(computeQuartiles({}));
  const auto one = computeQuartiles({42});
  EXPECT_DOUBLE_EQ(one->lower, 42);
  EXPECT_DOUBLE_EQ(one->upper, 42);
}

TEST(ParkingNumberValue, TakesTheLastRunOfDigits) {
  EXPECT_EQ(parkingNumberValue("B2-117"), 117);
  EXPECT_EQ(parkingNumberValue("098"), 98);
  EXPECT_EQ(parkingNumberValue("12A"), 12);
  EXPECT_EQ(parkingNumberValue("0000000000042"), 42);
  EXPECT_FALSE(parkingNumberValue("EXIT"));
  EXPECT_FALSE(parkingNumberValue(""));
  EXPECT_FALSE(parkingNumberValue("12345678901234"));
}

TEST(BoxPlotFilter, EmptyAndFillingQueueAcceptEverything) {
  BoxPlotFilter filter;
  EXPECT_FALSE(filter.range());
  EXPECT_TRUE(filter.accept(117));
  for (int i = 0; i < 28; ++i) EXPECT_TRUE(filter.accept(117));
  EXPECT_EQ(filter.size(), 29u);
  EXPECT_FALSE(filter.full());
  // The 30th number fills the queue whatever it is (the paper fills it first).
  EXPECT_TRUE(filter.accept(9999));
  EXPECT_TRUE(filter.full());
}

TEST(BoxPlotFilter, QueueOfThirtyAndHandComputedRange) {
  BoxPlotFilter filter;
  for (int n = 101; n <= 130; ++n) ASSERT_TRUE(filter.accept(n));
  ASSERT_EQ(filter.size(), 30u);
  // 101..130: Q1 at position 7.25 -> 108.25, median 115.5, Q3 at 21.75 -> 122.75;
  // IQR 14.5, range 115.5 -+ 21.75.
  const auto range = filter.range();
  ASSERT_TRUE(range);
  EXPECT_DOUBLE_EQ(range->first, 93.75);
  EXPECT_DOUBLE_EQ(range->second, 137.25);
  EXPECT_FALSE(filter.accept(500));
  EXPECT_FALSE(filter.accept(93));
  EXPECT_FALSE(filter.accept(138));
  EXPECT_EQ(filter.size(), 30u);
  EXPECT_EQ(filter.queue().front(), 101);  // rejected numbers do not enter
  EXPECT_TRUE(filter.accept(137));
  EXPECT_EQ(filter.size(), 30u);
  EXPECT_EQ(filter.queue().front(), 102);  // first in, first out
  EXPECT_EQ(filter.queue().back(), 137);
}

TEST(BoxPlotFilter, AllEqualValuesAcceptOnlyThatValue) {
  BoxPlotFilter filter;
  for (int i = 0; i < 30; ++i) filter.accept(117);
  EXPECT_EQ(filter.range()->first, 117);
  EXPECT_EQ(filter.range()->second, 117);
  EXPECT_TRUE(filter.accept(117));
  EXPECT_FALSE(filter.accept(118));
  EXPECT_FALSE(filter.accept(116));
}

TEST(BoxPlotFilter, OptionalResetAfterConsecutiveRejections) {
  BoxPlotFilterOptions options;
  options.queue_length = 5;
  options.reset_after_rejections = 3;
  BoxPlotFilter filter(options);
  for (int i = 0; i < 5; ++i) filter.accept(10);
  EXPECT_FALSE(filter.accept(50));
  EXPECT_FALSE(filter.accept(51));
  EXPECT_TRUE(filter.accept(10));  // an accepted number resets the count
  EXPECT_FALSE(filter.accept(50));
  EXPECT_FALSE(filter.accept(51));
  EXPECT_FALSE(filter.accept(52));  // third in a row: the queue is cleared
  EXPECT_EQ(filter.size(), 0u);
  EXPECT_TRUE(filter.accept(50));
}

}  // namespace
}  // namespace parkloc::localize
