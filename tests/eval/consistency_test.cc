#include "eval/consistency.h"

#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "common/error.h"

namespace parkloc::eval {
namespace {

// Truth: x = t, y = 0, yaw = 0 at t = 0, 1, ..., 9.
std::vector<io::StampedPose> straightTruth() {
  std::vector<io::StampedPose> truth(10);
  for (int i = 0; i < 10; ++i) {
    truth[i].timestamp = i;
    truth[i].pose.translation() = Eigen::Vector3d(i, 0.0, 0.0);
  }
  return truth;
}

ReportedFrame reported(double t, Eigen::Vector3d error, Eigen::Vector3d sigmas,
                       const std::string& status = "ok") {
  ReportedFrame f;
  f.timestamp = t;
  f.status = status;
  f.has_pose = true;
  f.pose = geometry::Pose2(t + error.x(), error.y(), error.z());
  f.covariance = sigmas.cwiseAbs2().asDiagonal();
  return f;
}

TEST(Consistency, NeesByHand) {
  const Eigen::Matrix3d p = Eigen::Vector3d(0.04, 0.01, 0.0025).asDiagonal();
  EXPECT_NEAR(nees({0.2, 0.1, 0.05}, p), 3.0, 1e-12);  // one sigma on each axis
  EXPECT_NEAR(nees({0.4, 0.0, 0.0}, p), 4.0, 1e-12);
  // Correlated position: P = [[2,1],[1,2]], P^-1 = [[2,-1],[-1,2]] / 3.
  Eigen::Matrix3d q = Eigen::Matrix3d::Identity();
  q.topLeftCorner<2, 2>() << 2.0, 1.0, 1.0, 2.0;
  EXPECT_NEAR(nees({1.0, 1.0, 0.0}, q), 2.0 / 3.0, 1e-12);
  EXPECT_NEAR(nees({1.0, -1.0, 0.0}, q), 2.0, 1e-12);
  EXPECT_TRUE(std::isinf(nees({1.0, 0.0, 0.0}, Eigen::Matrix3d::Zero())));
}

TEST(Consistency, ProtectionLevelUsesTheLargestPositionEigenvalue) {
  Eigen::Matrix3d q = Eigen::Matrix3d::Identity() * 100.0;  // yaw must not count
  q.topLeftCorner<2, 2>() << 2.0, 1.0, 1.0, 2.0;            // eigenvalues 3 and 1
  EXPECT_NEAR(protectionLevel(q, 2.0), 2.0 * std::sqrt(3.0), 1e-12);
}

TEST(Consistency, CountsBoundAlertsAndMissedDetections) {
  ConsistencyOptions options;                     // bound 7.815, k 4.29, alert limit 0.5
  const Eigen::Vector3d small(0.05, 0.05, 0.01);  // PL = 4.29 * 0.05 = 0.21: no alert
  const Eigen::Vector3d large(0.2, 0.2, 0.05);    // PL = 0.86: alert
  std::vector<ReportedFrame> frames{
      reported(0.0, {0.05, 0.0, 0.0}, small),         // NEES 1, inside
      reported(1.0, {0.1, 0.1, 0.0}, small),          // NEES 8, outside
      reported(2.0, {0.6, 0.0, 0.0}, small),          // error 0.6, no alert: missed
      reported(3.0, {0.7, 0.0, 0.0}, small),          // missed again (same episode)
      reported(4.0, {0.3, 0.0, 0.0}, large),          // alert, error below: false alert
      reported(5.0, {0.8, 0.0, 0.0}, large),          // new episode, flagged: not missed
      reported(6.0, {0.9, 0.0, 0.0}, small, "lost"),  // lost is an alert
  };
  ReportedFrame none;
  none.timestamp = 7.0;
  none.status = "not_initialised";
  frames.push_back(none);
  frames.push_back(reported(20.0, {0.0, 0.0, 0.0}, small));  // beyond the truth

  const auto r = evaluateConsistency(frames, straightTruth(), options);
  ASSERT_EQ(r.frames.size(), 7u);
  EXPECT_EQ(r.frames_total, 9u);
  EXPECT_EQ(r.frames_without_pose, 1u);
  EXPECT_EQ(r.frames_unanswered, 1u);  // not initialised after a pose
  EXPECT_EQ(r.frames_without_truth, 1u);
  EXPECT_NEAR(r.frames[0].nees, 1.0, 1e-9);
  EXPECT_NEAR(r.frames[1].nees, 8.0, 1e-9);
  EXPECT_NEAR(r.frames[4].nees, 0.09 / 0.04, 1e-9);  // 2.25: inside
  EXPECT_EQ(r.inside_bound, 2u);
  EXPECT_NEAR(r.fraction_inside, 2.0 / 7.0, 1e-12);
  EXPECT_NEAR(r.frames[4].protection_level_m, 4.29 * 0.2, 1e-9);
  EXPECT_EQ(r.over_alert_limit, 4u);
  EXPECT_EQ(r.missed_detections, 2u);
  EXPECT_TRUE(r.frames[2].missed);
  EXPECT_FALSE(r.frames[5].missed);
  EXPECT_TRUE(r.frames[6].alert);
  EXPECT_EQ(r.alerts, 3u);
  EXPECT_EQ(r.false_alerts, 1u);
  EXPECT_EQ(r.episodes, 2u);  // frames 2-3 and 5-6
  EXPECT_EQ(r.late_episodes, 1u);
  EXPECT_NEAR(r.max_position_error_m, 0.9, 1e-9);
  EXPECT_NEAR(r.mean_position_error_m,
              (0.05 + std::hypot(0.1, 0.1) + 0.6 + 0.7 + 0.3 + 0.8 + 0.9) / 7.0, 1e-9);
}

TEST(Consistency, TruthIsInterpolatedAndYawWrapped) {
  // At t = 2.5 the truth is x = 2.5; yaw error across +-pi wraps to a small angle.
  std::vector<io::StampedPose> truth = straightTruth();
  ReportedFrame f = reported(2.5, {0.0, 0.0, 0.0}, {0.1, 0.1, 0.1});
  f.pose.yaw = 2.0 * M_PI - 0.05;
  const auto r = evaluateConsistency({f}, truth);
  ASSERT_EQ(r.frames.size(), 1u);
  EXPECT_NEAR(r.frames[0].position_error_m, 0.0, 1e-9);
  EXPECT_NEAR(r.frames[0].error.z(), -0.05, 1e-9);
  EXPECT_NEAR(r.frames[0].nees, 0.25, 1e-9);
}

class FramesFile : public ::testing::Test {
 protected:
  std::string path_ = (std::filesystem::temp_directory_path() /
                       ("parkloc_consistency_" + std::to_string(::getpid()) + ".jsonl"))
                          .string();
  void TearDown() override { std::filesystem::remove(path_); }
  void write(const std::string& text) { std::ofstream(path_) << text; }
};

TEST_F(FramesFile, ReadsTheRunnersLines) {
  write(R"({"timestamp":0.1,"status":"not_initialised","has_pose":false,"warnings":[]})"
        "\n"
        R"({"timestamp":0.2,"status":"ok","has_pose":true,"pose":{"x":1.5,"y":-2,"yaw":0.3},)"
        R"("covariance":[[0.01,0.002,0],[0.002,0.02,0],[0,0,0.001]]})"
        "\n\n");
  const auto frames = loadReportedFrames(path_);
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_FALSE(frames[0].has_pose);
  EXPECT_EQ(frames[1].status, "ok");
  EXPECT_DOUBLE_EQ(frames[1].pose.y, -2.0);
  EXPECT_DOUBLE_EQ(frames[1].covariance(0, 1), 0.002);
  EXPECT_DOUBLE_EQ(frames[1].covariance(2, 2), 0.001);
}

TEST_F(FramesFile, BadLinesThrowWithTheLineNumber) {
  write(R"({"timestamp":0.1,"status":"ok","has_pose":true,"pose":{"x":1,"y":2,"yaw":0}})");
  try {
    loadReportedFrames(path_);
    FAIL() << "accepted a pose without covariance";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(":1:"), std::string::npos) << e.what();
  }
  write("not json\n");
  EXPECT_THROW(loadReportedFrames(path_), InputError);
  write(R"({"timestamp":0.1,"status":"ok","has_pose":true,"pose":{"x":1,"y":2,"yaw":0},)"
        R"("covariance":[[1,0],[0,1]]})");
  EXPECT_THROW(loadReportedFrames(path_), InputError);
  EXPECT_THROW(loadReportedFrames(path_ + ".absent"), IoError);
}

}  // namespace
}  // namespace parkloc::eval
