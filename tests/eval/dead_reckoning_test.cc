#include "eval/dead_reckoning.h"

#include <gtest/gtest.h>

#include <cmath>

namespace parkloc::eval {
namespace {

std::vector<OdometrySample> constant(double speed, double yaw_rate, double t0, double t1,
                                         double rate) {
  std::vector<OdometrySample> out;
  for (double t = t0; t <= t1 + 1e-9; t += 1.0 / rate) out.push_back({t, speed, yaw_rate});
  return out;
}

TEST(DeadReckoning, StraightLine) {
  DeadReckoning dr(geometry::Pose2(1.0, 2.0, M_PI / 2), 0.0);
  dr.advance(constant(2.0, 0.0, 0.0, 3.0, 50.0), 3.0);
  EXPECT_NEAR(dr.pose().x, 1.0, 1e-9);
  EXPECT_NEAR(dr.pose().y, 8.0, 1e-9);
  EXPECT_NEAR(dr.time(), 3.0, 1e-12);
}

TEST(DeadReckoning, ConstantTurnFollowsTheCircleExactly) {
  // Speed 1 m/s, yaw rate 0.5 rad/s: a circle of radius 2 around (0, 2); after pi seconds
  // (a quarter turn... half of pi/2 rad/s) the vehicle is at (2 sin(pi/2), 2 - 2 cos(pi/2)).
  DeadReckoning dr(geometry::Pose2(0.0, 0.0, 0.0), 0.0);
  const auto samples = constant(1.0, 0.5, 0.0, 4.0, 10.0);
  dr.advance(samples, M_PI);
  EXPECT_NEAR(dr.pose().x, 2.0, 1e-9);
  EXPECT_NEAR(dr.pose().y, 2.0, 1e-9);
  EXPECT_NEAR(dr.pose().yaw, M_PI / 2, 1e-9);
}

TEST(DeadReckoning, IncrementalEqualsOneShot) {
  const auto samples = constant(1.5, -0.2, 0.0, 5.0, 20.0);
  DeadReckoning once(geometry::Pose2(), 0.0), steps(geometry::Pose2(), 0.0);
  once.advance(samples, 5.0);
  for (double t = 0.1; t <= 5.0 + 1e-9; t += 0.1) steps.advance(samples, t);
  EXPECT_NEAR(once.pose().x, steps.pose().x, 1e-9);
  EXPECT_NEAR(once.pose().y, steps.pose().y, 1e-9);
  EXPECT_NEAR(once.pose().yaw, steps.pose().yaw, 1e-9);
}

TEST(DeadReckoning, SkipsNonFiniteSamples) {
  DeadReckoning dr(geometry::Pose2(), 0.0);
  dr.advance({{0.0, 1.0, 0.0}, {0.5, std::nan(""), 0.0}, {1.0, 1.0, 0.0}}, 2.0);
  EXPECT_NEAR(dr.pose().x, 2.0, 1e-9);
}

}  // namespace
}  // namespace parkloc::eval
