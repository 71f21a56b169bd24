#include "eval/latency.h"

#include <gtest/gtest.h>

namespace parkloc::eval {
namespace {

TEST(Latency, PerStageAndTotal) {
  std::vector<FrameTiming> frames = {
      {10.0, {{"detect", 6.0}, {"localize", 1.0}}},
      {20.0, {{"detect", 14.0}, {"localize", 2.0}}},
      {30.0, {{"localize", 3.0}}},  // detection skipped on this frame
  };
  const LatencyReport r = latencyReport(frames);
  EXPECT_DOUBLE_EQ(r.total_ms.median, 20.0);
  EXPECT_DOUBLE_EQ(r.total_ms.mean, 20.0);
  EXPECT_NEAR(r.total_ms.p99, 29.8, 1e-12);
  ASSERT_EQ(r.stage_ms.size(), 2u);
  EXPECT_DOUBLE_EQ(r.stage_ms.at("detect").mean, 20.0 / 3.0);
  EXPECT_DOUBLE_EQ(r.stage_ms.at("detect").median, 6.0);
  EXPECT_DOUBLE_EQ(r.stage_ms.at("localize").max, 3.0);
  EXPECT_EQ(r.samples_ms.at("total").size(), 3u);
}

}  // namespace
}  // namespace parkloc::eval
