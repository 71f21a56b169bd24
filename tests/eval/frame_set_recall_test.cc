#include "eval/frame_set_recall.h"

#include <gtest/gtest.h>

namespace parkloc::eval {
namespace {

io::LabelInstance number(float x0, const std::string& text, double occluded = 0.0) {
  io::LabelInstance l;
  l.polygon = {Eigen::Vector2d(x0, 0), Eigen::Vector2d(x0 + 100, 0), Eigen::Vector2d(x0 + 100, 40),
               Eigen::Vector2d(x0, 40)};
  l.text = text;
  l.landmark_id = "B1:" + text;
  l.cls = map::TextClass::kParkingNumber;
  l.occluded_fraction = occluded;
  return l;
}

ocr::TextInstance detection(float x0, const std::string& text) {
  ocr::TextInstance d;
  d.polygon = {cv::Point2f(x0, 0), cv::Point2f(x0 + 100, 0), cv::Point2f(x0 + 100, 40),
               cv::Point2f(x0, 40)};
  d.text = text;
  d.cls = map::TextClass::kParkingNumber;
  return d;
}

TEST(FrameSetRecall, ANumberCountsOnceFoundWhenSomeCameraFindsIt) {
  FrameSetRecallTally tally;
  io::ImageLabels front, rear;
  // A002 is seen by both cameras and found by the rear one only; A003 by the front only,
  // misread; A004 nowhere found; A005 is hidden (don't care).
  front.instances = {number(0, "A002"), number(200, "A003"), number(400, "A005", 0.8)};
  rear.instances = {number(0, "A002"), number(200, "A004")};
  tally.addImage(front, {detection(200, "A008"), detection(400, "A005")});
  tally.addImage(rear, {detection(0, "A002")});
  tally.endFrameSet();
  EXPECT_EQ(tally.result().numbers, 3u);
  EXPECT_EQ(tally.result().found, 2u);
  EXPECT_EQ(tally.result().read, 1u);

  // The next frame set counts its own pairs, the front camera's A002 (found and read) and
  // A003 (missed).
  tally.addImage(front, {detection(0, "A002")});
  tally.endFrameSet();
  EXPECT_EQ(tally.result().numbers, 5u);
  EXPECT_EQ(tally.result().found, 3u);
  EXPECT_EQ(tally.result().read, 2u);
  EXPECT_DOUBLE_EQ(tally.result().foundShare(), 0.6);
}

}  // namespace
}  // namespace parkloc::eval
