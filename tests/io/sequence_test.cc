#include "io/sequence.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <opencv2/imgcodecs.hpp>

#include "common/error.h"
#include "geometry/rig.h"
#include "io/calibration_yaml.h"
#include "io/map_geojson.h"
#include "test_dir.h"

namespace parkloc::io {
namespace {

class SequenceTest : public testing::TempDirTest {
 protected:
  // Rig: front, rear, left, right. Images for front and left only; "roof" is not in the rig.
  void makeSequence() {
    saveCalibration(geometry::defaultRig(), path("calib.yaml"));
    map::Landmark l;
    l.id = l.text = "B1-101";
    l.level = "B1";
    l.width = 1.0;
    l.height = 0.5;
    saveMap(map::HdMap({l}), path("map.geojson"));
    const cv::Mat image(8, 12, CV_8UC3, cv::Scalar(10, 20, 30));
    std::filesystem::create_directories(dir_ / "images/front");
    std::filesystem::create_directories(dir_ / "images/left");
    std::filesystem::create_directories(dir_ / "images/roof");
    cv::imwrite(path("images/front/0.100000.png"), image);
    cv::imwrite(path("images/front/0.200000.png"), image);
    cv::imwrite(path("images/left/0.100000.png"), image);
    write("images/left/0.300000.jpg", "this is not a jpeg");
    write("images/left/0.400000.png", "");
    write("images/front/thumbnail.png", "x");
  }
};

TEST_F(SequenceTest, TimestampStemHasSixDecimals) {
  EXPECT_EQ(timestampStem(12.35), "12.350000");
  EXPECT_EQ(timestampStem(0.0), "0.000000");
}

TEST_F(SequenceTest, ListsFrameSetsAndWarnsAboutMissingAndUnknownFolders) {
  makeSequence();
  const Sequence seq(dir_.string());
  EXPECT_EQ(seq.rig().cameras.size(), 4u);
  EXPECT_EQ(seq.map().size(), 1u);
  EXPECT_EQ(seq.metaJson(), "{}");
  EXPECT_TRUE(seq.groundTruth().empty());
  EXPECT_EQ(seq.cameras(), (std::vector<std::string>{"front", "left"}));
  EXPECT_EQ(seq.timestamps(), (std::vector<double>{0.1, 0.2, 0.3, 0.4}));

  const auto& w = seq.warnings();
  auto has = [&](const std::string& text) {
    return std::find(w.begin(), w.end(), text) != w.end();
  };
  EXPECT_TRUE(has("camera 'rear': no images folder"));
  EXPECT_TRUE(has("camera 'right': no images folder"));
  EXPECT_TRUE(has("camera 'front': skipped thumbnail.png (name is not a timestamp)"));
  EXPECT_TRUE(has("images folder 'roof' is not a camera of the rig; ignored"));
  EXPECT_EQ(w.size(), 4u);

  EXPECT_EQ(seq.imagePath(0, "front"), path("images/front/0.100000.png"));
  EXPECT_EQ(seq.imagePath(2, "front"), "");
  EXPECT_EQ(seq.imagePath(0, "rear"), "");
}

TEST_F(SequenceTest, CorruptMissingAndEmptyImagesLoadEmptyWithAReason) {
  makeSequence();
  const Sequence seq(dir_.string());
  std::string why;
  const cv::Mat good = seq.loadImage(0, "left", &why);
  ASSERT_FALSE(good.empty());
  EXPECT_EQ(good.size(), cv::Size(12, 8));
  EXPECT_EQ(why, "");

  EXPECT_TRUE(seq.loadImage(2, "left", &why).empty());
  EXPECT_EQ(why, path("images/left/0.300000.jpg") + ": cannot decode the image");
  EXPECT_TRUE(seq.loadImage(3, "left", &why).empty());
  EXPECT_EQ(why, path("images/left/0.400000.png") + ": empty file");
  EXPECT_TRUE(seq.loadImage(1, "left", &why).empty());
  EXPECT_EQ(why, "camera 'left' has no image at 0.200000");
  EXPECT_TRUE(seq.loadImage(9, "left", &why).empty());
  EXPECT_EQ(why, "frame 9 out of range (4 frames)");
}

TEST_F(SequenceTest, LabelsAreOptional) {
  makeSequence();
  ImageLabels labels;
  labels.camera = "front";
  labels.timestamp = 0.1;
  labels.width = 12;
  labels.height = 8;
  std::filesystem::create_directories(dir_ / "labels/front");
  saveLabels(labels, path("labels/front/0.100000.json"));
  const Sequence seq(dir_.string());
  const auto loaded = seq.loadLabels(0, "front");
  ASSERT_TRUE(loaded.has_value());
  EXPECT_EQ(loaded->camera, "front");
  EXPECT_FALSE(seq.loadLabels(1, "front").has_value());
}

TEST_F(SequenceTest, LevelTruthIsOptionalAndMalformedOnesAreRejected) {
  makeSequence();
  EXPECT_TRUE(Sequence(dir_.string()).levelTruth().empty());
  write("levels.csv", "timestamp,level\n0.1,B1\n0.2,B2\n");
  const Sequence seq(dir_.string());
  ASSERT_EQ(seq.levelTruth().size(), 2u);
  EXPECT_EQ(levelAt(seq.levelTruth(), seq.timestamps()[1]), "B2");
  write("levels.csv", "timestamp;level\n0.1;B1\n");
  try {
    Sequence bad(dir_.string());
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "levels " + path("levels.csv") + ":1: expected the header 'timestamp,level'");
  }
}

TEST_F(SequenceTest, MissingCalibrationNamesThePath) {
  makeSequence();
  std::filesystem::remove(dir_ / "calib.yaml");
  try {
    Sequence seq(dir_.string());
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "sequence " + dir_.string() + ": calibration " + path("calib.yaml") + " not found");
  }
}

TEST_F(SequenceTest, MissingMapNamesThePath) {
  makeSequence();
  std::filesystem::remove(dir_ / "map.geojson");
  try {
    Sequence seq(dir_.string());
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "sequence " + dir_.string() + ": map " + path("map.geojson") + " not found");
  }
}

}  // namespace
}  // namespace parkloc::io
