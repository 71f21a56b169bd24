#include "eval/pose_prediction.h"

#include <gtest/gtest.h>

#include <cmath>

namespace parkloc::eval {
namespace {

io::StampedPose stamped(double t, const geometry::Pose2& pose) { return {t, pose.toRigid3()}; }

// 2 m/s straight ahead, samples at 50 Hz over 3 s.
std::vector<OdometrySample> straightAhead() {
  std::vector<OdometrySample> out;
  for (int i = 0; i <= 150; ++i) out.push_back({i / 50.0, 2.0, 0.0});
  return out;
}

// The estimate of the frame before, carried to the frame's time by odometry; never the
// frame's own estimate, which was made from the images being read.
TEST(PosePrediction, CarriesTheEstimateBeforeTheFrameForwardByOdometry) {
  const geometry::Pose2 north(5.0, 1.0, M_PI / 2);
  const PosePrediction prediction(
      {stamped(1.0, north), stamped(1.1, geometry::Pose2(50.0, 50.0, 0.0))}, straightAhead());
  const auto at = prediction.at(1.1);
  ASSERT_TRUE(at.has_value());
  EXPECT_NEAR(at->x, 5.0, 1e-9);
  EXPECT_NEAR(at->y, 1.0 + 0.2, 1e-9);  // 0.1 s at 2 m/s, heading north
  EXPECT_NEAR(at->yaw, M_PI / 2, 1e-9);
}

TEST(PosePrediction, PredictsNothingBeforeTheFirstEstimateOrAfterTheFixIsLost) {
  const PosePrediction prediction({stamped(1.0, geometry::Pose2(0.0, 0.0, 0.0))}, straightAhead());
  EXPECT_FALSE(prediction.at(0.5).has_value());
  EXPECT_FALSE(prediction.at(1.0).has_value());  // its own estimate is not a prediction
  EXPECT_TRUE(prediction.at(1.4).has_value());
  EXPECT_FALSE(prediction.at(1.6).has_value());  // older than max_age_s
}

}  // namespace
}  // namespace parkloc::eval
