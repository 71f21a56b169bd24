#include "io/labels.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "common/error.h"
#include "test_dir.h"

namespace parkloc::io {
namespace {

class LabelsTest : public testing::TempDirTest {};

ImageLabels sampleLabels() {
  ImageLabels labels;
  labels.camera = "front";
  labels.timestamp = 12.35;
  labels.width = 1280;
  labels.height = 800;
  LabelInstance number;
  number.polygon = {Eigen::Vector2d(100.4, 200.6), Eigen::Vector2d(180.5, 201.0),
                    Eigen::Vector2d(179.2, 240.49), Eigen::Vector2d(99.0, 239.0)};
  number.text = "B2-117";
  number.landmark_id = "B2-117";
  number.rotation_deg = 37.25;
  number.paint_wear = 0.625;
  number.ink_snr = 7.25;
  LabelInstance pillar = number;
  pillar.text = "C3";
  pillar.cls = map::TextClass::kPillar;
  pillar.occluded_fraction = 0.6;
  pillar.truncated = true;
  pillar.landmark_id = "P-C3";
  pillar.rotation_deg = 180.0;
  pillar.paint_wear = 0.0;
  pillar.ink_snr.reset();
  pillar.visible_polygon = {Eigen::Vector2d(100.4, 200.6), Eigen::Vector2d(140.25, 200.8),
                            Eigen::Vector2d(139.5, 240.0), Eigen::Vector2d(99.0, 239.0)};
  LabelInstance thin = number;
  thin.text = "B2-118";
  thin.legible = false;
  labels.instances = {number, pillar, thin};
  return labels;
}

std::string readAll(const std::string& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The message of the InputError that loading `path` throws; "no error" when it loads.
std::string loadError(const std::string& path) {
  try {
    loadLabels(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST_F(LabelsTest, JsonRoundTripIsExact) {
  const ImageLabels labels = sampleLabels();
  saveLabels(labels, path("l.json"));
  const ImageLabels back = loadLabels(path("l.json"));
  EXPECT_EQ(back.camera, labels.camera);
  EXPECT_EQ(back.timestamp, labels.timestamp);
  EXPECT_EQ(back.width, labels.width);
  EXPECT_EQ(back.height, labels.height);
  ASSERT_EQ(back.instances.size(), labels.instances.size());
  for (size_t i = 0; i < labels.instances.size(); ++i) {
    const LabelInstance& a = labels.instances[i];
    const LabelInstance& b = back.instances[i];
    for (int k = 0; k < 4; ++k) EXPECT_EQ(a.polygon[k], b.polygon[k]);
    EXPECT_EQ(a.text, b.text);
    EXPECT_EQ(a.cls, b.cls);
    EXPECT_EQ(a.occluded_fraction, b.occluded_fraction);
    EXPECT_EQ(a.truncated, b.truncated);
    EXPECT_EQ(a.legible, b.legible);
    EXPECT_EQ(a.landmark_id, b.landmark_id);
    EXPECT_EQ(a.rotation_deg, b.rotation_deg);
    EXPECT_EQ(a.paint_wear, b.paint_wear);
    EXPECT_EQ(a.ink_snr, b.ink_snr);
    ASSERT_EQ(a.visible_polygon.has_value(), b.visible_polygon.has_value());
    if (a.visible_polygon) {
      for (int k = 0; k < 4; ++k) EXPECT_EQ((*a.visible_polygon)[k], (*b.visible_polygon)[k]);
    }
  }
}

TEST_F(LabelsTest, IcdarFileRoundsAndMarksOccludedAndIllegibleText) {
  saveIcdarLabels(sampleLabels(), path("gt.txt"));
  EXPECT_EQ(readAll(path("gt.txt")),
            "100,201,181,201,179,240,99,239,B2-117\n"
            "100,201,140,201,140,240,99,239,###\n"  // the cut pillar: the part it shows
            "100,201,181,201,179,240,99,239,###\n");
}

TEST_F(LabelsTest, LegibleDefaultsToTrueAndMustBeABoolean) {
  const std::string ok = write("old.json", R"({"camera": "front", "timestamp": 1.0, "width": 10,
      "height": 10, "instances": [{"polygon": [[0,0],[1,0],[1,1],[0,1]], "text": "A",
      "class": "pillar"}]})");
  EXPECT_TRUE(loadLabels(ok).instances.at(0).legible);
  const std::string bad = write("bad.json", R"({"camera": "front", "timestamp": 1.0, "width": 10,
      "height": 10, "instances": [{"polygon": [[0,0],[1,0],[1,1],[0,1]], "text": "A",
      "class": "pillar", "legible": "yes"}]})");
  EXPECT_EQ(loadError(bad), "labels " + bad + ": instance #0: field 'legible': expected a boolean");
}

// Labels without paint_wear mean intact paint. A wear outside [0, 1] is an error.
TEST_F(LabelsTest, PaintWearDefaultsToIntactAndMustLieBetweenZeroAndOne) {
  const std::string old = write("old.json", R"({"camera": "front", "timestamp": 1.0, "width": 10,
      "height": 10, "instances": [{"polygon": [[0,0],[1,0],[1,1],[0,1]], "text": "A",
      "class": "parking_number"}]})");
  EXPECT_EQ(loadLabels(old).instances.at(0).paint_wear, 0.0);
  const std::string bad = write("bad.json", R"({"camera": "front", "timestamp": 1.0, "width": 10,
      "height": 10, "instances": [{"polygon": [[0,0],[1,0],[1,1],[0,1]], "text": "A",
      "class": "parking_number", "paint_wear": 1.5}]})");
  EXPECT_EQ(loadError(bad), "labels " + bad +
                                ": instance #0: field 'paint_wear': expected a number in [0, 1], "
                                "got 1.5");
}

// ink_snr is optional (text other than painted floor text has none).
// A negative one is an error.
TEST_F(LabelsTest, InkSnrIsOptionalAndNeverNegative) {
  const std::string old = write("old.json", R"({"camera": "front", "timestamp": 1.0, "width": 10,
      "height": 10, "instances": [{"polygon": [[0,0],[1,0],[1,1],[0,1]], "text": "A",
      "class": "parking_number"}]})");
  EXPECT_FALSE(loadLabels(old).instances.at(0).ink_snr.has_value());
  const std::string bad = write("bad.json", R"({"camera": "front", "timestamp": 1.0, "width": 10,
      "height": 10, "instances": [{"polygon": [[0,0],[1,0],[1,1],[0,1]], "text": "A",
      "class": "parking_number", "ink_snr": -2}]})");
  EXPECT_EQ(loadError(bad),
            "labels " + bad + ": instance #0: field 'ink_snr': expected a number >= 0, got -2");
}

