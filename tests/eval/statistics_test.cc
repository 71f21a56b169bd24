#include "eval/statistics.h"

#include <gtest/gtest.h>

#include <cmath>

namespace parkloc::eval {
namespace {

TEST(Statistics, PercentileInterpolatesBetweenRanksAsNumpyDoes) {
  // numpy.percentile([1, 2, 3, 4], 95) = 3.85; median 2.5.
  EXPECT_NEAR(percentile({4, 1, 3, 2}, 95.0), 3.85, 1e-12);
  EXPECT_NEAR(percentile({4, 1, 3, 2}, 50.0), 2.5, 1e-12);
  EXPECT_DOUBLE_EQ(percentile({7.0}, 99.0), 7.0);
  EXPECT_DOUBLE_EQ(percentile({}, 50.0), 0.0);
  EXPECT_DOUBLE_EQ(percentile({1, 2, 3}, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(percentile({1, 2, 3}, 100.0), 3.0);
}

TEST(Statistics, SummaryOfAHandComputedSample) {
  const Summary s = summarize({3.0, 4.0, 0.0, 5.0});
  EXPECT_EQ(s.count, 4u);
  EXPECT_DOUBLE_EQ(s.mean, 3.0);
  EXPECT_DOUBLE_EQ(s.median, 3.5);
  EXPECT_DOUBLE_EQ(s.rmse, std::sqrt(50.0 / 4.0));
  EXPECT_DOUBLE_EQ(s.std, std::sqrt((0.0 + 1.0 + 9.0 + 4.0) / 4.0));
  EXPECT_DOUBLE_EQ(s.min, 0.0);
  EXPECT_DOUBLE_EQ(s.max, 5.0);
  EXPECT_NEAR(s.p95, 4.0 + 0.85 * 1.0, 1e-12);  // rank 2.85 of [0, 3, 4, 5]
  EXPECT_NEAR(s.p99, 4.0 + 0.97 * 1.0, 1e-12);
}

TEST(Statistics, EmptySampleIsAllZeros) {
  const Summary s = summarize({});
  EXPECT_EQ(s.count, 0u);
  EXPECT_EQ(s.mean, 0.0);
  EXPECT_EQ(s.max, 0.0);
}

}  // namespace
}  // namespace parkloc::eval
