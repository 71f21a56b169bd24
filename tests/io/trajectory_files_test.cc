// TUM trajectories and odometry CSV: round trips and one test per bad-input case.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "common/error.h"
#include "io/odometry_csv.h"
#include "io/tum.h"
#include "test_dir.h"

namespace parkloc::io {
namespace {

class TrajectoryFilesTest : public testing::TempDirTest {
 protected:
  template <typename Load>
  std::string errorFor(Load load, const std::string& text) const {
    const std::string p = write("file.txt", text);
    try {
      load(p);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
  std::string tumError(const std::string& text) const { return errorFor(loadTum, text); }
  std::string odometryError(const std::string& text) const { return errorFor(loadOdometry, text); }
};

TEST_F(TrajectoryFilesTest, TumRoundTripKeepsMicrometresAndQuaternions) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<StampedPose> poses;
  for (int i = 0; i < 50; ++i) {
    StampedPose p;
    p.timestamp = 1700000000.0 + i * 0.0333333333;
    p.pose.linear() =
        Eigen::Quaterniond(u(rng), u(rng), u(rng), u(rng)).normalized().toRotationMatrix();
    p.pose.translation() = 100.0 * Eigen::Vector3d(u(rng), u(rng), u(rng));
    poses.push_back(p);
  }
  saveTum(poses, path("poses.tum"));
  const auto back = loadTum(path("poses.tum"));
  ASSERT_EQ(back.size(), poses.size());
  for (size_t i = 0; i < poses.size(); ++i) {
    EXPECT_NEAR(back[i].timestamp, poses[i].timestamp, 1e-6);
    EXPECT_LT((back[i].pose.translation() - poses[i].pose.translation()).norm(), 1e-6);
    EXPECT_LT((back[i].pose.linear() - poses[i].pose.linear()).cwiseAbs().maxCoeff(), 1e-9);
  }
}

TEST_F(TrajectoryFilesTest, TumSkipsCommentsAndBlankLines) {
  const std::string p =
      write("a.tum", "# header\n\n1.5 1 2 3 0 0 0 1\n   \n# end\n2 0 0 0 0 0 1 0\n");
  const auto poses = loadTum(p);
  ASSERT_EQ(poses.size(), 2u);
  EXPECT_EQ(poses[0].timestamp, 1.5);
  EXPECT_EQ(poses[0].pose.translation(), Eigen::Vector3d(1, 2, 3));
  EXPECT_NEAR(poses[1].pose.linear()(0, 0), -1.0, 1e-15);
}

TEST_F(TrajectoryFilesTest, TumWrongColumnCountNamesTheLine) {
  EXPECT_EQ(tumError("# c\n1 2 3 4 0 0 0 1\n2 3 4 0 0 0 1\n"),
            "tum " + path("file.txt") + ":3: expected 8 columns 'timestamp tx ty tz qx qy qz qw'");
}

TEST_F(TrajectoryFilesTest, TumNotANumberNamesTheToken) {
  EXPECT_EQ(tumError("1 2 3 x4 0 0 0 1\n"), "tum " + path("file.txt") + ":1: not a number: 'x4'");
}

TEST_F(TrajectoryFilesTest, TumNanIsRejected) {
  EXPECT_EQ(tumError("1 2 nan 4 0 0 0 1\n"),
            "tum " + path("file.txt") + ":1: non-finite value in column 3");
}

TEST_F(TrajectoryFilesTest, TumZeroQuaternionIsRejected) {
  EXPECT_EQ(tumError("1 2 3 4 0 0 0 0\n"), "tum " + path("file.txt") + ":1: zero quaternion");
}

TEST_F(TrajectoryFilesTest, OdometryRoundTripIsExact) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  std::vector<OdometrySample> samples;
  double t = 10.0 / 3.0;
  for (int i = 0; i < 100; ++i) {
    t += 0.01 + 1e-3 * std::abs(u(rng));
    samples.push_back({t, 3.0 * u(rng), u(rng) / 7.0});
  }
  saveOdometry(samples, path("odometry.csv"));
  const auto back = loadOdometry(path("odometry.csv"));
  ASSERT_EQ(back.size(), samples.size());
  for (size_t i = 0; i < samples.size(); ++i) {
    EXPECT_EQ(back[i].timestamp, samples[i].timestamp);
    EXPECT_EQ(back[i].speed, samples[i].speed);
    EXPECT_EQ(back[i].yaw_rate, samples[i].yaw_rate);
  }
}

TEST_F(TrajectoryFilesTest, OdometryMissingHeaderIsRejected) {
  EXPECT_EQ(odometryError("0.0,1.0,0.0\n"),
            "odometry " + path("file.txt") + ":1: expected the header 'timestamp,speed,yaw_rate'");
}

TEST_F(TrajectoryFilesTest, OdometryMalformedRowNamesTheLine) {
  EXPECT_EQ(odometryError("timestamp,speed,yaw_rate\n0.0,1.0,0.0\n0.1,1.0\n"),
            "odometry " + path("file.txt") +
                ":3: malformed row '0.1,1.0' (expected 'timestamp,speed,yaw_rate')");
}

TEST_F(TrajectoryFilesTest, OdometryNanIsRejected) {
  EXPECT_EQ(odometryError("timestamp,speed,yaw_rate\n0.0,NaN,0.0\n"),
            "odometry " + path("file.txt") + ":2: non-finite value in column 2");
}

TEST_F(TrajectoryFilesTest, OdometryTimestampsMustIncrease) {
  EXPECT_EQ(
      odometryError("timestamp,speed,yaw_rate\n0.0,1,0\n0.1,1,0\n\n0.1,1,0\n"),
      "odometry " + path("file.txt") + ":5: timestamp 0.1 is not after the previous one (0.1)");
}

}  // namespace
}  // namespace parkloc::io
