// frames.jsonl: one JSON object per frame set (run/frame_log.h).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "run/frame_log.h"

namespace parkloc::run {
namespace {

TEST(FrameLog, APoseComesWithTheFiltersOdometryEstimates) {
  localize::FrameResult r;
  r.timestamp = 1.5;
  r.has_pose = true;
  r.pose = geometry::Pose2(2.0, 3.0, 0.1);
  r.odometry = localize::FrameResult::OdometryEstimate{0.02, 0.005, 1.03, 0.01};
  const nlohmann::json j = nlohmann::json::parse(frameResultToJson(r));
  ASSERT_TRUE(j.contains("odometry_estimate"));
  EXPECT_DOUBLE_EQ(j["odometry_estimate"]["yaw_rate_bias"].get<double>(), 0.02);
  EXPECT_DOUBLE_EQ(j["odometry_estimate"]["yaw_rate_bias_sigma"].get<double>(), 0.005);
  EXPECT_DOUBLE_EQ(j["odometry_estimate"]["speed_scale"].get<double>(), 1.03);
  EXPECT_DOUBLE_EQ(j["odometry_estimate"]["speed_scale_sigma"].get<double>(), 0.01);
  EXPECT_DOUBLE_EQ(j["pose"]["x"].get<double>(), 2.0);

  localize::FrameResult before_the_first_fix;
  const nlohmann::json none = nlohmann::json::parse(frameResultToJson(before_the_first_fix));
  EXPECT_FALSE(none.contains("odometry_estimate"));
  EXPECT_FALSE(none.contains("pose"));
}

}  // namespace
}  // namespace parkloc::run
