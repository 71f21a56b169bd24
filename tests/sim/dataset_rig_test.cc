#include "sim/dataset_rig.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "common/error.h"
#include "io/calibration_yaml.h"
#include "io/sequence.h"
#include "sim/dataset_writer.h"

namespace parkloc::sim {
namespace {

namespace fs = std::filesystem;

// A rig unlike the default one: a small fisheye camera and a pinhole one, yawed and mounted
// at other heights, with images of other sizes.
geometry::Rig twoCameraRig() {
  geometry::Rig rig = geometry::defaultRig();
  rig.cameras.resize(2);
  auto& fisheye = rig.cameras[0].model;
  fisheye.width = 320;
  fisheye.height = 208;
  fisheye.fx = fisheye.fy = 95.0;
  fisheye.cx = 159.5;
  fisheye.cy = 103.5;
  rig.cameras[0].vehicle_from_camera.translation().z() = 0.9;
  geometry::RigCamera& pinhole = rig.cameras[1];
  pinhole.name = "rear_pinhole";
  pinhole.model.type = geometry::CameraModelType::kPinhole;
  pinhole.model.width = 256;
  pinhole.model.height = 144;
  pinhole.model.fx = pinhole.model.fy = 120.0;
  pinhole.model.cx = 127.5;
  pinhole.model.cy = 71.5;
  pinhole.model.distortion = {-0.05, 0.01, 0.0, 0.0};
  pinhole.vehicle_from_camera.linear() =
      geometry::vehicleFromCameraRotation(M_PI - 0.25, 40.0 * M_PI / 180.0);
  return rig;
}

Scenario smallScenario() {
  Scenario scenario = demoScenario();
  scenario.garages[0].slots_per_row = 9;
  return scenario;
}

TEST(DatasetRig, TheGivenRigIsRenderedAtItsImageSizesAndCameraCount) {
  const fs::path root = fs::temp_directory_path() / ("parkloc_rig_" + std::to_string(::getpid()));
  fs::remove_all(root);
  DatasetOptions options;
  options.out_dir = root.string();
  options.max_frames = 1;
  options.rig = twoCameraRig();
  const DatasetStats stats = writeDataset(smallScenario(), options);
  EXPECT_EQ(stats.images, 2);
  const fs::path dir = root / "sequences" / planSequences(smallScenario())[0].name;
  const geometry::Rig written = io::loadCalibration((dir / "calib.yaml").string());
  ASSERT_EQ(written.cameras.size(), 2u);
  for (const auto& camera : options.rig->cameras) {
    const auto* w = written.find(camera.name);
    ASSERT_NE(w, nullptr) << camera.name;
    EXPECT_EQ(w->model.type, camera.model.type);
    size_t images = 0;
    for (const auto& e : fs::directory_iterator(dir / "images" / camera.name)) {
      const cv::Mat image = cv::imread(e.path().string());
      EXPECT_EQ(image.cols, camera.model.width) << e.path();
      EXPECT_EQ(image.rows, camera.model.height) << e.path();
      // Rendered, not blank: the floor and the garage show.
      EXPECT_GT(cv::mean(image)[1], 5.0) << e.path();
      ++images;
    }
    EXPECT_EQ(images, 1u) << camera.name;
  }
  EXPECT_FALSE(fs::exists(dir / "images" / "left"));
  fs::remove_all(root);
}

TEST(DatasetRig, TheOptionsRigWinsOverTheScenariosAndTheDefaultIsTheDefaultRig) {
  Scenario scenario = smallScenario();
  EXPECT_EQ(datasetRig(scenario, {}).cameras.size(), geometry::defaultRig().cameras.size());
  scenario.rig = PARKLOC_SOURCE_DIR "/data/rig/second_rig.yaml";
  const geometry::Rig second = datasetRig(scenario, {});
  ASSERT_EQ(second.cameras.size(), 4u);
  EXPECT_EQ(second.cameras[0].model.width, 1920);
  EXPECT_EQ(second.cameras[0].model.height, 1080);
  DatasetOptions options;
  options.rig = twoCameraRig();
  EXPECT_EQ(datasetRig(scenario, options).cameras.size(), 2u);
}

TEST(DatasetRig, ARigOfOneOrSevenCamerasIsAnInputError) {
  DatasetOptions options;
  options.rig = geometry::defaultRig();
  options.rig->cameras.resize(1);
  EXPECT_THROW(datasetRig(smallScenario(), options), InputError);
  options.rig = geometry::defaultRig();
  for (int k = 0; k < 3; ++k) {
    options.rig->cameras.push_back(options.rig->cameras[k]);
    options.rig->cameras.back().name += "_2";
  }
  EXPECT_EQ(options.rig->cameras.size(), 7u);
  EXPECT_THROW(datasetRig(smallScenario(), options), InputError);
  options.rig->cameras.resize(6);
  EXPECT_NO_THROW(datasetRig(smallScenario(), options));
}

}  // namespace
}  // namespace parkloc::sim
