#include "ocr/ppocr/regions.h"

#include <gtest/gtest.h>

namespace parkloc::ocr {
namespace {

DbBox boxAt(float cx, float cy, float score) {
  DbBox box;
  box.quad = {
      cv::Point2f(cx - 10, cy - 5), {cx + 10, cy - 5}, {cx + 10, cy + 5}, {cx - 10, cy + 5}};
  box.score = score;
  return box;
}

// A 256 x 64 patch whose predicted text is 100 x 20 px: its centre is (128, 32).
const cv::Size kPatch{256, 64};

TEST(BoxAtPrediction, IsTheBoxNearestThePredictedCentre) {
  const auto chosen = boxAtPrediction(
      {boxAt(160, 32, 0.9f), boxAt(130, 35, 0.5f), boxAt(100, 30, 0.7f)}, kPatch, 100.f, 20.f);
  ASSERT_TRUE(chosen.has_value());
  EXPECT_FLOAT_EQ(chosen->score, 0.5f);
}

TEST(BoxAtPrediction, IgnoresBoxesBeyondThreeQuartersOfAWidthAlongOrAHeightAcross) {
  // 76 px along is 0.76 text widths; 21 px across is 1.05 text heights.
  EXPECT_FALSE(boxAtPrediction({boxAt(128 + 76, 32, 0.9f)}, kPatch, 100.f, 20.f));
  EXPECT_FALSE(boxAtPrediction({boxAt(128, 32 + 21, 0.9f)}, kPatch, 100.f, 20.f));
  EXPECT_TRUE(boxAtPrediction({boxAt(128 + 74, 32, 0.9f)}, kPatch, 100.f, 20.f));
  EXPECT_TRUE(boxAtPrediction({boxAt(128, 32 + 19, 0.9f)}, kPatch, 100.f, 20.f));
  EXPECT_FALSE(boxAtPrediction({}, kPatch, 100.f, 20.f));
}

TEST(RegionJobs, ReadAtThePredictionGrownOrAtTheRegionOneWayRound) {
  RegionOfInterest predicted, searched;
  predicted.expected_texts = {"B2-117"};
  predicted.predicted = {cv::Point2f(0, 0), {100, 0}, {100, 20}, {0, 20}};
  searched.expected_texts = {"B2-118"};
  searched.polygon = {cv::Point2f(10, 10), {50, 10}, {50, 30}, {10, 30}};
  const std::vector<RegionOfInterest> regions = {predicted, searched};
  RegionOptions options;
  const std::vector<ReadJob> jobs = regionJobs(regions, options);
  ASSERT_EQ(jobs.size(), 2u);
  EXPECT_TRUE(readAtPrediction(regions[0], options));
  EXPECT_FALSE(readAtPrediction(regions[1], options));
  EXPECT_NEAR(quadWidth(jobs[0].quad), 100.f * options.prediction_expand_x, 1e-3);
  EXPECT_NEAR(quadHeight(jobs[0].quad), 20.f * options.prediction_expand_y, 1e-3);
  EXPECT_EQ(jobs[1].quad, regions[1].polygon);
  for (size_t r = 0; r < jobs.size(); ++r) {
    EXPECT_EQ(jobs[r].lexicon, &regions[r].expected_texts);
    EXPECT_FALSE(jobs[r].try_both_directions);
    EXPECT_EQ(jobs[r].detection_score, 0.f);
  }
  options.read_at_prediction = false;
  EXPECT_EQ(regionJobs(regions, options)[0].quad, regions[0].polygon);
}

TEST(RegionPatches, AreMadeForTheSearchedRegionsAtThePatchSize) {
  RegionOfInterest predicted, searched;
  predicted.predicted = {cv::Point2f(0, 0), {100, 0}, {100, 20}, {0, 20}};
  searched.polygon = {cv::Point2f(100, 100), {200, 100}, {200, 120}, {100, 120}};
  const cv::Mat image(300, 300, CV_8UC3, cv::Scalar(128, 128, 128));
  const auto patches = regionPatches(image, {predicted, searched}, RegionOptions{});
  ASSERT_EQ(patches.size(), 1u);
  EXPECT_EQ(patches[0].region, 1u);
  EXPECT_EQ(patches[0].image.size(), RegionOptions{}.patch);
  // The text keeps its aspect ratio in the patch (5 : 1).
  EXPECT_NEAR(patches[0].text_width / patches[0].text_height, 5.f, 1e-3);
}

}  // namespace
}  // namespace parkloc::ocr
