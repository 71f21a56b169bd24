// Tracking identified texts (PipelineOptions::reread_interval_frames): texts read lately
// are only fitted, a few unread ones are read per frame set, and the pose stays exact.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "localize/pipeline.h"
#include "synthetic_scene.h"

namespace parkloc::localize {
namespace {

// Shows exactly what the synthetic scene holds inside the requested regions; a fitted
// region gives its text unread, as the OCR engine does. Notes what was asked for.
class RecordingSpotter : public ocr::TextSpotter {
 public:
  explicit RecordingSpotter(const map::HdMap& map) : map_(map) {}
  std::string name() const override { return "recording"; }
  std::vector<ocr::TextInstance> spot(const cv::Mat&, const ocr::SpotRequest& request) override {
    auto all = testing::spotExactly(*request.camera, map_, pose, {});
    if (request.regions.empty()) {
      for (const auto& t : all) read_now.insert(t.text);
      full_frames.push_back(request);
      full_frames.back().camera = nullptr;  // the pipeline's, gone after the call
      return all;
    }
    std::vector<ocr::TextInstance> out;
    for (const auto& r : request.regions) {
      (r.read ? read_now : fitted_now).insert(r.expected_texts.front());
      reads_asked += r.read ? 1 : 0;
      for (auto t : all)
        if (r.expected_texts.front() == t.text) {
          t.read = r.read;
          out.push_back(t);
        }
    }
    return out;
  }
  geometry::Pose2 pose;
  std::set<std::string> read_now, fitted_now;
  int reads_asked = 0;
  std::vector<ocr::SpotRequest> full_frames;  // every full-frame request, in order

