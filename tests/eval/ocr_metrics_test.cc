#include "eval/ocr_metrics.h"

#include <gtest/gtest.h>

namespace parkloc::eval {
namespace {

io::LabelInstance label(double x0, double y0, double x1, double y1, const std::string& text,
                        map::TextClass cls, double occluded = 0.0, double rotation_deg = 0.0) {
  io::LabelInstance l;
  l.polygon = {Eigen::Vector2d(x0, y0), Eigen::Vector2d(x1, y0), Eigen::Vector2d(x1, y1),
               Eigen::Vector2d(x0, y1)};
  l.text = text;
  l.cls = cls;
  l.occluded_fraction = occluded;
  l.rotation_deg = rotation_deg;
  return l;
}

ocr::TextInstance detection(float x0, float y0, float x1, float y1, const std::string& text,
                            const std::string& raw, map::TextClass cls) {
  ocr::TextInstance d;
  d.polygon = {cv::Point2f(x0, y0), cv::Point2f(x1, y0), cv::Point2f(x1, y1), cv::Point2f(x0, y1)};
  d.text = text;
  d.raw_text = raw;
  d.cls = cls;
  return d;
}

using map::TextClass;

TEST(OcrMetrics, CountsOfOneHandMadeImage) {
  io::ImageLabels truth;
  truth.instances = {
      label(0, 0, 100, 40, "B2-117", TextClass::kParkingNumber),         // read right
      label(200, 0, 300, 40, "B2-118", TextClass::kParkingNumber),       // raw wrong
      label(400, 0, 440, 100, "B2", TextClass::kPillar, 0.0, 90.0),      // missed
      label(600, 0, 700, 40, "B2-120", TextClass::kParkingNumber, 0.7),  // don't care
  };
  const std::vector<ocr::TextInstance> detections = {
      detection(0, 0, 100, 40, "B2-117", "B2-117", TextClass::kParkingNumber),
      detection(200, 0, 290, 40, "B2-118", "B2-11B", TextClass::kOther),          // IoU 0.9
      detection(800, 0, 900, 40, "EXIT", "EXIT", TextClass::kOther),              // false positive
      detection(600, 0, 700, 40, "B2-120", "B2-120", TextClass::kParkingNumber),  // ignored
  };
  OcrEvaluator evaluator;
  evaluator.add(truth, detections, {"weak_light"}, 0.5);
  const OcrEvaluation& r = evaluator.result();
  const OcrCounts& all = r.overall;
  EXPECT_EQ(all.truths, 3u);
  EXPECT_EQ(all.detections, 3u);
  EXPECT_EQ(all.tp, 2u);
  EXPECT_EQ(all.fp, 1u);
  EXPECT_EQ(all.fn, 1u);
  EXPECT_NEAR(all.meanIoU(), (1.0 + 0.9) / 2.0, 1e-6);
  EXPECT_DOUBLE_EQ(all.recognitionAccuracy(), 1.0);
  EXPECT_DOUBLE_EQ(all.recognitionRawAccuracy(), 0.5);
  EXPECT_DOUBLE_EQ(all.classificationAccuracy(), 0.5);
  EXPECT_DOUBLE_EQ(all.precision(), 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(all.recall(), 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(all.fMeasure(), 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(all.fpRate(), 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(all.fnRate(), 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(all.endToEndAccuracy(), 2.0 / 3.0);

  const OcrCounts& numbers = r.by_class.at("parking_number");
  EXPECT_EQ(numbers.truths, 2u);
  EXPECT_EQ(numbers.tp, 2u);
  EXPECT_EQ(numbers.fp, 0u);
  EXPECT_EQ(r.by_class.at("pillar").fn, 1u);
  EXPECT_EQ(r.by_class.at("other").fp, 1u);  // the false detection's predicted class

  EXPECT_EQ(r.by_condition.at("weak_light").tp, 2u);
  EXPECT_EQ(r.by_condition.at("rot90").fn, 1u);
  EXPECT_EQ(r.by_condition.count("bright"), 0u);
  EXPECT_EQ(r.images, 1u);
  EXPECT_DOUBLE_EQ(r.imagesPerSecond(), 2.0);
}

TEST(OcrMetrics, ATextCutByTheImageEdgeIsMatchedByThePartTheImageShows) {
  // A 100 x 50 image. The whole text's corners lie far past the right edge; through the lens
  // the part inside ends at x = 70 (visible_polygon), while the straight quad clipped to the
  // image would run to the edge. The detection boxes the part that shows.
  io::ImageLabels truth;
  truth.width = 100;
  truth.height = 50;
  io::LabelInstance cut = label(40, 10, 300, 40, "C004", TextClass::kParkingNumber);
  cut.truncated = true;
  cut.visible_polygon = label(40, 10, 70, 40, "", TextClass::kParkingNumber).polygon;
  truth.instances = {cut};
  const std::vector<ocr::TextInstance> detections = {
      detection(41, 10, 70, 40, "C004", "C004", TextClass::kParkingNumber)};

  OcrEvaluator shown;  // inside_image_only, the default
  shown.add(truth, detections, {}, 0.1);
  EXPECT_EQ(shown.result().overall.tp, 1u);
  EXPECT_NEAR(shown.result().overall.meanIoU(), 29.0 / 30.0, 1e-4);

  OcrEvaluationOptions whole;
  whole.inside_image_only = false;
  OcrEvaluator whole_polygon(whole);
  whole_polygon.add(truth, detections, {}, 0.1);
  EXPECT_EQ(whole_polygon.result().overall.tp, 0u);
  EXPECT_EQ(whole_polygon.result().overall.fn, 1u);
}

TEST(OcrMetrics, HeightBinsSplitAtTheirEdges) {
  EXPECT_EQ(heightBin(7.9), "under 8 px");
  EXPECT_EQ(heightBin(8.0), "8-12 px");
  EXPECT_EQ(heightBin(23.9), "16-24 px");
  EXPECT_EQ(heightBin(40.0), "24 px and more");
}

TEST(OcrMetrics, ParkingNumbersAreCountedByHeight) {
  io::ImageLabels truth;
  truth.instances = {
      label(0, 0, 100, 10, "B2-117", TextClass::kParkingNumber),    // 10 px, found
      label(200, 0, 300, 30, "B2-118", TextClass::kParkingNumber),  // 30 px, missed
      label(400, 0, 500, 30, "B2", TextClass::kPillar),             // not a number
  };
  const std::vector<ocr::TextInstance> detections = {
      detection(0, 0, 100, 10, "B2-117", "B2-117", TextClass::kParkingNumber),
      detection(400, 0, 500, 30, "B2", "B2", TextClass::kPillar),
  };
  OcrEvaluator evaluator;
  evaluator.add(truth, detections, {});
  const auto& bins = evaluator.result().parking_numbers_by_height;
  ASSERT_EQ(bins.size(), 2u);
  EXPECT_EQ(bins.at("8-12 px").tp, 1u);
  EXPECT_EQ(bins.at("8-12 px").truths, 1u);
  EXPECT_EQ(bins.at("24 px and more").fn, 1u);
  EXPECT_EQ(bins.at("24 px and more").tp, 0u);
}

// Numbers go to the bin of their paint; a false detection, which has no paint, to none.
TEST(OcrMetrics, ParkingNumbersAreCountedByTheirPaint) {
  io::ImageLabels truth;
  truth.instances = {
      label(0, 0, 100, 30, "B2-117", TextClass::kParkingNumber),    // intact, found
      label(200, 0, 300, 30, "B2-118", TextClass::kParkingNumber),  // worn, missed
      label(400, 0, 500, 30, "B2-119", TextClass::kParkingNumber),  // worn, found, misread
  };
  truth.instances[1].paint_wear = 0.6;
  truth.instances[2].paint_wear = 0.3;
  const std::vector<ocr::TextInstance> detections = {
      detection(0, 0, 100, 30, "B2-117", "B2-117", TextClass::kParkingNumber),
      detection(400, 0, 500, 30, "B2-110", "B2-110", TextClass::kParkingNumber),
      detection(800, 0, 900, 30, "B2-120", "B2-120", TextClass::kParkingNumber),  // false
  };
  OcrEvaluator evaluator;
  evaluator.add(truth, detections, {});
  const auto& bins = evaluator.result().parking_numbers_by_paint;
  ASSERT_EQ(bins.size(), 2u);
  const OcrCounts& intact = bins.at("intact paint");
  const OcrCounts& worn = bins.at("worn paint");
  EXPECT_EQ(intact.truths, 1u);
  EXPECT_EQ(intact.tp, 1u);
  EXPECT_EQ(intact.recognized, 1u);
  EXPECT_EQ(worn.truths, 2u);
  EXPECT_EQ(worn.tp, 1u);
  EXPECT_EQ(worn.fn, 1u);
  EXPECT_EQ(worn.recognized, 0u);
  EXPECT_EQ(intact.fp + worn.fp, 0u);
  EXPECT_EQ(evaluator.result().overall.fp, 1u);
  EXPECT_EQ(paintBin(0.0), "intact paint");
  EXPECT_EQ(paintBin(0.01), "worn paint");
}

// A number partly hidden, or cut by the image's edge, goes to "partly hidden"; its raw reading
// of the part that shows counts there, not beside the numbers in full sight.
TEST(OcrMetrics, ParkingNumbersAreCountedByWhetherTheyAreInFullSight) {
  io::ImageLabels truth;
  truth.instances = {
      label(0, 0, 100, 30, "B2-117", TextClass::kParkingNumber),         // in sight, raw right
      label(200, 0, 300, 30, "B2-118", TextClass::kParkingNumber, 0.3),  // hidden, raw a part
      label(400, 0, 500, 30, "B2-119", TextClass::kParkingNumber),       // cut by the edge
      label(600, 0, 700, 30, "B2-120", TextClass::kParkingNumber, 0.7),  // don't care
  };
  truth.instances[2].truncated = true;
  const std::vector<ocr::TextInstance> detections = {
      detection(0, 0, 100, 30, "B2-117", "B2-117", TextClass::kParkingNumber),
      detection(200, 0, 300, 30, "B2-118", "-118", TextClass::kParkingNumber),
      detection(800, 0, 900, 30, "B2-121", "B2-121", TextClass::kParkingNumber),  // false
  };
  // truths, TP, FN, FP, read with the lexicon, read raw
  auto counts = [](const OcrCounts& c) {
    return std::vector<size_t>{c.truths, c.tp, c.fn, c.fp, c.recognized, c.recognized_raw};
  };
  OcrEvaluator evaluator;
  evaluator.add(truth, detections, {});
  const auto& bins = evaluator.result().parking_numbers_by_sight;
  ASSERT_EQ(bins.size(), 2u);
  EXPECT_EQ(counts(bins.at("in full sight")), (std::vector<size_t>{1, 1, 0, 0, 1, 1}));
  EXPECT_EQ(counts(bins.at("partly hidden")), (std::vector<size_t>{2, 1, 1, 0, 1, 0}));
  EXPECT_EQ(counts(evaluator.result().overall), (std::vector<size_t>{3, 2, 1, 1, 2, 1}));
}

// Numbers go to the bin of their ink's SNR; labels without one, and false detections, to none.
TEST(OcrMetrics, ParkingNumbersAreCountedByTheirInkSnr) {
  io::ImageLabels truth;
  truth.instances = {
      label(0, 0, 100, 30, "B2-117", TextClass::kParkingNumber),    // SNR 6.5, found
      label(200, 0, 300, 30, "B2-118", TextClass::kParkingNumber),  // SNR 6.5, missed
      label(400, 0, 500, 30, "B2-119", TextClass::kParkingNumber),  // SNR 30, found
      label(600, 0, 700, 30, "B2-121", TextClass::kParkingNumber),  // no SNR, found
  };
  truth.instances[0].ink_snr = 6.5;
  truth.instances[1].ink_snr = 6.5;
  truth.instances[2].ink_snr = 30.0;
  const std::vector<ocr::TextInstance> detections = {
      detection(0, 0, 100, 30, "B2-117", "B2-117", TextClass::kParkingNumber),
      detection(400, 0, 500, 30, "B2-119", "B2-119", TextClass::kParkingNumber),
      detection(600, 0, 700, 30, "B2-121", "B2-121", TextClass::kParkingNumber),
      detection(800, 0, 900, 30, "B2-120", "B2-120", TextClass::kParkingNumber),  // false
  };
  OcrEvaluator evaluator;
  evaluator.add(truth, detections, {});
  const auto& bins = evaluator.result().parking_numbers_by_ink;
  ASSERT_EQ(bins.size(), 2u);
  const OcrCounts& faint = bins.at("ink SNR under 8");
  const OcrCounts& clear = bins.at("ink SNR 20 and more");
  EXPECT_EQ(faint.truths, 2u);
  EXPECT_EQ(faint.tp, 1u);
  EXPECT_EQ(faint.fn, 1u);
  EXPECT_EQ(clear.truths, 1u);
  EXPECT_EQ(clear.tp, 1u);
  EXPECT_EQ(faint.fp + clear.fp, 0u);
  EXPECT_EQ(evaluator.result().overall.truths, 4u);
  EXPECT_EQ(inkBin(7.99), "ink SNR under 8");
  EXPECT_EQ(inkBin(8.0), "ink SNR 8-12");
  EXPECT_EQ(inkBin(19.9), "ink SNR 12-20");
}

TEST(OcrMetrics, TheHeightOnlyRuleCaresForTextLabelledIllegibleButTallEnough) {
  io::ImageLabels truth;
  truth.instances = {
      label(0, 0, 100, 30, "B2-117", TextClass::kParkingNumber),    // legible, found
      label(200, 0, 220, 30, "B2-118", TextClass::kParkingNumber),  // squeezed, missed
      label(400, 0, 500, 6, "B2-119", TextClass::kParkingNumber),   // 6 px, missed
      label(600, 0, 700, 30, "B2-120", TextClass::kParkingNumber),  // squeezed, found
  };
  truth.instances[1].legible = false;
  truth.instances[2].legible = false;
  truth.instances[3].legible = false;
  const std::vector<ocr::TextInstance> detections = {
      detection(0, 0, 100, 30, "B2-117", "B2-117", TextClass::kParkingNumber),
      detection(600, 0, 700, 30, "B2-120", "B2-120", TextClass::kParkingNumber),
  };
  OcrEvaluator evaluator;
  evaluator.add(truth, detections, {});
  const OcrCounts& labelled = evaluator.result().by_class.at("parking_number");
  EXPECT_EQ(labelled.truths, 1u);  // the found illegible one is ignored, not a false positive
  EXPECT_EQ(labelled.tp, 1u);
  EXPECT_EQ(labelled.fp, 0u);
  const OcrCounts& by_height = evaluator.result().height_rule_by_class.at("parking_number");
  EXPECT_EQ(by_height.truths, 3u);  // all but the one under 8 px
  EXPECT_EQ(by_height.tp, 2u);
  EXPECT_EQ(by_height.fn, 1u);
  EXPECT_EQ(by_height.fp, 0u);
}

TEST(OcrMetrics, ReadingAngleFollowsTheLabelConvention) {
  Quad upright = {cv::Point2f(0, 0), cv::Point2f(10, 0), cv::Point2f(10, 4), cv::Point2f(0, 4)};
  EXPECT_NEAR(readingAngleDeg(upright), 0.0, 1e-9);
  Quad upside_down = {upright[2], upright[3], upright[0], upright[1]};
  EXPECT_NEAR(std::fabs(readingAngleDeg(upside_down)), 180.0, 1e-9);
  // Reading downwards in the image (y grows): +90 in image coordinates.
  Quad down = {cv::Point2f(4, 0), cv::Point2f(4, 10), cv::Point2f(0, 10), cv::Point2f(0, 0)};
  EXPECT_NEAR(readingAngleDeg(down), 90.0, 1e-9);
}

TEST(OcrMetrics, AccumulatesOverImages) {
  io::ImageLabels truth;
  truth.instances = {label(0, 0, 100, 40, "117", TextClass::kParkingNumber)};
  OcrEvaluator evaluator;
  evaluator.add(truth, {detection(0, 0, 100, 40, "117", "117", TextClass::kParkingNumber)}, {});
  evaluator.add(truth, {}, {});
  EXPECT_EQ(evaluator.result().overall.tp, 1u);
  EXPECT_EQ(evaluator.result().overall.fn, 1u);
  EXPECT_DOUBLE_EQ(evaluator.result().overall.recall(), 0.5);
  EXPECT_DOUBLE_EQ(evaluator.result().overall.precision(), 1.0);
}

}  // namespace
}  // namespace parkloc::eval
