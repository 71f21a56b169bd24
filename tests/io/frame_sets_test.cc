#include "io/frame_sets.h"

#include <gtest/gtest.h>

namespace parkloc::io {
namespace {

TEST(FrameSets, SynchronisedCamerasShareOneSetPerTimestamp) {
  const std::map<std::string, std::vector<double>> times{{"front", {0.0, 0.1, 0.2}},
                                                         {"rear", {0.0, 0.1, 0.2}}};
  EXPECT_NEAR(frameSetTolerance(times), 0.045, 1e-12);
  const auto sets = groupFrameSets(times, frameSetTolerance(times));
  ASSERT_EQ(sets.size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_DOUBLE_EQ(sets[i].timestamp, 0.1 * static_cast<double>(i));
    EXPECT_EQ(sets[i].images, (std::map<std::string, size_t>{{"front", i}, {"rear", i}}));
  }
}

TEST(FrameSets, CamerasWithOffsetsAndJitterJoinTheNearestSetOnce) {
  // 10 Hz; the rear camera 30 ms late with +-5 ms jitter, the left one 20 ms early, and the
  // left camera drops its third frame.
  const std::map<std::string, std::vector<double>> times{
      {"front", {1.00, 1.10, 1.20, 1.30}},
      {"left", {0.98, 1.08, 1.28}},
      {"rear", {1.035, 1.125, 1.23, 1.33}}};
  const auto sets = groupFrameSets(times, frameSetTolerance(times));
  ASSERT_EQ(sets.size(), 4u);
  EXPECT_DOUBLE_EQ(sets[0].timestamp, 0.98);
  EXPECT_EQ(sets[0].images, (std::map<std::string, size_t>{{"front", 0}, {"left", 0}, {"rear", 0}}));
  EXPECT_EQ(sets[1].images, (std::map<std::string, size_t>{{"front", 1}, {"left", 1}, {"rear", 1}}));
  EXPECT_DOUBLE_EQ(sets[2].timestamp, 1.20);
  EXPECT_EQ(sets[2].images, (std::map<std::string, size_t>{{"front", 2}, {"rear", 2}}));
  EXPECT_EQ(sets[3].images, (std::map<std::string, size_t>{{"front", 3}, {"left", 2}, {"rear", 3}}));
}

TEST(FrameSets, ACameraNeverGivesTwoImagesToOneSet) {
  // Rear took two images near front's second one: the nearer joins it, the other stands alone.
  const std::map<std::string, std::vector<double>> times{{"front", {0.0, 0.1, 0.2}},
                                                         {"rear", {0.09, 0.12}}};
  const auto sets = groupFrameSets(times, 0.045);
  ASSERT_EQ(sets.size(), 4u);
  EXPECT_EQ(sets[1].images, (std::map<std::string, size_t>{{"front", 1}, {"rear", 0}}));
  EXPECT_DOUBLE_EQ(sets[1].timestamp, 0.09);
  EXPECT_EQ(sets[2].images, (std::map<std::string, size_t>{{"rear", 1}}));
}

TEST(FrameSets, OneFramePerCameraGroupsOnlyIdenticalTimes) {
  const std::map<std::string, std::vector<double>> times{{"front", {0.5}}, {"rear", {0.5001}}};
  EXPECT_DOUBLE_EQ(frameSetTolerance(times), 1e-6);
  EXPECT_EQ(groupFrameSets(times, frameSetTolerance(times)).size(), 2u);
}

}  // namespace
}  // namespace parkloc::io