TEST_F(LabelsTest, MissingFieldIsNamed) {
  const std::string p = write("bad.json", R"({"camera": "front", "timestamp": 1.0, "width": 10,
      "height": 10, "instances": [{"polygon": [[0,0],[1,0],[1,1],[0,1]], "class": "pillar"}]})");
  EXPECT_EQ(loadError(p), "labels " + p + ": instance #0: missing field 'text'");
}

TEST_F(LabelsTest, PolygonMustHaveFourPoints) {
  const std::string p = write("bad.json", R"({"camera": "front", "timestamp": 1.0, "width": 10,
      "height": 10, "instances": [{"polygon": [[0,0],[1,0],[1,1]], "text": "A",
      "class": "pillar"}]})");
  EXPECT_EQ(loadError(p),
            "labels " + p + ": instance #0: field 'polygon': expected 4 [x, y] points");
}

TEST_F(LabelsTest, AVisiblePolygonIsCheckedLikeThePolygon) {
  const std::string p = write("bad.json", R"({"camera": "front", "timestamp": 1.0, "width": 10,
      "height": 10, "instances": [{"polygon": [[0,0],[1,0],[1,1],[0,1]], "text": "A",
      "class": "pillar", "visible_polygon": [[0,0],[1,0],[1,"x"],[0,1]]}]})");
  EXPECT_EQ(loadError(p),
            "labels " + p + ": instance #0: field 'visible_polygon': point 2 is not [x, y]");
}

}  // namespace
}  // namespace parkloc::io
