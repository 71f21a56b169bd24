#include "api/frame_assembly.h"

#include <gtest/gtest.h>

namespace parkloc::api {
namespace {

const std::vector<std::string> kCameras = {"front", "left", "rear", "right"};
const cv::Mat kImage(8, 8, CV_8UC3, cv::Scalar(0, 0, 0));

std::vector<std::string> camerasOf(const localize::FrameInput& frame) {
  std::vector<std::string> names;
  for (const auto& c : frame.cameras) names.push_back(c.camera);
  return names;
}

TEST(FrameAssembly, ASetClosesWhenEveryCameraHasAnImage) {
  FrameAssembly assembly(kCameras, 0.045);
  EXPECT_TRUE(assembly.addImage("left", 1.010, kImage).empty());
  EXPECT_TRUE(assembly.addImage("front", 1.000, kImage).empty());
  EXPECT_TRUE(assembly.addImage("rear", 1.030, kImage).empty());
  const auto closed = assembly.addImage("right", 1.020, kImage);
  ASSERT_EQ(closed.size(), 1u);
  EXPECT_DOUBLE_EQ(closed[0].timestamp, 1.000);  // the earliest capture time
  ASSERT_EQ(closed[0].cameras.size(), 4u);
  EXPECT_EQ(closed[0].cameras[0].camera, "left");
  EXPECT_DOUBLE_EQ(*closed[0].cameras[0].capture_time, 1.010);  // each image keeps its own
  EXPECT_FALSE(assembly.flush().has_value());
}

TEST(FrameAssembly, ASecondImageOfACameraClosesTheSetWithoutTheMissingOnes) {
  FrameAssembly assembly(kCameras, 0.045);
  assembly.addImage("front", 1.0, kImage);
  assembly.addImage("left", 1.0, kImage);
  const auto closed = assembly.addImage("front", 1.02, kImage);
  ASSERT_EQ(closed.size(), 1u);
  EXPECT_EQ(camerasOf(closed[0]), (std::vector<std::string>{"front", "left"}));
  const auto open = assembly.flush();
  ASSERT_TRUE(open.has_value());
  EXPECT_DOUBLE_EQ(open->timestamp, 1.02);
}

TEST(FrameAssembly, AnImageBeyondTheToleranceStartsTheNextSet) {
  FrameAssembly assembly(kCameras, 0.045);
  assembly.addImage("front", 1.0, kImage);
  const auto closed = assembly.addImage("left", 1.05, kImage);
  ASSERT_EQ(closed.size(), 1u);
  EXPECT_EQ(camerasOf(closed[0]), std::vector<std::string>{"front"});
  EXPECT_EQ(camerasOf(*assembly.flush()), std::vector<std::string>{"left"});
}

TEST(FrameAssembly, OneCameraRigClosesTheOpenSetAndItsOwn) {
  FrameAssembly assembly({"front"}, 0.045);
  EXPECT_EQ(assembly.addImage("front", 1.0, kImage).size(), 1u);
  EXPECT_EQ(assembly.addImage("front", 1.1, kImage).size(), 1u);
  EXPECT_FALSE(assembly.flush().has_value());
}

TEST(FrameAssembly, LateAndUnknownImagesAreDroppedWithAWarning) {
  FrameAssembly assembly(kCameras, 0.045);
  EXPECT_TRUE(assembly.addImage("roof", 1.0, kImage).empty());
  assembly.addImage("front", 1.0, kImage);
  assembly.addImage("front", 1.1, kImage);              // closes the set at 1.0
  EXPECT_TRUE(assembly.addImage("left", 0.99, kImage).empty());  // its set is gone
  EXPECT_TRUE(assembly.addImage("rear", 1.04, kImage).empty());  // before the open window
  const auto warnings = assembly.takeWarnings();
  ASSERT_EQ(warnings.size(), 3u);
  EXPECT_NE(warnings[0].find("'roof'"), std::string::npos);
  EXPECT_NE(warnings[1].find("'left'"), std::string::npos);
  EXPECT_NE(warnings[2].find("'rear'"), std::string::npos);
  EXPECT_TRUE(assembly.takeWarnings().empty());
  EXPECT_EQ(camerasOf(*assembly.flush()), std::vector<std::string>{"front"});
}

TEST(FrameAssembly, AnImageThatIsNotBgrIsDroppedAndAnEmptyOneKept) {
  FrameAssembly assembly({"front", "left"}, 0.045);
  EXPECT_TRUE(assembly.addImage("front", 1.0, cv::Mat(8, 8, CV_8UC1)).empty());
  ASSERT_EQ(assembly.takeWarnings().size(), 1u);
  // An empty image stands for one that could not be decoded: the pipeline reports it.
  const auto closed = assembly.addImage("left", 1.0, cv::Mat());
  EXPECT_TRUE(closed.empty());
  EXPECT_EQ(camerasOf(*assembly.flush()), std::vector<std::string>{"left"});
}

TEST(FrameAssembly, OdometryGoesWithTheFirstSetAtOrAfterIt) {
  FrameAssembly assembly({"front"}, 0.045);
  assembly.addOdometry({0.95, 1.0, 0.0});
  assembly.addOdometry({1.00, 1.0, 0.0});
  assembly.addOdometry({1.05, 1.0, 0.0});
  const auto first = assembly.addImage("front", 1.0, kImage);
  ASSERT_EQ(first.size(), 1u);
  ASSERT_EQ(first[0].odometry.size(), 2u);
  EXPECT_DOUBLE_EQ(first[0].odometry[1].timestamp, 1.00);
  assembly.addOdometry({0.99, 1.0, 0.0});  // out of order
  assembly.addOdometry({1.10, 1.0, 0.0});
  const auto second = assembly.addImage("front", 1.1, kImage);
  ASSERT_EQ(second.size(), 1u);
  ASSERT_EQ(second[0].odometry.size(), 2u);
  EXPECT_DOUBLE_EQ(second[0].odometry[0].timestamp, 1.05);
  EXPECT_EQ(assembly.takeWarnings().size(), 1u);
}

TEST(FrameAssembly, OdometryForAProcessedSetIsDropped) {
  FrameAssembly assembly({"front"}, 0.045);
  assembly.addImage("front", 1.0, kImage);
  assembly.addOdometry({0.98, 1.0, 0.0});
  const auto warnings = assembly.takeWarnings();
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("already processed"), std::string::npos);
}

}  // namespace
}  // namespace parkloc::api
