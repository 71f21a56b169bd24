// The embedding facade (include/parkloc/parkloc.h) on bad files and on a short rendered drive
// read with the shipped models, through nothing but its own interface.
#include "parkloc/parkloc.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "io/sequence.h"
#include "sim/dataset_writer.h"
#include "sim/scenario.h"

namespace parkloc {
namespace {

namespace fs = std::filesystem;

const std::string kData = std::string(PARKLOC_SOURCE_DIR) + "/data";
const std::string kCalib = kData + "/rig/default_rig.yaml";
const std::string kMap = kData + "/maps/example_garage.geojson";

LocalizerSettings settingsFor(const std::string& calibration, const std::string& map) {
  LocalizerSettings settings;
  settings.calibration_file = calibration;
  settings.map_file = map;
  return settings;
}

TEST(LocalizerCreate, AMissingCalibrationIsOneLineNamingTheFile) {
  const auto made = Localizer::create(settingsFor("/nonexistent/calib.yaml", kMap));
  EXPECT_FALSE(made.localizer.has_value());
  EXPECT_NE(made.error.find("/nonexistent/calib.yaml"), std::string::npos) << made.error;
  EXPECT_EQ(made.error.find('\n'), std::string::npos) << made.error;
}

TEST(LocalizerCreate, AMapThatIsNotGeoJsonIsRejected) {
  const auto made = Localizer::create(settingsFor(kCalib, kCalib));
  EXPECT_FALSE(made.localizer.has_value());
  EXPECT_NE(made.error.find("malformed JSON"), std::string::npos) << made.error;
}

TEST(LocalizerCreate, AnEmptyCalibrationPathIsRejected) {
  const auto made = Localizer::create(settingsFor("", kMap));
  EXPECT_FALSE(made.localizer.has_value());
  EXPECT_NE(made.error.find("calibration"), std::string::npos) << made.error;
}

TEST(LocalizerCreate, AModelFolderWithoutModelsIsRejected) {
  LocalizerSettings settings = settingsFor(kCalib, kMap);
  settings.models_dir = "/nonexistent/models";
  const auto made = Localizer::create(settings);
  EXPECT_FALSE(made.localizer.has_value());
  EXPECT_NE(made.error.find("/nonexistent/models"), std::string::npos) << made.error;
}

TEST(LocalizerCreate, AMisspeltConfigurationKeyIsRejected) {
  LocalizerSettings settings = settingsFor(kCalib, kMap);
  settings.config_file = std::string(PARKLOC_SOURCE_DIR) + "/tests/data/config/unknown_key.yaml";
  const auto made = Localizer::create(settings);
  EXPECT_FALSE(made.localizer.has_value());
  EXPECT_NE(made.error.find("unknown option"), std::string::npos) << made.error;
}

TEST(LocalizerCreate, ALevelHintTheMapDoesNotHaveIsRejected) {
  LocalizerSettings settings = settingsFor(kCalib, kMap);
  settings.models_dir = PARKLOC_MODEL_DIR;
  settings.level = "B9";
  const auto made = Localizer::create(settings);
  EXPECT_FALSE(made.localizer.has_value());
  EXPECT_NE(made.error.find("\"B9\" is not a level of the map"), std::string::npos) << made.error;
}

TEST(LocalizerCreate, TheCalibrationNamesTheCamerasAndTheModelsAreTheBuilds) {
  LocalizerSettings settings = settingsFor(kCalib, kMap);
  settings.models_dir = PARKLOC_MODEL_DIR;
  const auto made = Localizer::create(settings);
  ASSERT_TRUE(made.localizer.has_value()) << made.error;
  EXPECT_EQ(made.localizer->cameras(),
            (std::vector<std::string>{"front", "rear", "left", "right"}));  // calibration order
  EXPECT_EQ(made.localizer->modelsDir(), PARKLOC_MODEL_DIR);
}

TEST(Localizer, AnImageOfACameraNotInTheCalibrationIsReportedNotFatal) {
  LocalizerSettings settings = settingsFor(kCalib, kMap);
  settings.models_dir = PARKLOC_MODEL_DIR;
  auto made = Localizer::create(settings);
  ASSERT_TRUE(made.localizer.has_value()) << made.error;
  const cv::Mat dark(800, 1280, CV_8UC3, cv::Scalar(20, 20, 20));  // the default rig's size
  EXPECT_TRUE(made.localizer->addImage("roof", 1.0, dark).empty());
  std::vector<PoseEstimate> estimates;
  for (const std::string& camera : made.localizer->cameras())
    for (auto& e : made.localizer->addImage(camera, 1.0, dark)) estimates.push_back(std::move(e));
  ASSERT_EQ(estimates.size(), 1u);
  EXPECT_FALSE(estimates[0].has_pose);
  EXPECT_EQ(estimates[0].status, TrackingStatus::kNoFix);
  ASSERT_FALSE(estimates[0].warnings.empty());
  EXPECT_NE(estimates[0].warnings[0].find("'roof'"), std::string::npos);
}

// The drive's true position at a capture time (poses.tum holds every one).
Eigen::Vector3d truthAt(const io::Sequence& s, double t) {
  for (const auto& p : s.groundTruth())
    if (std::abs(p.timestamp - t) < 1e-6) return p.pose.translation();
  ADD_FAILURE() << "no ground truth at " << t;
  return Eigen::Vector3d::Constant(1e9);
}

// One drive of the test garage, rendered once for the suite.
class LocalizerDrive : public ::testing::Test {
 protected:
  static constexpr int kFrames = 12;  // the first fix comes within a few frame sets

  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("parkloc_localizer_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    sim::DatasetOptions render;
    render.out_dir = dir_.string();
    render.splits = {"test"};
    render.max_sequences = 1;
    render.max_frames = kFrames;
    sim::writeDataset(sim::defaultScenario(), render);
    sequence_ = new io::Sequence(fs::directory_iterator(dir_ / "sequences")->path().string());
  }
  static void TearDownTestSuite() {
    delete sequence_;
    std::error_code ignored;
    fs::remove_all(dir_, ignored);
  }

