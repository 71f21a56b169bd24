#include "eval/number_recall.h"

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

// The tally's pairs so far, found and read.
void expectPairs(const NumberRecallTally& tally, size_t numbers, size_t found, size_t read) {
  EXPECT_EQ(tally.result().numbers, numbers);
  EXPECT_EQ(tally.result().found, found);
  EXPECT_EQ(tally.result().read, read);
}

TEST(NumberRecall, PerFrameSetANumberCountsOnceFoundWhenSomeCameraFindsIt) {
  NumberRecallTally tally;
  io::ImageLabels front, rear;
  // A002 is seen by both cameras and found by the rear one only; A003 by the front only,
  // misread; A004 nowhere found; A005 is hidden (don't care).
  front.instances = {number(0, "A002"), number(200, "A003"), number(400, "A005", 0.8)};
  rear.instances = {number(0, "A002"), number(200, "A004")};
  tally.addImage(front, {detection(200, "A008"), detection(400, "A005")});
  tally.addImage(rear, {detection(0, "A002")});
  tally.endGroup();
  expectPairs(tally, 3, 2, 1);

  // The next frame set counts its own pairs, the front camera's A002 (found and read) and
  // A003 (missed).
  tally.addImage(front, {detection(0, "A002")});
  tally.endGroup();
  expectPairs(tally, 5, 3, 2);
  EXPECT_DOUBLE_EQ(tally.result().foundShare(), 0.6);
}

// A drive is one group of many frame sets: a number counts once, found when some frame found
// it; the next drive's numbers are pairs of their own.
TEST(NumberRecall, PerDriveANumberCountsOnceFoundWhenSomeFrameFindsIt) {
  NumberRecallTally tally;
  io::ImageLabels frame;
  frame.instances = {number(0, "A002"), number(200, "A003")};
  tally.addImage(frame, {});                      // both missed
  tally.addImage(frame, {detection(0, "A008")});  // A002 found, misread
  tally.addImage(frame, {detection(0, "A002")});  // A002 found and read
  tally.endGroup();
  expectPairs(tally, 2, 1, 1);
  tally.addImage(frame, {detection(200, "A003")});
  tally.endGroup();
  expectPairs(tally, 4, 2, 2);
}

}  // namespace
}  // namespace parkloc::eval
