// The map builder as a test: a short tour of a validation garage is rendered, read by the
// shipped PP-OCR models and built into a map with the default options (as `parkloc map build`
// does), and the map is compared with the garage's true one (as `parkloc eval map` does).
//
// Slow (rendering plus real OCR of every frame set, about a minute on two cores): labelled
// `slow` in CTest.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "config/config.h"
#include "eval/map_comparison.h"
#include "io/sequence.h"
#include "mapping/map_builder.h"
#include "ocr/ppocr/pp_ocr_spotter.h"
#include "sim/dataset_writer.h"
#include "sim/scenario.h"

namespace parkloc {
namespace {

namespace fs = std::filesystem;

constexpr int kFrames = 50;  // 5 s at 10 Hz: a few numbers on both sides, each in many frames

TEST(MapBuildDrive, BuildsTheMapOfAShortTourWithinCentimetres) {
  const fs::path dir =
      fs::temp_directory_path() / ("parkloc_map_build_drive_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  sim::DatasetOptions render;
  render.out_dir = dir.string();
  render.splits = {"val"};  // g08: a tour of B1
  render.max_sequences = 1;
  render.max_frames = kFrames;
  ASSERT_EQ(sim::writeDataset(sim::defaultScenario(), render).sequences, 1);
  const fs::path drive = fs::directory_iterator(dir / "sequences")->path();

  const config::Config defaults;
  ocr::PpOcrSpotter spotter(config::spotterOptions(defaults));
  const io::Sequence sensors(drive.string(), "", "", "", io::SequenceContents::kSensors);
  EXPECT_EQ(sensors.map().size(), 0u);  // the builder does not see the truth
  const mapping::MapBuild build = mapping::buildMap({&sensors}, &spotter, defaults.map_build);
  std::vector<map::Landmark> landmarks;
  for (const auto& l : build.landmarks) landmarks.push_back(l.toLandmark("B1"));

  const io::Sequence truth(drive.string());
  const eval::MapComparison c =
      eval::compareMaps(map::HdMap(landmarks), truth.map(), "B1", eval::legibleFrameSets(truth),
                        eval::MapComparisonOptions{});
  fs::remove_all(dir);
  ASSERT_TRUE(c.fit);
  EXPECT_GE(c.position_m.count, 3u);
  EXPECT_LT(c.position_m.rmse, 0.03);
  EXPECT_LT(c.position_m.max, 0.10);
  // Every legible number but one; the heading bound allows one number seen in few frame sets
  // from one side (132 here, decided by the numbering's sequence, 2.5 deg off).
  EXPECT_LT(c.abs_heading_deg.rmse, 1.5);
  EXPECT_LE(c.phantoms.size(), 1u);
  EXPECT_GE(c.completeness, 0.85);
  EXPECT_TRUE(build.estimation.converged) << build.estimation.message;
}

}  // namespace
}  // namespace parkloc