  static Localizer make(const std::string& config_file = "") {
    LocalizerSettings settings = settingsFor((fs::path(sequence_->dir()) / "calib.yaml").string(),
                                             (fs::path(sequence_->dir()) / "map.geojson").string());
    settings.models_dir = PARKLOC_MODEL_DIR;
    settings.config_file = config_file;
    auto made = Localizer::create(settings);
    if (!made.localizer) throw std::runtime_error(made.error);
    return std::move(*made.localizer);
  }

  // The drive's odometry and images fed as they arrive, camera by camera in capture order;
  // the estimates the localizer returned meanwhile.
  static std::vector<PoseEstimate> feed(Localizer& localizer) {
    const auto& s = *sequence_;
    size_t odometry = 0;
    std::vector<PoseEstimate> estimates;
    for (size_t i = 0; i < s.timestamps().size(); ++i) {
      for (const std::string& camera : s.cameras()) {
        const double t = *s.captureTime(i, camera);
        for (; odometry < s.odometry().size() && s.odometry()[odometry].timestamp <= t; ++odometry)
          localizer.addOdometry(s.odometry()[odometry].timestamp, s.odometry()[odometry].speed,
                                s.odometry()[odometry].yaw_rate);
        for (auto& e : localizer.addImage(camera, t, s.loadImage(i, camera)))
          estimates.push_back(std::move(e));
      }
    }
    return estimates;
  }

  static inline fs::path dir_;
  static inline io::Sequence* sequence_ = nullptr;
};

TEST_F(LocalizerDrive, ImagesAndOdometryAsTheyArriveGiveThePoseOfEachFrameSet) {
  Localizer localizer = make();
  const auto& s = *sequence_;
  const std::vector<PoseEstimate> estimates = feed(localizer);
  EXPECT_FALSE(localizer.flush().has_value());  // every set held all four cameras
  ASSERT_EQ(estimates.size(), s.timestamps().size());

  int posed = 0;
  for (size_t i = 0; i < estimates.size(); ++i) {
    const PoseEstimate& e = estimates[i];
    EXPECT_DOUBLE_EQ(e.timestamp, s.timestamps()[i]);
    EXPECT_EQ(e.cameras.size(), 4u);
    if (!e.has_pose) {
      EXPECT_EQ(e.status, TrackingStatus::kNoFix);
      continue;
    }
    ++posed;
    EXPECT_NE(e.status, TrackingStatus::kNoFix);
    const Eigen::Vector3d truth = truthAt(s, e.timestamp);
    EXPECT_LT(std::hypot(e.x - truth.x(), e.y - truth.y()), 0.2) << "frame set " << i;
    EXPECT_GT(e.covariance[0], 0.0);  // x variance
    EXPECT_GT(e.covariance[8], 0.0);  // yaw variance
    EXPECT_FALSE(e.level.empty());
  }
  EXPECT_GE(posed, kFrames / 2) << "the first fix came late or the track was lost";
}

TEST_F(LocalizerDrive, TheWorkersTheConfigurationAsksForSpotBesideTheFrameSets) {
  // The full frames and the reads on worker threads with spotters of their own, their texts
  // fused a frame set after their images (waiting for the workers: the same poses whatever
  // the machine's load). The first fix comes one frame set later than inside the frame set.
  Localizer localizer =
      make(std::string(PARKLOC_SOURCE_DIR) + "/tests/data/config/workers_waiting.yaml");
  const auto& s = *sequence_;
  int posed = 0;
  for (const PoseEstimate& e : feed(localizer)) {
    if (!e.has_pose) continue;
    ++posed;
    const Eigen::Vector3d truth = truthAt(s, e.timestamp);
    EXPECT_LT(std::hypot(e.x - truth.x(), e.y - truth.y()), 0.2) << "at " << e.timestamp;
  }
  EXPECT_GE(posed, kFrames / 2 - 1) << "the workers' texts were not fused";
}

TEST(LocalizerCreate, TheShippedRealtimeOverlayIsAValidConfiguration) {
  const std::string rig = std::string(PARKLOC_SOURCE_DIR) + "/data/rig/default_rig.yaml";
  LocalizerSettings settings;
  settings.calibration_file = rig;
  settings.map_file = std::string(PARKLOC_SOURCE_DIR) + "/data/maps/example_garage.geojson";
  settings.models_dir = PARKLOC_MODEL_DIR;
  settings.config_file = std::string(PARKLOC_SOURCE_DIR) + "/data/config/realtime.yaml";
  const auto made = Localizer::create(settings);
  EXPECT_TRUE(made.localizer.has_value()) << made.error;
}

}  // namespace
}  // namespace parkloc
