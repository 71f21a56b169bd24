#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "common/error.h"
#include "io/sequence.h"
#include "sim/dataset_writer.h"
#include "sim/scenario.h"

namespace parkloc::sim {
namespace {

TEST(DatasetWriter, WritesALoadableSequence) {
  namespace fs = std::filesystem;
  const fs::path out =
      fs::temp_directory_path() / ("parkloc_sim_writer_" + std::to_string(::getpid()));
  fs::remove_all(out);
  Scenario s = demoScenario();
  s.garages[0].slots_per_row = 9;
  DatasetOptions options;
  options.out_dir = out.string();
  options.max_frames = 2;
  size_t last_done = 0;
  const DatasetStats stats = writeDataset(s, options, [&](size_t done, size_t total) {
    EXPECT_LE(done, total);
    last_done = done;
  });
  EXPECT_EQ(stats.sequences, 1);
  EXPECT_EQ(stats.frame_sets, 2);
  EXPECT_EQ(stats.images, 8);
  EXPECT_EQ(last_done, 2u);
  const auto plans = planSequences(s);
  ASSERT_EQ(plans.size(), 1u);
  const io::Sequence seq((out / "sequences" / plans[0].name).string());
  EXPECT_EQ(seq.timestamps().size(), 2u);
  EXPECT_EQ(seq.cameras().size(), 4u);
  EXPECT_EQ(seq.groundTruth().size(), 2u);
  EXPECT_GT(seq.odometry().size(), 2u);
  EXPECT_GT(seq.map().size(), 10u);
  int instances = 0;
  for (const auto& cam : seq.cameras()) {
    const auto labels = seq.loadLabels(1, cam);
    ASSERT_TRUE(labels.has_value());
    instances += static_cast<int>(labels->instances.size());
    EXPECT_FALSE(seq.loadImage(1, cam).empty());
    EXPECT_TRUE(fs::exists(out / "sequences" / plans[0].name / "labels" / cam /
                           (io::timestampStem(0.1) + ".txt")));
  }
  EXPECT_GT(instances, 0);
  const auto meta = nlohmann::json::parse(seq.metaJson());
  EXPECT_EQ(meta.at("split"), "test");
  EXPECT_EQ(meta.at("condition"), "bright");
  std::ifstream splits(out / "splits.json");
  const auto sj = nlohmann::json::parse(splits);
  EXPECT_EQ(sj.at("test").size(), 1u);
  fs::remove_all(out);
}

// The demo garage twice: "ga" in the train split, "gb" in the test split.
Scenario twoGarages() {
  Scenario s = demoScenario();
  s.garages[0].slots_per_row = 9;
  s.garages.push_back(s.garages[0]);
  s.garages[0].split = "train";
  s.garages[0].name = "ga";
  s.garages[1].split = "test";
  s.garages[1].name = "gb";
  return s;
}

TEST(DatasetWriter, OneSplitHasTheSameGaragesAsTheWholeDataset) {
  namespace fs = std::filesystem;
  const fs::path base =
      fs::temp_directory_path() / ("parkloc_sim_split_" + std::to_string(::getpid()));
  fs::remove_all(base);
  const Scenario s = twoGarages();
  auto metaOf = [](const fs::path& dir) {
    std::ifstream in(dir / "meta.json");
    return nlohmann::json::parse(in);
  };
  DatasetOptions options;
  options.max_frames = 1;
  options.out_dir = (base / "all").string();
  EXPECT_EQ(writeDataset(s, options).sequences, 2);
  options.out_dir = (base / "test").string();
  options.splits = {"test"};
  EXPECT_EQ(writeDataset(s, options).sequences, 1);
  const std::string name = planSequences(s)[1].name;
  ASSERT_TRUE(fs::exists(base / "test" / "sequences" / name));
  EXPECT_FALSE(fs::exists(base / "test" / "sequences" / planSequences(s)[0].name));
  EXPECT_EQ(metaOf(base / "test" / "sequences" / name).at("garage_seed"),
            metaOf(base / "all" / "sequences" / name).at("garage_seed"));
  options.splits = {"tset"};
  EXPECT_THROW(writeDataset(s, options), InputError);
  fs::remove_all(base);
}

TEST(DatasetWriter, WritingOneSplitKeepsTheOthersListed) {
  namespace fs = std::filesystem;
  const fs::path out =
      fs::temp_directory_path() / ("parkloc_sim_splits_" + std::to_string(::getpid()));
  fs::remove_all(out);
  const Scenario s = twoGarages();
  const auto plans = planSequences(s);
  auto splitsOf = [&] {
    std::ifstream in(out / "splits.json");
    return nlohmann::json::parse(in);
  };
  DatasetOptions options;
  options.max_frames = 1;
  options.out_dir = out.string();
  options.splits = {"test"};
  writeDataset(s, options);
  EXPECT_EQ(splitsOf().at("train").size(), 0u);
  options.splits = {"train"};
  writeDataset(s, options);
  EXPECT_EQ(splitsOf().at("train"), nlohmann::json::array({plans[0].name}));
  EXPECT_EQ(splitsOf().at("test"), nlohmann::json::array({plans[1].name}));  // kept
  // A listed sequence whose folder is gone is not kept.
  fs::remove_all(out / "sequences" / plans[0].name);
  options.splits = {"test"};
  writeDataset(s, options);
  EXPECT_EQ(splitsOf().at("train").size(), 0u);
  EXPECT_EQ(splitsOf().at("test"), nlohmann::json::array({plans[1].name}));
  fs::remove_all(out);
}

// Writes two frame sets of the demo drive and returns, per file of the first camera, the image
// bytes and the number of parking numbers labelled legible.
struct Written {
  std::vector<std::string> images;
  int legible_numbers = 0;
};
Written writeDemo(const Scenario& s, const std::string& tag) {
  namespace fs = std::filesystem;
  const fs::path out = fs::temp_directory_path() /
                       ("parkloc_sim_legibility_" + tag + "_" + std::to_string(::getpid()));
  fs::remove_all(out);
  DatasetOptions options;
  options.out_dir = out.string();
  options.max_frames = 2;
  writeDataset(s, options);
  const io::Sequence seq((out / "sequences" / planSequences(s)[0].name).string());
  Written w;
  for (size_t k = 0; k < seq.timestamps().size(); ++k)
    for (const auto& cam : seq.cameras()) {
      std::ifstream f(seq.imagePath(k, cam), std::ios::binary);
      w.images.emplace_back(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
      const auto labels = seq.loadLabels(k, cam);
      if (!labels) continue;
      for (const auto& inst : labels->instances)
        if (inst.legible && inst.cls == map::TextClass::kParkingNumber) ++w.legible_numbers;
    }
  fs::remove_all(out);
  return w;
}

TEST(DatasetWriter, LegibilityOnTheImageCountsTheCodecsBlocks) {
  Scenario s = demoScenario();
  s.garages[0].slots_per_row = 9;
  s.garages[0].drives[0].appearance.compression = 1.0f;  // JPEG at about quality 15
  const Written on_scene = writeDemo(s, "scene");
  s.legibility_on_image = true;
  const Written on_image = writeDemo(s, "image");
  // The same images, judged differently: the codec's blocks leave fewer numbers legible.
  EXPECT_EQ(on_scene.images, on_image.images);
  EXPECT_GT(on_scene.legible_numbers, 4);
  EXPECT_LT(on_image.legible_numbers, on_scene.legible_numbers);
}

TEST(DatasetWriter, LegibilityOnACleanImageKeepsMostNumbers) {
  Scenario s = demoScenario();
  s.garages[0].slots_per_row = 9;
  const Written on_scene = writeDemo(s, "clean_scene");
  s.legibility_on_image = true;
  const Written on_image = writeDemo(s, "clean_image");
  EXPECT_EQ(on_scene.images, on_image.images);
  EXPECT_GE(on_image.legible_numbers, 0.8 * on_scene.legible_numbers);
  EXPECT_LE(on_image.legible_numbers, on_scene.legible_numbers);
}

TEST(DatasetWriter, RejectsBadOptions) {
  DatasetOptions options;
  EXPECT_THROW(writeDataset(demoScenario(), options), InputError);
  options.out_dir = "/tmp/x";
  options.jobs = 0;
  EXPECT_THROW(writeDataset(demoScenario(), options), InputError);
}

TEST(DatasetWriter, CamerasWithDelaysAreRenderedAtTheirCaptureTimes) {
  // Rear 30 ms and right 20 ms after the trigger, up to 5 ms jitter: each image is named by its
  // capture time, its labels are at the vehicle's pose then, poses.tum holds every capture time,
  // and the reader forms one frame set per trigger with each image's own time.
  namespace fs = std::filesystem;
  const fs::path out =
      fs::temp_directory_path() / ("parkloc_sim_delays_" + std::to_string(::getpid()));
  fs::remove_all(out);
  Scenario s = demoScenario();
  s.garages[0].slots_per_row = 9;
  s.garages[0].drives[0].camera_delay_s = {{"rear", 0.030}, {"right", 0.020}};
  s.garages[0].drives[0].camera_jitter_s = 0.005;
  DatasetOptions options;
  options.out_dir = out.string();
  options.max_frames = 2;
  writeDataset(s, options);
  const io::Sequence seq((out / "sequences" / planSequences(s)[0].name).string());
  ASSERT_EQ(seq.timestamps().size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    const double trigger = 0.1 * static_cast<double>(i);
    for (const auto& [camera, delay] : std::map<std::string, double>{
             {"front", 0.0}, {"left", 0.0}, {"rear", 0.030}, {"right", 0.020}}) {
      const std::optional<double> t = seq.captureTime(i, camera);
      ASSERT_TRUE(t) << camera;
      EXPECT_GE(*t, trigger + delay - 1e-6) << camera;
      EXPECT_LE(*t, trigger + delay + 0.005 + 1e-6) << camera;
      const auto labels = seq.loadLabels(i, camera);
      ASSERT_TRUE(labels) << camera;
      EXPECT_NEAR(labels->timestamp, *t, 1e-6);
    }
    EXPECT_NE(*seq.captureTime(i, "rear"), *seq.captureTime(i, "front"));
  }
  // The truth at every capture time, in time order.
  EXPECT_GE(seq.groundTruth().size(), 6u);
  for (size_t k = 1; k < seq.groundTruth().size(); ++k)
    EXPECT_GT(seq.groundTruth()[k].timestamp, seq.groundTruth()[k - 1].timestamp);
  fs::remove_all(out);
}

TEST(DatasetWriter, CameraDelaysMustStayWithinAFrameSet) {
  const std::string yaml = R"(
frame_rate: 10
garages:
  - {name: g, levels: [B1], drives: [{route: tour, camera_delay_s: {rear: DELAY}, camera_jitter_s: 0.005}]}
)";
  const auto with = [&](const std::string& delay) {
    std::string text = yaml;
    text.replace(text.find("DELAY"), 5, delay);
    return parseScenario(text, "s.yaml");
  };
  EXPECT_EQ(with("0.03").garages[0].drives[0].camera_delay_s.at("rear"), 0.03);
  try {
    with("0.04");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("s.yaml garage 0 drive 0: camera delays and jitter span "
                                         "0.045 s, more than 0.4 frame periods (0.040 s)"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(with("-0.01"), InputError);
  EXPECT_THROW(with("fast"), InputError);
}

}  // namespace
}  // namespace parkloc::sim
