#include "localize/region_budget.h"

#include <gtest/gtest.h>

#include <set>

#include "localize/pipeline.h"
#include "synthetic_scene.h"

namespace parkloc::localize {
namespace {

RegionCandidate candidate(const std::string& id, double size_px, double height_px = 20.0) {
  RegionCandidate c;
  c.landmark_id = id;
  c.roi.expected_texts = {id};
  c.size_px = size_px;
  c.height_px = height_px;
  return c;
}

// Four cameras, each predicting `per_camera` landmarks of decreasing size.
std::vector<std::vector<RegionCandidate>> fourCameras(int per_camera) {
  std::vector<std::vector<RegionCandidate>> out(4);
  for (int c = 0; c < 4; ++c)
    for (int i = 0; i < per_camera; ++i)
      out[c].push_back(
          candidate("c" + std::to_string(c) + "-" + std::to_string(i), 100.0 - 10 * i));
  return out;
}

size_t total(const std::vector<std::vector<size_t>>& chosen) {
  size_t n = 0;
  for (const auto& c : chosen) n += c.size();
  return n;
}

TEST(RegionBudget, NeverExceedsTheBudgetAndServesEveryCameraWhenItCan) {
  const auto candidates = fourCameras(10);
  for (int budget : {1, 2, 3, 4, 6, 9}) {
    RegionBudgetOptions options;
    options.max_regions = budget;
    const auto chosen = selectRegionsWithinBudget(candidates, {}, 0, options);
    EXPECT_EQ(total(chosen), static_cast<size_t>(budget));
    if (budget >= 4) {
      for (const auto& c : chosen) EXPECT_FALSE(c.empty());
    }
  }
}

TEST(RegionBudget, WithoutABudgetEveryRegionIsChosen) {
  const auto candidates = fourCameras(7);
  RegionBudgetOptions options;
  options.max_regions = 0;
  EXPECT_EQ(total(selectRegionsWithinBudget(candidates, {}, 0, options)), 28u);
}

TEST(RegionBudget, PrefersTheLargestTextAndSkipsGrazingViews) {
  std::vector<std::vector<RegionCandidate>> candidates(1);
  candidates[0] = {candidate("small", 20.0), candidate("grazing", 300.0, 3.0),
                   candidate("large", 150.0), candidate("medium", 60.0)};
  RegionBudgetOptions options;
  options.max_regions = 2;
  const auto chosen = selectRegionsWithinBudget(candidates, {}, 0, options);
  ASSERT_EQ(chosen[0].size(), 2u);
  EXPECT_EQ(chosen[0][0], 2u);  // large
  EXPECT_EQ(chosen[0][1], 3u);  // medium
}

TEST(RegionBudget, LandmarksAskedForLatelyGiveWayToOthers) {
  std::vector<std::vector<RegionCandidate>> candidates(1);
  candidates[0] = {candidate("near", 120.0), candidate("farther", 80.0)};
  RegionBudgetOptions options;
  options.max_regions = 1;
  std::map<std::string, int> last_asked;
  std::vector<std::string> picked;
  for (int frame = 0; frame < 4; ++frame) {
    const auto chosen = selectRegionsWithinBudget(candidates, last_asked, frame, options);
    ASSERT_EQ(chosen[0].size(), 1u);
    const auto& id = candidates[0][chosen[0][0]].landmark_id;
    last_asked[id] = frame;
    picked.push_back(id);
  }
  EXPECT_EQ(picked.front(), "near");
  EXPECT_EQ(std::set<std::string>(picked.begin(), picked.end()).size(), 2u);
}

TEST(RegionBudget, ASmallBudgetRotatesOverTheCameras) {
  const auto candidates = fourCameras(3);
  RegionBudgetOptions options;
  options.max_regions = 1;
  std::set<size_t> served;
  for (int frame = 0; frame < 4; ++frame) {
    options.first_camera = frame;
    const auto chosen = selectRegionsWithinBudget(candidates, {}, frame, options);
    ASSERT_EQ(total(chosen), 1u);
    for (size_t c = 0; c < chosen.size(); ++c)
      if (!chosen[c].empty()) served.insert(c);
  }
  EXPECT_EQ(served.size(), 4u);
}

// The pipeline with the budget: a spotter that reads exactly what the synthetic scene shows
// inside the requested regions, on a drive down the aisle.
class CountingSpotter : public ocr::TextSpotter {
 public:
  CountingSpotter(const geometry::Rig& rig, const map::HdMap& map) : rig_(rig), map_(map) {}
  std::string name() const override { return "counting"; }
  std::vector<ocr::TextInstance> spot(const cv::Mat&, const ocr::SpotRequest& request) override {
    if (!only_camera.empty() && request.camera->name != only_camera) return {};
    auto all = testing::spotExactly(*request.camera, map_, pose, {});
    return testing::inRequestedRegions(all, request);
  }
  geometry::Pose2 pose;
  std::string only_camera;  // non-empty: every other camera sees nothing

