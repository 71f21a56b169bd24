#include "eval/evaluation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>

#include "common/error.h"
#include "eval/dataset.h"
#include "io/calibration_yaml.h"
#include "io/map_geojson.h"
#include "io/odometry_csv.h"
#include "io/sequence.h"
#include "io/tum.h"
#include "ocr/text_spotter.h"

namespace parkloc::eval {
namespace {
namespace fs = std::filesystem;

// A tiny drive on a circle (radius 5 m, 1 m/s) with exact odometry, tiny blank images and
// no labels: enough for the runner's plumbing and the odometry-only variant.
std::string writeSequence(const std::string& root, const std::string& name) {
  const fs::path dir = fs::path(root) / "sequences" / name;
  fs::create_directories(dir);
  const geometry::Rig rig = geometry::defaultRig();
  io::saveCalibration(rig, (dir / "calib.yaml").string());
  map::Landmark l;
  l.id = "B1-001";
  l.text = "001";
  l.level = "B1";
  l.width = 0.8;
  l.height = 0.45;
  io::saveMap(map::HdMap({l}, "test"), (dir / "map.geojson").string());
  std::vector<io::StampedPose> poses;
  std::vector<OdometrySample> odometry;
  for (int i = 0; i <= 200; ++i) {
    const double t = i * 0.02;
    odometry.push_back({t, 1.0, 0.2});
  }
  const cv::Mat blank(8, 8, CV_8UC3, cv::Scalar(40, 40, 40));
  for (int i = 0; i < 20; ++i) {
    const double t = i * 0.2, a = 0.2 * t;
    poses.push_back({t, geometry::Pose2(5.0 * std::sin(a), 5.0 - 5.0 * std::cos(a), a).toRigid3()});
    for (const auto& camera : rig.cameras) {
      fs::create_directories(dir / "images" / camera.name);
      cv::imwrite((dir / "images" / camera.name / (io::timestampStem(t) + ".png")).string(), blank);
    }
  }
  io::saveTum(poses, (dir / "poses.tum").string());
  io::saveOdometry(odometry, (dir / "odometry.csv").string());
  std::ofstream(dir / "meta.json") << R"({"condition": "weak", "split": "test"})";
  return dir.string();
}

class EvaluationTest : public testing::Test {
 protected:
  void SetUp() override {
    // One folder per test process: ctest runs the tests of this fixture in parallel.
    root_ = testing::TempDir() + "/parkloc_eval_dataset_" +
            testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(root_);
    writeSequence(root_, "seq_a");
    std::ofstream(root_ + "/splits.json") << R"({"train": [], "test": ["seq_a"]})";
  }
  std::string root_;
};

TEST_F(EvaluationTest, SplitListsTheSequenceFolders) {
  const auto test = splitSequences(root_, "test");
  ASSERT_EQ(test.size(), 1u);
  EXPECT_EQ(fs::path(test[0]).filename(), "seq_a");
  EXPECT_TRUE(splitSequences(root_, "train").empty());
  // A sequence folder stands for itself.
  EXPECT_EQ(splitSequences(test[0], "test"), test);
}

TEST(Dataset, LevelFromMeta) {
  EXPECT_EQ(sequenceLevel(R"({"level": "B2", "levels": ["B1", "B2"]})"), "B2");
  EXPECT_EQ(sequenceLevel("{}"), "");
  EXPECT_EQ(sequenceLevel("not json"), "");
}

TEST_F(EvaluationTest, BadSplitsAreInputErrorsNamingTheProblem) {
  try {
    splitSequences(root_, "validation");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("validation"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("splits.json"), std::string::npos);
  }
  std::ofstream(root_ + "/splits.json") << R"({"test": ["missing_seq"]})";
  EXPECT_THROW(splitSequences(root_, "test"), InputError);
  EXPECT_THROW(splitSequences(root_ + "/nowhere", "test"), InputError);
}

TEST_F(EvaluationTest, OdometryOnlyOnExactOdometryTracksTheTruth) {
  EvaluationOptions options;
  options.oracle = false;
  size_t progress_calls = 0;
  options.progress = [&](const Progress& p) {
    ++progress_calls;
    EXPECT_LE(p.done, p.total);
  };
  const EvaluationReport r = evaluateSequences(splitSequences(root_, "test"), nullptr, options);
  EXPECT_EQ(progress_calls, 20u);
  // Without a spotter and the oracle, the tables still exist but the main variant is empty.
  const nlohmann::json j = resultsJson(r);
  const auto& t5 = j["tables"]["table5"]["rows"];
  ASSERT_EQ(t5.size(), 1u);
  EXPECT_EQ(t5[0][0], "odometry-only dead reckoning");
  EXPECT_LT(t5[0][1].get<double>(), 0.1);  // cm: exact odometry on an exact circle
}

TEST_F(EvaluationTest, WithoutASpotterTheOracleIsTheMainVariant) {
  EvaluationOptions options;
  options.odometry_only = false;
  const EvaluationReport r = evaluateSequences(splitSequences(root_, "test"), nullptr, options);
  EXPECT_EQ(r.main.key, "oracle");
  EXPECT_EQ(r.main.frames, 20u);
}

TEST_F(EvaluationTest, EachMapNoiseLevelIsAConfigurationAndARow) {
  EvaluationOptions options;
  options.odometry_only = false;
  const auto hasTable = [](const EvaluationReport& r, const std::string& key) {
    return std::any_of(r.tables.begin(), r.tables.end(),
                       [&](const Table& t) { return t.key == key; });
  };
  const EvaluationReport exact = evaluateSequences(splitSequences(root_, "test"), nullptr, options);
  EXPECT_FALSE(hasTable(exact, "map_noise"));
  EXPECT_EQ(exact.variants.size(), 1u);

  options.map_noise_levels = {0.0, 0.03, 0.10};
  const EvaluationReport r = evaluateSequences(splitSequences(root_, "test"), nullptr, options);
  ASSERT_EQ(r.variants.size(), 3u);
  EXPECT_EQ(r.variants[0].key, "oracle");
  EXPECT_EQ(r.variants[1].key, "oracle_map_noise_3cm");
  EXPECT_EQ(r.variants[2].key, "oracle_map_noise_10cm");
  EXPECT_EQ(r.main.key, "oracle");
  ASSERT_TRUE(hasTable(r, "map_noise"));
  const auto table = std::find_if(r.tables.begin(), r.tables.end(),
                                  [](const Table& t) { return t.key == "map_noise"; });
  ASSERT_EQ(table->rows.size(), 3u);
  EXPECT_EQ(table->rows[2][0].text, "10.0");
  // The drives smoothed from the fixes the filter fused (eval/drive_smoother.h): blank
  // images give no fix, so nothing to smooth.
  EXPECT_EQ(table->header[8], "Smoothed mean / p95 / max (cm)");
  for (const auto& row : table->rows) EXPECT_EQ(row[8].text, "-");
  // Trajectory plots of the exact and of each perturbed map.
  EXPECT_EQ(r.trajectories.size(), 3u);

  // Two draws of each perturbed level: a configuration each, a row each and one pooled.
  options.map_noise_seeds = {1, 2};
  const EvaluationReport two = evaluateSequences(splitSequences(root_, "test"), nullptr, options);
  ASSERT_EQ(two.variants.size(), 5u);
  EXPECT_EQ(two.variants[1].key, "oracle_map_noise_3cm_seed1");
  EXPECT_EQ(two.variants[4].key, "oracle_map_noise_10cm_seed2");
  const auto pooled = std::find_if(two.tables.begin(), two.tables.end(),
                                   [](const Table& t) { return t.key == "map_noise"; });
  ASSERT_NE(pooled, two.tables.end());
  ASSERT_EQ(pooled->rows.size(), 7u);  // exact; 3 cm: 1, 2, all; 10 cm: 1, 2, all
  EXPECT_EQ(pooled->rows[0][1].text, "-");
  EXPECT_EQ(pooled->rows[3][0].text, "3.0");
  EXPECT_EQ(pooled->rows[3][1].text, "all 2");
  EXPECT_EQ(pooled->rows[5][1].text, "2");
  // The pooled row holds both draws' frame sets.
  const auto frame_sets = [](const TableCell& c) {
    return std::stoi(c.text.substr(c.text.find('/') + 1));
  };
  EXPECT_EQ(frame_sets(pooled->rows[6][7]), 2 * frame_sets(pooled->rows[4][7]));
}

// Finds nothing; notes whether each full-frame request asked for second opinions.
class RequestRecordingSpotter : public ocr::TextSpotter {
 public:
  std::string name() const override { return "request-recording"; }
  std::vector<ocr::TextInstance> spot(const cv::Mat&, const ocr::SpotRequest& request) override {
    if (request.regions.empty()) (request.second_opinions ? with : without) += 1;
    return {};
  }
  int with = 0, without = 0;
};

TEST_F(EvaluationTest, ThePaperPipelinesSharedPassAsksForNoSecondOpinions) {
  EvaluationOptions options;
  options.parkloc = false;
  options.oracle = false;
  options.odometry_only = false;
  options.max_frames_per_sequence = 3;
  RequestRecordingSpotter spotter;
  const EvaluationReport r = evaluateSequences(splitSequences(root_, "test"), &spotter, options);
  EXPECT_EQ(spotter.without, 12);  // 3 frame sets of 4 cameras, spotted once for 8 variants
  EXPECT_EQ(spotter.with, 0);
  const bool noted = std::any_of(r.notes.begin(), r.notes.end(), [](const std::string& n) {
    return n.find("without second opinions") != std::string::npos;
  });
  EXPECT_TRUE(noted);
}

}  // namespace
}  // namespace parkloc::eval
