// Turning a bird's-eye image's labels agrees with cv::rotate, for every quarter turn.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include "eval/birds_eye_evaluation.h"

namespace parkloc::eval {
namespace {

TEST(BirdsEyeEvaluation, TurnedLabelsFollowTheTurnedImage) {
  cv::Mat image(30, 40, CV_8UC1, cv::Scalar(0));
  image.at<uint8_t>(3, 7) = 255;  // x 7, y 3
  io::ImageLabels labels;
  labels.width = 40;
  labels.height = 30;
  io::LabelInstance inst;
  inst.polygon = {Eigen::Vector2d(7, 3), Eigen::Vector2d(8, 3), Eigen::Vector2d(8, 4),
                  Eigen::Vector2d(7, 4)};
  inst.rotation_deg = 0.0;
  labels.instances.push_back(inst);
  const cv::RotateFlags flags[] = {cv::ROTATE_90_CLOCKWISE, cv::ROTATE_180,
                                   cv::ROTATE_90_COUNTERCLOCKWISE};
  for (int turns = 1; turns <= 3; ++turns) {
    cv::Mat turned;
    cv::rotate(image, turned, flags[turns - 1]);
    cv::Point at;
    cv::minMaxLoc(turned, nullptr, nullptr, nullptr, &at);
    const io::ImageLabels t = turnLabels(labels, turns);
    EXPECT_EQ(t.width, turned.cols);
    EXPECT_EQ(t.height, turned.rows);
    EXPECT_DOUBLE_EQ(t.instances[0].polygon[0].x(), at.x) << turns;
    EXPECT_DOUBLE_EQ(t.instances[0].polygon[0].y(), at.y) << turns;
    EXPECT_NEAR(std::abs(std::remainder(t.instances[0].rotation_deg - 90.0 * turns, 360.0)), 0.0,
                1e-9);
  }
  const io::ImageLabels round = turnLabels(turnLabels(labels, 3), 1);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(round.instances[0].polygon[k], inst.polygon[k]);
  EXPECT_EQ(birdsEyeOrientations().size(), 4u);
}

}  // namespace
}  // namespace parkloc::eval
