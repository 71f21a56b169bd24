#include "eval/text_matching.h"

#include <gtest/gtest.h>

namespace parkloc::eval {
namespace {

Quad box(float x0, float y0, float x1, float y1) {
  return {cv::Point2f(x0, y0), cv::Point2f(x1, y0), cv::Point2f(x1, y1), cv::Point2f(x0, y1)};
}

TEST(TextMatching, ATextCutByTheImageBorderMatchesItsVisiblePart) {
  // The label runs 40 px past a 100 x 50 image's right edge; the detection covers 36 of
  // the 40 px inside: IoU 0.45 with the whole label, 0.9 with its part inside the image.
  const std::vector<Quad> truths = {box(59.5f, 10, 139.5f, 20)};
  const std::vector<Quad> detections = {box(63.5f, 10, 99.5f, 20)};
  EXPECT_TRUE(matchDetections(truths, {false}, detections).matches.empty());
  MatchingOptions options;
  options.image_size = cv::Size(100, 50);
  const ImageMatching m = matchDetections(truths, {false}, detections, options);
  ASSERT_EQ(m.matches.size(), 1u);
  EXPECT_NEAR(m.matches[0].iou, 0.9, 1e-4);
  EXPECT_TRUE(m.false_detections.empty());
}

TEST(TextMatching, APartlyHiddenTextMatchesADetectionOfItsVisiblePartOrOfTheWholeText) {
  // A car hides the top 60 % of a 100 x 20 px number: the label's visible part is the strip
  // y 12..20, the whole text y 0..20.
  const std::vector<Quad> shown = {box(0, 12, 100, 20)};
  const std::vector<std::optional<Quad>> whole = {box(0, 0, 100, 20)};
  const std::vector<Quad> of_the_whole = {box(0, 1, 100, 20)};  // IoU 0.42 with the strip
  EXPECT_TRUE(matchDetections(shown, {false}, of_the_whole).matches.empty());
  ImageMatching m = matchDetections(shown, whole, {false}, of_the_whole);
  ASSERT_EQ(m.matches.size(), 1u);
  EXPECT_NEAR(m.matches[0].iou, 0.95, 1e-6);
  // A box of the strip matches through the strip itself; one of neither does not match.
  m = matchDetections(shown, whole, {false}, {box(0, 12, 100, 20)});
  ASSERT_EQ(m.matches.size(), 1u);
  EXPECT_NEAR(m.matches[0].iou, 1.0, 1e-6);
  m = matchDetections(shown, whole, {false}, {box(0, 0, 45, 20)});
  EXPECT_TRUE(m.matches.empty());
  EXPECT_EQ(m.false_detections.size(), 1u);
}

TEST(TextMatching, OneToOneAtIoUHalf) {
  const std::vector<Quad> truths = {box(0, 0, 10, 10), box(100, 0, 110, 10)};
  // d0 on t0 (IoU 0.81), d1 a duplicate of t0 (IoU 0.64, must not match twice), d2 far off.
  const std::vector<Quad> detections = {box(1, 1, 10, 10), box(2, 2, 10, 10), box(200, 0, 210, 10)};
  const ImageMatching m = matchDetections(truths, {false, false}, detections);
  ASSERT_EQ(m.matches.size(), 1u);
  EXPECT_EQ(m.matches[0].truth, 0u);
  EXPECT_EQ(m.matches[0].detection, 0u);
  EXPECT_NEAR(m.matches[0].iou, 0.81, 1e-6);
  EXPECT_EQ(m.missed_truths, std::vector<size_t>({1}));
  EXPECT_TRUE(m.nearest_to_missed.empty());  // nothing overlaps t1
  EXPECT_EQ(m.false_detections, std::vector<size_t>({1, 2}));
  EXPECT_TRUE(m.ignored_detections.empty());
}

TEST(TextMatching, BelowHalfIoUIsNoMatch) {
  // IoU 1/3: a false positive and a miss.
  const ImageMatching m = matchDetections({box(0, 0, 10, 10)}, {false}, {box(5, 0, 15, 10)});
  EXPECT_TRUE(m.matches.empty());
  EXPECT_EQ(m.missed_truths.size(), 1u);
  EXPECT_EQ(m.false_detections.size(), 1u);
  ASSERT_EQ(m.nearest_to_missed.size(), 1u);  // the box beside the miss is what was found there
  EXPECT_EQ(m.nearest_to_missed[0].detection, 0u);
  EXPECT_NEAR(m.nearest_to_missed[0].iou, 1.0 / 3.0, 1e-6);
}

TEST(TextMatching, GreedyTakesTheBestPairFirst) {
  // Each detection overlaps both truths (IoU 2/3) and equals one of them (IoU 1): greedy
  // matching by IoU pairs each with its equal, not the first one it overlaps.
  const std::vector<Quad> truths = {box(0, 0, 10, 10), box(2, 0, 12, 10)};
  const std::vector<Quad> detections = {box(2, 0, 12, 10), box(0, 0, 10, 10)};
  const ImageMatching m = matchDetections(truths, {false, false}, detections);
  ASSERT_EQ(m.matches.size(), 2u);
  for (const MatchedPair& p : m.matches) EXPECT_NEAR(p.iou, 1.0, 1e-6);
}

TEST(TextMatching, DontCareTruthIsNeitherMissedNorAFalsePositive) {
  const std::vector<Quad> truths = {box(0, 0, 10, 10), box(50, 0, 60, 10)};
  const std::vector<Quad> detections = {box(0, 0, 10, 10), box(51, 1, 59, 9)};
  const ImageMatching m = matchDetections(truths, {false, true}, detections);
  EXPECT_EQ(m.matches.size(), 1u);
  EXPECT_TRUE(m.missed_truths.empty());
  EXPECT_TRUE(m.false_detections.empty());
  EXPECT_EQ(m.ignored_detections, std::vector<size_t>({1}));
}

TEST(TextMatching, ABoxOnTheWholeOfAMostlyHiddenTextIsIgnored) {
  // A car hides the top 70 % of a 100 x 20 px number (don't care): its visible strip is y 14..20.
  // A box of the whole text covers the strip by 30 % of its own area (IoU 0.3), yet boxes the
  // whole text: ignored, as a box of the strip would be.
  const std::vector<Quad> shown = {box(0, 14, 100, 20)};
  const std::vector<std::optional<Quad>> whole = {box(0, 0, 100, 20)};
  const std::vector<Quad> of_the_whole = {box(0, 0, 100, 20)};
  EXPECT_EQ(matchDetections(shown, {true}, of_the_whole).false_detections.size(), 1u);
  const ImageMatching m = matchDetections(shown, whole, {true}, of_the_whole);
  EXPECT_TRUE(m.false_detections.empty());
  EXPECT_EQ(m.ignored_detections, std::vector<size_t>({0}));
  // A box beside the text is no box of it.
  EXPECT_EQ(matchDetections(shown, whole, {true}, {box(0, 40, 100, 60)}).false_detections.size(),
            1u);
}

TEST(TextMatching, UndetectedDontCareIsNotMissed) {
  const ImageMatching m = matchDetections({box(0, 0, 10, 10)}, {true}, {});
  EXPECT_TRUE(m.missed_truths.empty());
}

}  // namespace
}  // namespace parkloc::eval
