#include "eval/text_outcomes.h"

#include <gtest/gtest.h>

namespace parkloc::eval {
namespace {

using map::TextClass;

// An axis-aligned box from x0 to x1, 40 px tall, as a label and as a detection.
io::LabelInstance labelAt(double x0, double x1, const std::string& text, double occluded = 0.0) {
  io::LabelInstance l;
  l.polygon = {Eigen::Vector2d(x0, 0), {x1, 0}, {x1, 40}, {x0, 40}};
  l.text = text;
  l.cls = TextClass::kParkingNumber;
  l.occluded_fraction = occluded;
  return l;
}

ocr::TextInstance foundAt(float x0, float x1, const std::string& text) {
  ocr::TextInstance d;
  d.polygon = {cv::Point2f(x0, 0), {x1, 0}, {x1, 40}, {x0, 40}};
  d.text = d.raw_text = text;
  d.cls = TextClass::kParkingNumber;
  return d;
}

const TextOutcome* outcomeOf(const std::vector<TextOutcome>& all, OutcomeKind kind, int index) {
  for (const TextOutcome& o : all)
    if (o.kind == kind && (kind == OutcomeKind::kFalseDetection ? o.detection : o.truth) == index)
      return &o;
  return nullptr;
}

TEST(TextOutcomes, NamesEachFoundMissedAndFalseText) {
  io::ImageLabels truth;
  truth.camera = "left";
  truth.timestamp = 1.5;
  truth.instances = {labelAt(0, 100, "A001"), labelAt(200, 300, "A002"),
                     labelAt(600, 700, "A003", 0.7)};  // the last is don't care
  const std::vector<ocr::TextInstance> found = {
      foundAt(0, 90, "A001"),     // IoU 0.9
      foundAt(230, 300, "A00"),   // IoU 0.7 with A002: found, misread
      foundAt(500, 560, "EXIT"),  // on nothing: false
      foundAt(600, 700, "A003"),  // on the don't-care label: no outcome
  };
  const std::vector<TextOutcome> all = textOutcomes(truth, found);
  ASSERT_EQ(all.size(), 3u);
  const TextOutcome* a001 = outcomeOf(all, OutcomeKind::kFound, 0);
  ASSERT_NE(a001, nullptr);
  EXPECT_EQ(a001->detection, 0);
  EXPECT_NEAR(a001->iou, 0.9, 1e-6);
  const TextOutcome* a002 = outcomeOf(all, OutcomeKind::kFound, 1);
  ASSERT_NE(a002, nullptr);
  EXPECT_NEAR(a002->iou, 0.7, 1e-6);
  EXPECT_NE(outcomeOf(all, OutcomeKind::kFalseDetection, 2), nullptr);

  const nlohmann::json j = outcomeJson(*a002, truth, found);
  EXPECT_EQ(j["outcome"], "found");
  EXPECT_EQ(j["camera"], "left");
  EXPECT_EQ(j["text"], "A002");
  EXPECT_EQ(j["detected"]["text"], "A00");
  EXPECT_NEAR(j["height_px"].get<double>(), 40.0, 1e-6);
}

TEST(TextOutcomes, AMissKeepsTheDetectionThatOverlapsItMost) {
  io::ImageLabels truth;
  truth.instances = {labelAt(0, 100, "A001")};
  const std::vector<ocr::TextInstance> found = {foundAt(70, 170, "01"), foundAt(40, 140, "001")};
  const std::vector<TextOutcome> all = textOutcomes(truth, found);
  const TextOutcome* miss = outcomeOf(all, OutcomeKind::kMissed, 0);
  ASSERT_NE(miss, nullptr);
  EXPECT_EQ(miss->detection, 1);
  EXPECT_NEAR(miss->iou, 60.0 / 140.0, 1e-6);  // under 0.5: a miss, and both boxes are false
  EXPECT_EQ(all.size(), 3u);
  EXPECT_EQ(outcomeJson(*miss, truth, found)["detected"]["text"], "001");
  EXPECT_FALSE(outcomeJson({OutcomeKind::kMissed, 0, -1, 0.0}, truth, found).contains("detected"));
}

TEST(TextOutcomes, ACutNumberIsFoundByItsPartInsideTheImage) {
  io::ImageLabels truth;
  truth.width = 150;
  truth.height = 100;
  truth.instances = {labelAt(100, 300, "A001", 0.0)};  // two thirds outside the image
  truth.instances[0].truncated = true;
  const std::vector<ocr::TextInstance> found = {foundAt(100, 149.5f, "A0")};
  const std::vector<TextOutcome> all = textOutcomes(truth, found);
  ASSERT_EQ(all.size(), 1u);
  EXPECT_EQ(all[0].kind, OutcomeKind::kFound);
  OcrEvaluationOptions whole;
  whole.inside_image_only = false;
  EXPECT_EQ(textOutcomes(truth, found, whole)[0].kind, OutcomeKind::kMissed);
}

}  // namespace
}  // namespace parkloc::eval
