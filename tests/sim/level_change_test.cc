// Drives that change level: the level schedule, the ramp level, level signs and the dataset
// writer's levels.csv, labels and meta.json of a drive down a ramp.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "common/error.h"
#include "io/sequence.h"
#include "sim/annotate.h"
#include "sim/dataset_writer.h"
#include "sim/garage.h"
#include "sim/level_schedule.h"
#include "sim/ramp_level.h"
#include "sim_test_util.h"

namespace parkloc::sim {
namespace {

DriveSpec downTheRamp(double duration, double ramp) {
  DriveSpec d;
  d.level = "B1";
  d.to_level = "B2";
  d.duration_s = duration;
  d.transition_s = ramp;
  return d;
}

TEST(LevelSchedule, CentredRampSplitsTheDrive) {
  const LevelSchedule s = levelSchedule(downTheRamp(30.0, 3.0), "B1", 29.99);
  ASSERT_TRUE(s.changesLevel());
  EXPECT_EQ(s.ramp_start, 13.5);
  EXPECT_EQ(s.ramp_end, 16.5);
  EXPECT_EQ(s.stretchAt(13.4), Stretch::kStartLevel);
  EXPECT_EQ(s.stretchAt(13.5), Stretch::kRamp);
  EXPECT_EQ(s.stretchAt(16.4), Stretch::kRamp);
  EXPECT_EQ(s.stretchAt(16.5), Stretch::kEndLevel);
  // On the ramp the frame still belongs to the level the car left.
  EXPECT_EQ(s.levelAt(16.4), "B1");
  EXPECT_EQ(s.levelAt(16.5), "B2");
}

TEST(LevelSchedule, ExplicitStartAndDrivesThatStay) {
  DriveSpec d = downTheRamp(20.0, 2.0);
  d.transition_at_s = 5.0;
  const LevelSchedule s = levelSchedule(d, "B1", 20.0);
  EXPECT_EQ(s.ramp_start, 5.0);
  EXPECT_EQ(s.ramp_end, 7.0);
  const LevelSchedule stay = levelSchedule(DriveSpec{}, "P3", 12.0);
  EXPECT_FALSE(stay.changesLevel());
  EXPECT_EQ(stay.stretchAt(6.0), Stretch::kStartLevel);
  EXPECT_EQ(stay.levelAt(1e6), "P3");
}

TEST(LevelSchedule, RampPastTheEndOfTheDriveIsRejected) {
  DriveSpec d = downTheRamp(20.0, 3.0);
  d.transition_at_s = 8.0;
  // The tour came out shorter than asked for: the ramp would end after the last frame.
  EXPECT_THROW(levelSchedule(d, "B1", 10.5), InputError);
  EXPECT_NO_THROW(levelSchedule(d, "B1", 11.5));
}

GarageSpec twoLevels(bool signs) {
  GarageSpec s = testing::smallSpec();
  s.levels = {"B1", "B2"};
  s.occupancy = 0.5;
  s.level_signs = signs;
  return s;
}

TEST(LevelSigns, EveryLevelGetsSignsNamingItAndNothingElseChanges) {
  const Garage plain = generateGarage(twoLevels(false), 17);
  const Garage signed_garage = generateGarage(twoLevels(true), 17);
  for (const std::string level : {"B1", "B2"}) {
    int signs = 0;
    for (const auto& lm : signed_garage.map.landmarks())
      if (lm.level == level && lm.id.find(":sign:") != std::string::npos) {
        EXPECT_EQ(lm.text, level);
        ++signs;
      }
    // One aisle: two end walls, two cross-aisle walls at each end, a two-faced board.
    EXPECT_EQ(signs, 8) << level;
  }
  // Every other landmark, box and decal is where it was without signs.
  std::vector<map::Landmark> rest;
  for (const auto& lm : signed_garage.map.landmarks())
    if (lm.id.find(":sign:") == std::string::npos) rest.push_back(lm);
  ASSERT_EQ(rest.size(), plain.map.landmarks().size());
  for (size_t i = 0; i < rest.size(); ++i) {
    EXPECT_EQ(rest[i].id, plain.map.landmarks()[i].id);
    EXPECT_EQ(rest[i].text, plain.map.landmarks()[i].text);
    EXPECT_EQ(rest[i].position, plain.map.landmarks()[i].position);
  }
  for (size_t l = 0; l < plain.levels.size(); ++l) {
    EXPECT_EQ(signed_garage.levels[l].floor_decals.size(), plain.levels[l].floor_decals.size());
    const cv::Mat diff = signed_garage.levels[l].floor_shade != plain.levels[l].floor_shade;
    EXPECT_EQ(cv::countNonZero(diff), 0);
  }
}

TEST(LevelSigns, TheEndWallSignIsLegibleToACarDrivingTowardsIt) {
  const Garage g = generateGarage(twoLevels(true), 17);
  const geometry::Rig rig = geometry::defaultRig();
  const geometry::RigCamera& front = rig.cameras.at(0);
  ASSERT_EQ(front.name, "front");
  // In aisle 0's lane, heading west to the wall at x = 0, 6 m short of it.
  const geometry::Pose2 pose(6.0 + 3.7, g.aisle_y[0] + 0.6, M_PI);
  int legible_signs = 0;
  for (const auto& inst : annotateImage(g, g.levelIndex("B2"), front, pose))
    if (inst.landmark_id.rfind("B2:sign:", 0) == 0 && inst.legible && inst.text == "B2")
      ++legible_signs;
  EXPECT_GE(legible_signs, 1);
}

TEST(RampLevel, KeepsBarePillarsAndLampsAndNoText) {
  const Garage g = generateGarage(twoLevels(true), 17);
  const GarageLevel& b1 = g.levels[0];
  const GarageLevel ramp = rampLevel(g, 0);
  const auto pillars = std::count_if(b1.boxes.begin(), b1.boxes.end(),
                                     [](const Box& b) { return b.material == Material::kPillar; });
  ASSERT_GT(pillars, 0);
  EXPECT_EQ(static_cast<long>(ramp.boxes.size()), pillars);
  for (const Box& b : ramp.boxes) {
    EXPECT_EQ(b.material, Material::kPillar);
    EXPECT_EQ(b.decal_count, 0);
  }
  EXPECT_TRUE(ramp.texts.empty());
  EXPECT_TRUE(ramp.floor_decals.empty());
  EXPECT_TRUE(ramp.box_decals.empty());
  EXPECT_EQ(ramp.lamps.size(), b1.lamps.size());
  EXPECT_EQ(ramp.floor_shade.size(), b1.floor_shade.size());
  // Rendered: lit like the level (the same lamps), with no paint.
  const geometry::Rig rig = testing::scaledRig(0.25);
  const auto rays = testing::raysOf(rig);
  LightingOptions light;
  light.noise_sigma = 0.0f;
  const geometry::Pose2 pose(g.aisle_x0 + 4.0, g.aisle_y[0] - 0.6, 0.0);
  const Renderer on_ramp(g, ramp, rig, rays, light);
  const Renderer on_b1(g, 0, rig, rays, light);
  const double ramp_luma = cv::mean(on_ramp.renderCamera(0, pose, 1))[1];
  const double level_luma = cv::mean(on_b1.renderCamera(0, pose, 1))[1];
  EXPECT_GT(ramp_luma, 0.7 * level_luma);
  EXPECT_LT(ramp_luma, 1.3 * level_luma);
}

class LevelChangeDrive : public ::testing::Test {
 protected:
  void SetUp() override {
    out_ = std::filesystem::temp_directory_path() /
           ("parkloc_level_change_" + std::to_string(::getpid()));
    std::filesystem::remove_all(out_);
  }
  void TearDown() override { std::filesystem::remove_all(out_); }
  std::filesystem::path out_;
};

TEST_F(LevelChangeDrive, WritesTheLevelPerFrameAndLabelsOfThatLevel) {
  Scenario s;
  s.name = "levels";
  s.seed = 5;
  s.frame_rate = 1.0;
  GarageSpec g = twoLevels(true);
  g.split = "val";
  g.drives = {downTheRamp(8.0, 2.0)};
  s.garages = {g};
  DatasetOptions options;
  options.out_dir = out_.string();
  writeDataset(s, options);
  const auto plans = planSequences(s);
  ASSERT_EQ(plans.size(), 1u);
  EXPECT_EQ(plans[0].name, "small_B1-B2_d0");
  const io::Sequence seq((out_ / "sequences" / plans[0].name).string());
  const auto& levels = seq.levelTruth();
  const auto& poses = seq.groundTruth();
  ASSERT_EQ(levels.size(), poses.size());
  ASSERT_GE(levels.size(), 7u);
  const auto meta = nlohmann::json::parse(seq.metaJson());
  EXPECT_EQ(meta.at("level"), "B1");
  EXPECT_EQ(meta.at("levels_driven"), nlohmann::json({"B1", "B2"}));
  const double ramp_start = meta.at("level_change").at("ramp_start_s");
  const double ramp_end = meta.at("level_change").at("ramp_end_s");
  EXPECT_NEAR(ramp_end - ramp_start, 2.0, 1e-9);
  int ramp_frames = 0, b2_frames = 0;
  for (size_t k = 0; k < levels.size(); ++k) {
    const double t = levels[k].timestamp;
    EXPECT_EQ(t, poses[k].timestamp);
    EXPECT_EQ(levels[k].level, t < ramp_end ? "B1" : "B2") << t;
    const bool on_ramp = t >= ramp_start && t < ramp_end;
    ramp_frames += on_ramp;
    b2_frames += levels[k].level == "B2";
    int instances = 0;
    for (const auto& cam : seq.cameras()) {
      const auto labels = seq.loadLabels(k, cam);
      ASSERT_TRUE(labels.has_value());
      for (const auto& inst : labels->instances) {
        ++instances;
        EXPECT_EQ(inst.landmark_id.rfind(levels[k].level + ":", 0), 0u)
            << inst.landmark_id << " at " << t;
      }
    }
    if (on_ramp) {
      EXPECT_EQ(instances, 0) << t;
    } else {
      EXPECT_GT(instances, 0) << t;
    }
    // The path runs on through the ramp: no jump between frames (at most 4 m/s).
    if (k > 0) {
      EXPECT_LT((poses[k].pose.translation() - poses[k - 1].pose.translation()).norm(),
                4.0 * (t - poses[k - 1].timestamp));
    }
  }
  EXPECT_EQ(ramp_frames, 2);
  EXPECT_GE(b2_frames, 3);
}

TEST_F(LevelChangeDrive, DrivesThatStayWriteOneLevel) {
  Scenario s = demoScenario();
  s.garages[0].slots_per_row = 9;
  DatasetOptions options;
  options.out_dir = out_.string();
  options.max_frames = 2;
  writeDataset(s, options);
  const io::Sequence seq((out_ / "sequences" / planSequences(s)[0].name).string());
  ASSERT_EQ(seq.levelTruth().size(), 2u);
  EXPECT_EQ(seq.levelTruth()[1].level, "B2");
  const auto meta = nlohmann::json::parse(seq.metaJson());
  EXPECT_EQ(meta.at("levels_driven"), nlohmann::json({"B2"}));
  EXPECT_FALSE(meta.contains("level_change"));
}

TEST_F(LevelChangeDrive, CodeBuiltScenarioWithABadTargetLevelIsRejected) {
  Scenario s;
  GarageSpec g = twoLevels(false);
  g.drives = {downTheRamp(8.0, 2.0)};
  g.drives[0].to_level = "B7";
  s.garages = {g};
  DatasetOptions options;
  options.out_dir = out_.string();
  EXPECT_THROW(writeDataset(s, options), InputError);
  g.drives[0].to_level = "B1";
  s.garages = {g};
  EXPECT_THROW(writeDataset(s, options), InputError);
}

}  // namespace
}  // namespace parkloc::sim
