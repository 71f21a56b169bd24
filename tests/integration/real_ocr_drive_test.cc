// The headline accuracy as a test: one drive of the test garage is rendered, its frame sets
// go through the localization pipeline with the shipped PP-OCR spotter (the models and
// classifiers `parkloc run` uses by default) and default pipeline options (no level given: the
// pipeline estimates it, as `parkloc run` does), and the estimated poses are compared with the
// drive's ground truth.
//
// Slow (rendering plus real OCR, 10-60 s on two cores): labelled `slow` in CTest so the
// sanitizer run (`make test-asan`, -LE slow) skips it; `make test` runs it.
#include <gtest/gtest.h>
#include <unistd.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "config/config.h"
#include "geometry/pose.h"
#include "io/sequence.h"
#include "localize/pipeline.h"
#include "ocr/ppocr/pp_ocr_spotter.h"
#include "run/sequence_runner.h"
#include "sim/dataset_writer.h"
#include "sim/scenario.h"

namespace parkloc {
namespace {

namespace fs = std::filesystem;

// Frame sets of the drive (10 Hz): long enough for the search, the first fix and several
// turns of the tracked phase (full-frame sweeps and map-guided reads).
constexpr int kFrames = 80;

class TempDir {
 public:
  TempDir()
      : path_(fs::temp_directory_path() /
              ("parkloc_real_ocr_drive_" + std::to_string(::getpid()))) {
    fs::remove_all(path_);
  }
  ~TempDir() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  std::string str() const { return path_.string(); }

 private:
  fs::path path_;
};

TEST(RealOcrDrive, LocalizesTheTestDriveWithinTheHeadlineBounds) {
  const auto started = std::chrono::steady_clock::now();
  const TempDir dir;
  sim::DatasetOptions render;
  render.out_dir = dir.str();
  render.splits = {"test"};  // a garage whose numbering and fonts the tuned models never saw
  render.max_sequences = 1;
  render.max_frames = kFrames;
  const sim::DatasetStats stats = sim::writeDataset(sim::defaultScenario(), render);
  ASSERT_EQ(stats.sequences, 1);
  ASSERT_EQ(stats.frame_sets, kFrames);

  const fs::path sequences = fs::path(dir.str()) / "sequences";
  ASSERT_TRUE(fs::is_directory(sequences));
  const fs::path drive = fs::directory_iterator(sequences)->path();
  const io::Sequence sequence(drive.string());

  const config::Config defaults;  // data/config/default.yaml, as `parkloc run` loads it
  ocr::PpOcrSpotter spotter(config::spotterOptions(defaults));
  // The level is the pipeline's to estimate: the parking numbers repeat on every level of
  // this garage, and only level signs and level-unique texts tell them apart.
  localize::Pipeline pipeline(sequence.rig(), sequence.map(), defaults.pipeline, &spotter);

  std::vector<double> errors_m;
  size_t after_first_fix = 0, posed_after_first_fix = 0;
  size_t first_fix = kFrames;  // index of the first frame set with a pose
  // The level, scored against the drive's (the test may read the simulator's meta.json).
  const std::string true_level =
      nlohmann::json::parse(sequence.metaJson()).at("level").get<std::string>();
  size_t decided = 0, decided_right = 0;
  double previous = -std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < sequence.timestamps().size(); ++i) {
    localize::FrameInput input;
    input.timestamp = sequence.timestamps()[i];
    input.odometry = run::odometryBetween(sequence.odometry(), previous, input.timestamp);
    previous = input.timestamp;
    for (const std::string& camera : sequence.cameras())
      input.cameras.push_back(
          {camera, sequence.loadImage(i, camera), std::nullopt, sequence.captureTime(i, camera)});

    const localize::FrameResult result = pipeline.process(input);
    if (result.level_decided) {
      ++decided;
      if (result.level == true_level) ++decided_right;
    }
    if (result.has_pose || after_first_fix > 0) ++after_first_fix;
    if (!result.has_pose) continue;
    first_fix = std::min(first_fix, i);
    ++posed_after_first_fix;
    const std::optional<geometry::Pose2> truth =
        run::truthAt(sequence.groundTruth(), input.timestamp);
    ASSERT_TRUE(truth) << "no ground truth at t = " << input.timestamp;
    errors_m.push_back((result.pose.translation() - truth->translation()).norm());
  }

  ASSERT_FALSE(errors_m.empty()) << "no pose in " << kFrames << " frame sets";
  double mean_m = 0.0;
  for (double e : errors_m) mean_m += e;
  mean_m /= static_cast<double>(errors_m.size());
  const double max_m = *std::max_element(errors_m.begin(), errors_m.end());
  const double posed_share =
      static_cast<double>(posed_after_first_fix) / static_cast<double>(after_first_fix);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  RecordProperty("mean_error_cm", std::to_string(100.0 * mean_m));
  RecordProperty("max_error_cm", std::to_string(100.0 * max_m));
  std::cout << "drive " << drive.filename().string() << ": " << errors_m.size() << " / " << kFrames
            << " frame sets with a pose, first fix at frame set " << first_fix
            << "; position error mean " << 100.0 * mean_m << " cm, max " << 100.0 * max_m
            << " cm; pose on " << 100.0 * posed_share
            << " % of the frame sets from the first fix on; level decided on " << decided
            << ", right on " << decided_right << "; " << seconds << " s\n";

  // Measured on this drive (g10_B1_d0, bright), no level given: first fix at frame set 3,
  // 1.1 cm mean and 4.2 cm max position error, a pose on every frame set from the first fix on,
  // the level decided on 64 of the 80 frame sets and right on all of them. The bounds leave room for OCR that reads a little differently on
  // another machine (thread count, ONNX Runtime version) while still failing on a real loss:
  // the mean bound is over twice the test split's headline figure (1.3 cm, docs/RESULTS.md);
  // the max bound is far below the half metre no frame may be off by, so one wrong
  // association that moves the pose by decimetres fails the test; the track may drop out on
  // a few frame sets but not lose the vehicle; the search must find the first fix within 2 s.
  EXPECT_LT(mean_m, 0.03);
  EXPECT_LT(max_m, 0.20);
  EXPECT_GE(posed_share, 0.95);
  EXPECT_LE(first_fix, 20u);
  // The level: decided on most of the drive (its signs and level-unique pillar labels are in
  // view within seconds) and never wrong where decided.
  EXPECT_GE(decided, static_cast<size_t>(kFrames) / 2);
  EXPECT_EQ(decided_right, decided);
}

}  // namespace
}  // namespace parkloc