 private:
  const map::HdMap& map_;
};

TEST(TrackedReading, ReadsAFewTextsPerFrameFitsTheRestAndKeepsThePose) {
  const geometry::Rig rig = geometry::defaultRig();
  const map::HdMap map = testing::aisleMap();
  RecordingSpotter spotter(map);
  PipelineOptions options;
  options.reading.reread_interval_frames = 10;
  options.reading.max_reads_per_frame = 2;
  options.reading.full_frame_interval = 1000;  // only the first frame on the full frame
  Pipeline pipeline(rig, map, options, &spotter);
  std::map<std::string, int> last_read;
  int fitted_total = 0;
  for (int k = 0; k < 40; ++k) {
    const double t = k / 10.0;
    spotter.pose = geometry::Pose2(1.5 * t, 0.1, 0.0);
    spotter.read_now.clear();
    spotter.fitted_now.clear();
    spotter.reads_asked = 0;
    const FrameInput in = testing::placeholderFrame(rig, t, 1.5);
    const FrameResult r = pipeline.process(in);
    ASSERT_TRUE(r.has_pose) << "frame " << k;
    EXPECT_LT((r.pose.translation() - spotter.pose.translation()).norm(), 0.01) << "frame " << k;
    if (k > 0) {
      EXPECT_LE(spotter.reads_asked, 2) << "frame " << k;
    }
    // Only texts read within the interval are fitted.
    for (const auto& text : spotter.fitted_now) {
      ASSERT_TRUE(last_read.count(text)) << text << " fitted before it was read, frame " << k;
      EXPECT_LT(k - last_read[text], 10) << text << " frame " << k;
    }
    for (const auto& text : spotter.read_now) last_read[text] = k;
    fitted_total += static_cast<int>(spotter.fitted_now.size());
  }
  EXPECT_GT(fitted_total, 100);  // most measurements come from fits
}

// While tracking, a full-frame sweep is told where the map's floor texts lie around the
// tracked pose and which way they read (for the way round to read each box), but keeps the
// whole floor lexicon; a search before the first fix is told nothing.
TEST(TrackedReading, TheTrackingSweepGetsTheFloorTextsPlacedAroundThePose) {
  const geometry::Rig rig = geometry::defaultRig();
  const map::HdMap map = testing::aisleMap();
  for (const bool place : {true, false}) {
    RecordingSpotter spotter(map);
    PipelineOptions options;
    options.reading.full_frame_interval = 8;
    options.reading.sweep_places_floor_texts = place;
    Pipeline pipeline(rig, map, options, &spotter);
    int sweeps = 0;
    for (int k = 0; k < 20; ++k) {
      spotter.pose = geometry::Pose2(0.15 * k, 0.1, 0.0);
      spotter.full_frames.clear();
      const FrameResult r = pipeline.process(testing::placeholderFrame(rig, k / 10.0, 1.5));
      ASSERT_TRUE(r.has_pose) << "frame " << k;
      for (const ocr::SpotRequest& request : spotter.full_frames) {
        if (k == 0 || !place) {
          EXPECT_TRUE(request.placed_floor_texts.empty()) << "frame " << k;
          continue;
        }
        ++sweeps;
        EXPECT_FALSE(request.narrow_to_placed_texts);
        EXPECT_FALSE(request.floor_lexicon.empty());
        ASSERT_FALSE(request.placed_floor_texts.empty()) << "frame " << k;
        for (const map::PlacedText& placed : request.placed_floor_texts) {
          const map::Landmark* l = nullptr;
          for (const map::Landmark& m : map.landmarks())
            if (m.text == placed.text) l = &m;
          ASSERT_NE(l, nullptr) << placed.text;
          EXPECT_EQ(l->surface, map::Surface::kGround) << placed.text;
          const Eigen::Vector2d truth = spotter.pose.inverse() * l->position.head<2>().eval();
          EXPECT_LT((placed.vehicle_xy - truth).norm(), 0.05) << placed.text << " frame " << k;
          EXPECT_NEAR(placed.reading.y(), l->readingDirection().y(), 0.05) << placed.text;
        }
      }
    }
    if (place) {
      EXPECT_GT(sweeps, 0);
    }
  }
}

TEST(TrackedReading, OffReadsEveryRegion) {
  const geometry::Rig rig = geometry::defaultRig();
  const map::HdMap map = testing::aisleMap();
  RecordingSpotter spotter(map);
  PipelineOptions options;
  options.reading.reread_interval_frames = 0;
  options.reading.full_frame_interval = 1000;
  Pipeline pipeline(rig, map, options, &spotter);
  for (int k = 0; k < 10; ++k) {
    spotter.pose = geometry::Pose2(0.1 * k, 0.1, 0.0);
    spotter.fitted_now.clear();
    const FrameInput in = testing::placeholderFrame(rig, k / 10.0, 1.0);
    pipeline.process(in);
    EXPECT_TRUE(spotter.fitted_now.empty()) << "frame " << k;
  }
}


TEST(TrackedReading, APlanWithoutReadsLeavesItsTextsDueForTheNextPlan) {
  // The read worker busy (no_reads): the texts due a read are only fitted if read lately,
  // and the next plan reads them as if this one had not happened.
  const geometry::Rig rig = geometry::defaultRig();
  const map::HdMap map = testing::aisleMap();
  const FloorHeights floors(map);
  ReadingOptions options;
  options.reread_interval_frames = 10;
  options.max_reads_per_frame = 2;
  options.full_frame_interval = 1000;
  PoseEkf ekf;
  ekf.initialise(geometry::Pose2(0.0, 0.1, 0.0), Eigen::Matrix3d::Identity() * 1e-4, 0.0);
  const LevelEstimate level(map, LevelOptions{}, "");
  const auto reads = [](const ReadPlan& plan) {
    int n = 0;
    for (const auto& camera : plan.regions)
      for (const auto& r : camera) n += r.roi.read;
    return n;
  };
  ReadPlanner busy(rig, rig, map, floors, options, true), free(rig, rig, map, floors, options, true);
  const ReadPlan without = busy.plan(true, ekf, level, std::nullopt, false, /*no_reads=*/true);
  EXPECT_EQ(reads(without), 0);
  const ReadPlan first = free.plan(true, ekf, level);
  ASSERT_EQ(reads(first), 2);
  const ReadPlan after = busy.plan(true, ekf, level);
  EXPECT_EQ(reads(after), reads(first));
}

TEST(TrackedReading, WhileTheLevelIsUndecidedTheLevelSignsAreReadFirst) {
  // Two levels of one plan: the same parking numbers on both, and on each pillar the level's
  // name ("B1" or "B2"), smaller than the numbers. Undecided, the planner reads the pillars,
  // whose reading tells the level, before the larger numbers, which do not.
  const map::HdMap plan = testing::aisleMap();
  std::vector<map::Landmark> landmarks;
  for (const std::string level : {"B1", "B2"})
    for (map::Landmark l : plan.landmarks()) {
      if (l.cls == map::TextClass::kPillar) {
        l.text = level;
        l.width = 0.2;
        l.height = 0.1;
      }
      l.id = level + ":" + l.id;
      l.level = level;
      landmarks.push_back(l);
    }
  const map::HdMap map(landmarks, "two levels");
  const geometry::Rig rig = geometry::defaultRig();
  const FloorHeights floors(map);
  PoseEkf ekf;
  ekf.initialise(geometry::Pose2(0.0, 0.1, 0.0), Eigen::Matrix3d::Identity() * 1e-4, 0.0);
  const LevelEstimate undecided(map, LevelOptions{}, "");
  ASSERT_FALSE(undecided.belief().decided);
  const auto signs_read = [&](int level_place_reads) {
    ReadingOptions options;
    options.max_reads_per_frame = 2;
    options.full_frame_interval = 1000;
    options.level_place_reads = level_place_reads;
    ReadPlanner planner(rig, rig, map, floors, options, true);
    const ReadPlan reading = planner.plan(true, ekf, undecided);
    int signs = 0, reads = 0;
    for (const auto& camera : reading.regions)
      for (const auto& r : camera) {
        reads += r.roi.read;
        signs += r.roi.read && r.roi.expected_texts.size() == 2;
      }
    EXPECT_EQ(reads, 2);
    return signs;
  };
  EXPECT_EQ(signs_read(2), 2);
  EXPECT_EQ(signs_read(1), 1);  // the other read for the largest number
  EXPECT_EQ(signs_read(0), 0);  // by size alone: the numbers
}

}  // namespace
}  // namespace parkloc::localize
