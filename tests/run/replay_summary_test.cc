// Several real-time replays taken together (run/replay_summary.h).
#include <gtest/gtest.h>

#include "run/replay_summary.h"

namespace parkloc::run {
namespace {

RunSummary replay(std::vector<double> ages, size_t dropped, std::optional<size_t> first_frame,
                  double first_ms, double mean_m, double p95_m) {
  RunSummary s;
  s.frames = ages.size() + 2;
  s.frames_dropped = dropped;
  s.pose_age_ms = std::move(ages);
  s.first_pose_frame = first_frame;
  s.first_pose_output_ms = first_ms;
  s.mean_position_error_m = mean_m;
  s.p95_position_error_m = p95_m;
  return s;
}

TEST(ReplaySummary, AgesArePooledAndErrorsAveragedOverThePosedReplays) {
  const ReplaySummary r = summarizeReplays({
      replay({1.0, 2.0, 3.0}, 1, 3, 370.0, 0.010, 0.020),
      replay({}, 0, std::nullopt, 0.0, 0.0, 0.0),  // never posed: no error to average
      replay({4.0, 5.0, 100.0}, 2, 5, 530.0, 0.030, 0.060),
  });
  EXPECT_EQ(r.replays, 3u);
  EXPECT_EQ(r.posed, 2u);
  EXPECT_EQ(r.frames, 5u + 2u + 5u + 3u);  // processed and dropped, all replays
  EXPECT_EQ(r.dropped, 3u);
  EXPECT_DOUBLE_EQ(r.age_median_ms, 3.5);  // of 1, 2, 3, 4, 5, 100
  EXPECT_DOUBLE_EQ(r.age_max_ms, 100.0);
  EXPECT_DOUBLE_EQ(r.mean_error_m, 0.020);
  EXPECT_DOUBLE_EQ(r.p95_error_m, 0.040);
  EXPECT_EQ(r.first_pose_frame_min, 3u);
  EXPECT_EQ(r.first_pose_frame_max, 5u);
  EXPECT_DOUBLE_EQ(r.first_pose_ms_min, 370.0);
  EXPECT_DOUBLE_EQ(r.first_pose_ms_max, 530.0);
}

TEST(ReplaySummary, NoPoseInAnyReplayGivesZerosNotInfinities) {
  const ReplaySummary r = summarizeReplays({replay({}, 4, std::nullopt, 0.0, 0.0, 0.0)});
  EXPECT_EQ(r.posed, 0u);
  EXPECT_EQ(r.dropped, 4u);
  EXPECT_EQ(r.first_pose_frame_min, 0u);
  EXPECT_DOUBLE_EQ(r.first_pose_ms_min, 0.0);
  EXPECT_DOUBLE_EQ(r.mean_error_m, 0.0);
  EXPECT_DOUBLE_EQ(r.age_max_ms, 0.0);
}

}  // namespace
}  // namespace parkloc::run