 private:
  const geometry::Rig& rig_;
  const map::HdMap& map_;
};

TEST(RegionBudget, PipelineKeepsTheBudgetSpreadsFullFramesAndRotatesCameras) {
  const geometry::Rig rig = geometry::defaultRig();
  const map::HdMap map = testing::aisleMap();
  CountingSpotter spotter(rig, map);
  PipelineOptions options;
  options.reading.max_regions_per_frame = 2;
  options.reading.max_regions_with_full_frame = 1;
  options.reading.full_frame_round_robin = true;
  options.reading.full_frame_interval = 8;
  options.reading.search_cameras_per_frame = 0;  // the first frame spots every camera
  Pipeline pipeline(rig, map, options, &spotter);
  std::set<std::string> cameras_with_regions, cameras_on_full_frame;
  int tracked = 0;
  for (int k = 0; k < 40; ++k) {
    const double t = k / 10.0;
    spotter.pose = geometry::Pose2(2.0 * t, 0.1, 0.0);
    const FrameInput in = testing::placeholderFrame(rig, t, 2.0);
    const FrameResult r = pipeline.process(in);
    ASSERT_TRUE(r.has_pose) << "frame " << k;
    EXPECT_LT((r.pose.translation() - spotter.pose.translation()).norm(), 0.01) << "frame " << k;
    int regions = 0, full = 0;
    for (const auto& c : r.cameras) {
      regions += c.regions;
      full += c.full_frame ? 1 : 0;
      if (c.regions > 0) cameras_with_regions.insert(c.camera);
    }
    if (k == 0) {
      EXPECT_EQ(full, 4);  // not initialised: every camera on the full frame
      continue;
    }
    ++tracked;
    EXPECT_LE(full, 1) << "frame " << k;
    EXPECT_LE(regions, full ? 1 : 2) << "frame " << k;
    for (const auto& c : r.cameras)
      if (c.full_frame) cameras_on_full_frame.insert(c.camera);
  }
  EXPECT_EQ(tracked, 39);
  EXPECT_EQ(cameras_on_full_frame.size(), rig.cameras.size());  // each camera's turn came
  EXPECT_GE(cameras_with_regions.size(), 3u);  // regions went round the cameras that see text
}

TEST(RegionBudget, SearchSpotsOneCameraPerFrameInTurnUntilTheFirstFix) {
  const geometry::Rig rig = geometry::defaultRig();
  const map::HdMap map = testing::aisleMap();
  CountingSpotter spotter(rig, map);
  spotter.only_camera = "left";  // the only camera that sees text (the others are dark)
  PipelineOptions options;
  options.reading.search_cameras_per_frame = 1;
  Pipeline pipeline(rig, map, options, &spotter);
  std::vector<std::string> searched;
  for (int k = 0; k < 8; ++k) {
    const double t = k / 10.0;
    spotter.pose = geometry::Pose2(2.0 * t, 0.1, 0.0);
    const FrameResult r = pipeline.process(testing::placeholderFrame(rig, t, 2.0));
    if (r.has_pose) {
      EXPECT_LT((r.pose.translation() - spotter.pose.translation()).norm(), 0.01);
      break;
    }
    int full = 0;
    for (const auto& c : r.cameras)
      if (c.full_frame) {
        ++full;
        searched.push_back(c.camera);
      }
    EXPECT_EQ(full, 1) << "frame " << k;
  }
  // Rig order front, rear, left, right: the fix comes on the third frame, from the left.
  EXPECT_EQ(searched, (std::vector<std::string>{"front", "rear"}));
}

}  // namespace
}  // namespace parkloc::localize
