#include <gtest/gtest.h>

#include "sim/drive.h"
#include "sim_test_util.h"

namespace parkloc::sim {
namespace {

class DriveTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    GarageSpec spec = testing::smallSpec();
    spec.aisles = 2;
    spec.slots_per_row = 10;
    spec.occupancy = 0.6;
    garage_ = new Garage(generateGarage(spec, 3));
  }
  static void TearDownTestSuite() { delete garage_; }
  static Garage* garage_;
};
Garage* DriveTest::garage_ = nullptr;

TEST_F(DriveTest, TourStaysInsideAtCarSpeeds) {
  for (uint64_t seed : {1, 2, 3, 4}) {
    const Drive d = planDrive(*garage_, 0, DriveSpec{"tour", "bright", "", 25.0}, seed);
    EXPECT_GT(d.duration(), 20.0);
    EXPECT_LE(d.duration(), 25.0 + 1e-9);
    double vmax = 0.0, yaw_change = 0.0;
    for (const auto& s : d.states()) {
      EXPECT_GE(s.pose.x, 0.5);
      EXPECT_LE(s.pose.x, garage_->size.x() - 0.5);
      EXPECT_GE(s.pose.y, 0.5);
      EXPECT_LE(s.pose.y, garage_->size.y() - 0.5);
      EXPECT_GE(s.speed, 0.0);
      vmax = std::max(vmax, s.speed);
      yaw_change += std::abs(s.yaw_rate) * 0.01;
    }
    EXPECT_GE(vmax, 1.9);
    EXPECT_LE(vmax, 4.0);
    EXPECT_GT(yaw_change, M_PI / 2 - 0.1) << "a tour goes through at least one turn";
  }
}

TEST_F(DriveTest, ParkEndsReversedIntoAFreeSlot) {
  for (uint64_t seed : {5, 6, 7}) {
    const Drive d = planDrive(*garage_, 0, DriveSpec{"park", "bright", "", 30.0}, seed);
    bool reversed = false;
    for (const auto& s : d.states()) reversed |= s.speed < -0.5;
    EXPECT_TRUE(reversed);
    const geometry::Pose2 end = d.states().back().pose;
    // The car's centre (1.4 m ahead of the rear axle) lies in a free slot, nose to the aisle.
    const Eigen::Vector2d centre = end * Eigen::Vector2d(1.4, 0.0);
    const Slot* best = nullptr;
    for (const auto& s : garage_->levels[0].slots)
      if (!best || (s.center - centre).norm() < (best->center - centre).norm()) best = &s;
    ASSERT_NE(best, nullptr);
    EXPECT_FALSE(best->occupied);
    EXPECT_LT(std::abs(centre.x() - best->center.x()), 0.3);
    EXPECT_LT(std::abs(centre.y() - best->center.y()), 1.0);
    EXPECT_NEAR(std::abs(geometry::wrapAngle(end.yaw + best->side * M_PI / 2)), 0.0, 0.05);
  }
}

TEST_F(DriveTest, NoiselessOdometryIntegratesToTheTrajectory) {
  const Drive d = planDrive(*garage_, 0, DriveSpec{"park", "bright", "", 30.0}, 8);
  const auto odo = simulateOdometry(d, 50.0, 1, OdometryNoise{0.0, 0.0, 0.0, 0.0});
  geometry::Pose2 p = d.states().front().pose;
  for (size_t i = 0; i + 1 < odo.size(); ++i) {
    const double dt = odo[i + 1].timestamp - odo[i].timestamp;
    const double yaw_mid = p.yaw + 0.5 * odo[i].yaw_rate * dt;
    p = geometry::Pose2(p.x + odo[i].speed * dt * std::cos(yaw_mid),
                        p.y + odo[i].speed * dt * std::sin(yaw_mid), p.yaw + odo[i].yaw_rate * dt);
  }
  const geometry::Pose2 truth = d.at(odo.back().timestamp).pose;
  EXPECT_LT((p.translation() - truth.translation()).norm(), 0.3);
  EXPECT_LT(std::abs(geometry::wrapAngle(p.yaw - truth.yaw)), 0.03);
}

TEST_F(DriveTest, OdometryNoiseHasTheRequestedSpread) {
  const Drive d = planDrive(*garage_, 0, DriveSpec{"tour", "bright", "", 25.0}, 9);
  const auto clean = simulateOdometry(d, 50.0, 1, OdometryNoise{0.0, 0.0, 0.0, 0.0});
  const OdometryNoise noise;
  const auto noisy = simulateOdometry(d, 50.0, 2, noise);
  ASSERT_EQ(clean.size(), noisy.size());
  double sum = 0, sum2 = 0;
  for (size_t i = 0; i < clean.size(); ++i) {
    const double e = noisy[i].yaw_rate - clean[i].yaw_rate;
    sum += e;
    sum2 += e * e;
  }
  const double mean = sum / clean.size();
  const double sd = std::sqrt(sum2 / clean.size() - mean * mean);
  EXPECT_NEAR(sd, noise.yaw_rate_sigma, 0.2 * noise.yaw_rate_sigma);
  EXPECT_LT(std::abs(mean), 5 * noise.yaw_rate_bias_sigma);
}

}  // namespace
}  // namespace parkloc::sim
