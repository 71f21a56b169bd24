// The calibration and map that ship in data/, and the broken variants in tests/data/ that
// the CLI tests feed to `parkloc calib check` / `parkloc map check`.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "common/error.h"
#include "geometry/rig.h"
#include "io/calibration_yaml.h"
#include "io/map_geojson.h"

namespace parkloc::io {
namespace {

const std::string kRoot = PARKLOC_SOURCE_DIR;

std::string readAll(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

template <typename Load>
std::string errorFor(Load load, const std::string& path) {
  try {
    load(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ShippedDataTest, DefaultRigFileIsTheDefaultRig) {
  const geometry::Rig shipped = loadCalibration(kRoot + "/data/rig/default_rig.yaml");
  const geometry::Rig expected = geometry::defaultRig();
  ASSERT_EQ(shipped.cameras.size(), expected.cameras.size());
  for (size_t i = 0; i < expected.cameras.size(); ++i) {
    const auto& a = shipped.cameras[i];
    const auto& b = expected.cameras[i];
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.model.width, b.model.width);
    EXPECT_EQ(a.model.height, b.model.height);
    EXPECT_EQ(a.model.fx, b.model.fx);
    EXPECT_EQ(a.model.cx, b.model.cx);
    EXPECT_EQ(a.model.cy, b.model.cy);
    EXPECT_EQ(a.model.distortion, b.model.distortion);
    EXPECT_EQ(a.model.max_theta, b.model.max_theta);
    EXPECT_LT(
        (a.vehicle_from_camera.matrix() - b.vehicle_from_camera.matrix()).cwiseAbs().maxCoeff(),
        1e-15);
    ASSERT_TRUE(a.body) << a.name;
    EXPECT_EQ(a.body->lo, b.body->lo);
    EXPECT_EQ(a.body->hi, b.body->hi);
  }
}

TEST(ShippedDataTest, ExampleMapIsInCanonicalFormAndPlausible) {
  const std::string path = kRoot + "/data/maps/example_garage.geojson";
  const map::HdMap m = loadMap(path);
  EXPECT_EQ(mapToGeoJson(m), readAll(path));  // saving gives back the file byte for byte
  int numbers = 0, pillars = 0, others = 0;
  for (const map::Landmark& l : m.landmarks()) {
    numbers += l.cls == map::TextClass::kParkingNumber;
    pillars += l.cls == map::TextClass::kPillar;
    others += l.cls == map::TextClass::kOther;
    EXPECT_EQ(l.level, "B1");
  }
  EXPECT_EQ(numbers, 20);
  EXPECT_GT(pillars, 0);
  EXPECT_GT(others, 0);
  // Neighbouring slots are 2.5 m apart.
  const map::Landmark* a = m.findById("B1-101");
  const map::Landmark* b = m.findById("B1-102");
  ASSERT_TRUE(a && b);
  EXPECT_NEAR((a->position - b->position).norm(), 2.5, 1e-12);
}

struct BrokenFile {
  std::string file;
  std::string message;  // what the error must contain after "<kind> <path>: "
};

class BrokenCalibration : public ::testing::TestWithParam<BrokenFile> {};
TEST_P(BrokenCalibration, IsRejectedWithItsMessage) {
  const std::string path = kRoot + "/tests/data/calib/" + GetParam().file;
  const std::string message = errorFor(loadCalibration, path);
  EXPECT_EQ(message.rfind("calib " + path + ": ", 0), 0u) << message;
  EXPECT_NE(message.find(GetParam().message), std::string::npos) << message;
}
INSTANTIATE_TEST_SUITE_P(
    TestsData, BrokenCalibration,
    ::testing::Values(
        BrokenFile{"missing_field.yaml", "camera 'front': field 'image_height': missing"},
        BrokenFile{"wrong_matrix_size.yaml",
                   "camera 'front': field 'K': expected a 3x3 matrix, got 3x2"},
        BrokenFile{"nan_value.yaml", "camera 'front': field 'max_theta': non-finite value"},
        BrokenFile{"unknown_model.yaml",
                   "camera 'front': field 'model': unknown model 'omnidirectional'"},
        BrokenFile{"duplicate_camera.yaml", "camera 'front': field 'name': duplicate camera name"},
        BrokenFile{"not_orthonormal.yaml",
                   "camera 'front': field 'T_vehicle_camera': rotation part is not orthonormal"},
        BrokenFile{"inverted_vehicle_body.yaml",
                   "vehicle_body: field 'max': must exceed min on every axis"},
        BrokenFile{"unparseable.yaml", "cannot parse YAML"}));

class BrokenMap : public ::testing::TestWithParam<BrokenFile> {};
TEST_P(BrokenMap, IsRejectedWithItsMessage) {
  const std::string path = kRoot + "/tests/data/maps/" + GetParam().file;
  const std::string message = errorFor(loadMap, path);
  EXPECT_EQ(message.rfind("map " + path + ": ", 0), 0u) << message;
  EXPECT_NE(message.find(GetParam().message), std::string::npos) << message;
}
INSTANTIATE_TEST_SUITE_P(
    TestsData, BrokenMap,
    ::testing::Values(
        BrokenFile{"malformed_json.geojson", "malformed JSON at byte"},
        BrokenFile{"missing_property.geojson",
                   "feature #2 (id 'B1-103'): missing property 'heading'"},
        BrokenFile{"duplicate_id.geojson",
                   "feature #4: duplicate id 'B1-104' (first at feature #3)"},
        BrokenFile{"duplicate_parking_number.geojson",
                   "landmark 'B1-112': parking number 'B1-102' appears twice on level 'B1'"}));

}  // namespace
}  // namespace parkloc::io
