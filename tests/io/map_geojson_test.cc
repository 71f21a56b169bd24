#include "io/map_geojson.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "common/error.h"
#include "test_dir.h"

namespace parkloc::io {
namespace {

class MapGeoJsonTest : public testing::TempDirTest {};

map::Landmark groundNumber(const std::string& text, double x, double y, double heading) {
  map::Landmark l;
  l.id = text;
  l.text = text;
  l.cls = map::TextClass::kParkingNumber;
  l.level = "B1";
  l.position = {x, y, 0.0};
  l.heading = heading;
  l.width = 1.0;
  l.height = 0.5;
  return l;
}

// A map with awkward doubles (thirds, tiny and huge values) in every field.
map::HdMap awkwardMap() {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-50.0, 50.0);
  std::vector<map::Landmark> landmarks;
  for (int i = 0; i < 20; ++i)
    landmarks.push_back(
        groundNumber("B1-" + std::to_string(100 + i), u(rng) / 3.0, u(rng) * 1e-7, u(rng) / 7.0));
  map::Landmark pillar;
  pillar.id = "P-3";
  pillar.text = "B1-C3";
  pillar.cls = map::TextClass::kPillar;
  pillar.level = "B1";
  pillar.position = {12.345678901234567, -3.0 / 7.0, 1.6};
  pillar.heading = M_PI / 2;
  pillar.width = 0.45;
  pillar.height = 0.3;
  pillar.surface = map::Surface::kVertical;
  pillar.normal = Eigen::Vector3d(std::cos(0.1), std::sin(0.1), 0.0);
  landmarks.push_back(pillar);
  map::Landmark exit = groundNumber("EXIT", 1e5 / 3.0, 2.0, -1.0);
  exit.id = "exit-1";
  exit.cls = map::TextClass::kOther;
  exit.normal = Eigen::Vector3d(0.0, 0.0, 1.0);
  landmarks.push_back(exit);
  return map::HdMap(landmarks, "awkward");
}

std::string feature(const std::string& properties, const std::string& coordinates = "[1, 2, 0]") {
  return R"({"type": "Feature", "geometry": {"type": "Point", "coordinates": )" + coordinates +
         R"(}, "properties": {)" + properties + "}}";
}
std::string collection(const std::string& features) {
  return R"({"type": "FeatureCollection", "features": [)" + features + "]}";
}
const std::string kGood =
    R"("id": "a", "text": "B1-101", "class": "parking_number", "level": "B1", "heading": 0.5,
       "width": 1.0, "height": 0.5, "surface": "ground")";

std::string errorFor(const std::string& text) {
  try {
    parseMap(text, "m.geojson");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST_F(MapGeoJsonTest, SaveLoadRoundTripIsExact) {
  const map::HdMap original = awkwardMap();
  saveMap(original, path("map.geojson"));
  const map::HdMap back = loadMap(path("map.geojson"));
  EXPECT_EQ(back.name(), "awkward");
  ASSERT_EQ(back.size(), original.size());
  for (size_t i = 0; i < original.size(); ++i) {
    const map::Landmark& a = original.landmarks()[i];
    const map::Landmark& b = back.landmarks()[i];
    EXPECT_EQ(a.id, b.id);
    EXPECT_EQ(a.text, b.text);
    EXPECT_EQ(a.cls, b.cls);
    EXPECT_EQ(a.level, b.level);
    EXPECT_EQ(a.position, b.position);  // bit-exact
    EXPECT_EQ(a.heading, b.heading);
    EXPECT_EQ(a.width, b.width);
    EXPECT_EQ(a.height, b.height);
    EXPECT_EQ(a.surface, b.surface);
    EXPECT_EQ(a.normal, b.normal);
  }
  EXPECT_EQ(mapToGeoJson(back), mapToGeoJson(original));
}

TEST_F(MapGeoJsonTest, MinimalFeatureLoads) {
  const map::HdMap m = parseMap(collection(feature(kGood)), "m.geojson");
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m.landmarks()[0].position, Eigen::Vector3d(1, 2, 0));
  EXPECT_EQ(m.landmarks()[0].normal, Eigen::Vector3d::UnitZ());
}

TEST_F(MapGeoJsonTest, MissingFileIsAnError) {
  EXPECT_THROW(loadMap(path("absent.geojson")), InputError);
}

TEST_F(MapGeoJsonTest, MalformedJsonGivesThePosition) {
  const std::string message = errorFor(R"({"type": "FeatureCollection", "features": [ }")");
  EXPECT_EQ(message.rfind("map m.geojson: malformed JSON at byte 45: ", 0), 0u) << message;
  EXPECT_NE(message.find("line 1, column 45"), std::string::npos) << message;
}

TEST_F(MapGeoJsonTest, NotAFeatureCollection) {
  EXPECT_EQ(errorFor(R"({"type": "Feature"})"),
            "map m.geojson: expected a GeoJSON FeatureCollection");
}

TEST_F(MapGeoJsonTest, MissingPropertyNamesFeatureAndProperty) {
  const std::string props = R"("id": "a", "text": "B1-101", "class": "parking_number",
      "level": "B1", "heading": 0.5, "width": 1.0, "surface": "ground")";
  EXPECT_EQ(errorFor(collection(feature(kGood) + "," + feature(props))),
            "map m.geojson: feature #1 (id 'a'): missing property 'height'");
}

TEST_F(MapGeoJsonTest, WrongTypeNamesTheType) {
  const std::string props = R"("id": "a", "text": "B1-101", "class": "parking_number",
      "level": "B1", "heading": "east", "width": 1.0, "height": 0.5, "surface": "ground")";
  EXPECT_EQ(errorFor(collection(feature(props))),
            "map m.geojson: feature #0 (id 'a'): property 'heading': expected a number, got "
            "string");
}

TEST_F(MapGeoJsonTest, UnknownClassIsRejected) {
  const std::string props = R"("id": "a", "text": "B1-101", "class": "arrow", "level": "B1",
      "heading": 0.5, "width": 1.0, "height": 0.5, "surface": "ground")";
  EXPECT_EQ(errorFor(collection(feature(props))),
            "map m.geojson: feature #0 (id 'a'): property 'class': unknown class 'arrow' "
            "(parking_number, pillar, other)");
}

TEST_F(MapGeoJsonTest, UnknownSurfaceIsRejected) {
  const std::string props = R"("id": "a", "text": "B1-101", "class": "pillar", "level": "B1",
      "heading": 0.5, "width": 1.0, "height": 0.5, "surface": "ceiling")";
  EXPECT_EQ(errorFor(collection(feature(props))),
            "map m.geojson: feature #0 (id 'a'): property 'surface': unknown surface 'ceiling' "
            "(ground, vertical)");
}

TEST_F(MapGeoJsonTest, VerticalTextNeedsANormal) {
  const std::string props = R"("id": "p", "text": "C3", "class": "pillar", "level": "B1",
      "heading": 0.5, "width": 1.0, "height": 0.5, "surface": "vertical")";
  EXPECT_EQ(errorFor(collection(feature(props))),
            "map m.geojson: feature #0 (id 'p'): missing property 'normal'");
}

TEST_F(MapGeoJsonTest, DuplicateIdNamesBothFeatures) {
  const std::string other = R"("id": "a", "text": "B1-102", "class": "parking_number",
      "level": "B1", "heading": 0.5, "width": 1.0, "height": 0.5, "surface": "ground")";
  EXPECT_EQ(errorFor(collection(feature(kGood) + "," + feature(other))),
            "map m.geojson: feature #1: duplicate id 'a' (first at feature #0)");
}

TEST_F(MapGeoJsonTest, ParkingNumberTwiceOnOneLevelIsRejected) {
  const std::string twin = R"("id": "b", "text": "B1-101", "class": "parking_number",
      "level": "B1", "heading": 0.5, "width": 1.0, "height": 0.5, "surface": "ground")";
  EXPECT_EQ(errorFor(collection(feature(kGood) + "," + feature(twin))),
            "map m.geojson: landmark 'b': parking number 'B1-101' appears twice on level 'B1'");
}

TEST_F(MapGeoJsonTest, SameParkingNumberOnTwoLevelsIsFine) {
  const std::string other_level = R"("id": "b", "text": "B1-101", "class": "parking_number",
      "level": "B2", "heading": 0.5, "width": 1.0, "height": 0.5, "surface": "ground")";
  EXPECT_EQ(errorFor(collection(feature(kGood) + "," + feature(other_level))), "");
}


std::string collectionWith(const std::string& map_properties, const std::string& features) {
  return R"({"type": "FeatureCollection", "properties": )" + map_properties +
         R"(, "features": [)" + features + "]}";
}

TEST_F(MapGeoJsonTest, SigmasAreAbsentWhenTheMapStatesNone) {
  const map::HdMap m = parseMap(collection(feature(kGood)), "m.geojson");
  EXPECT_FALSE(m.accuracy().position_sigma);
  EXPECT_FALSE(m.accuracy().heading_sigma);
  EXPECT_FALSE(m.landmarks()[0].accuracy.position_sigma);
  EXPECT_FALSE(m.landmarks()[0].accuracy.heading_sigma);
}

TEST_F(MapGeoJsonTest, FeatureSigmaOverridesTheMapWideDefault) {
  const std::string own = kGood + R"(, "position_sigma": 0.25)";
  const std::string b = R"("id": "b", "text": "B1-102", "class": "parking_number", "level": "B1",
      "heading": 0.5, "width": 1.0, "height": 0.5, "surface": "ground", "heading_sigma": 0.02)";
  const map::HdMap m = parseMap(
      collectionWith(R"({"position_sigma": 0.05, "heading_sigma": 0.01})",
                     feature(own) + "," + feature(b)),
      "m.geojson");
  EXPECT_EQ(m.accuracy().position_sigma, 0.05);
  EXPECT_EQ(m.accuracy().heading_sigma, 0.01);
  EXPECT_EQ(m.landmarks()[0].accuracy.position_sigma, 0.25);
  EXPECT_EQ(m.landmarks()[0].accuracy.heading_sigma, 0.01);  // the map's
  EXPECT_EQ(m.landmarks()[1].accuracy.position_sigma, 0.05);  // the map's
  EXPECT_EQ(m.landmarks()[1].accuracy.heading_sigma, 0.02);
}

TEST_F(MapGeoJsonTest, SigmasRoundTrip) {
  std::vector<map::Landmark> landmarks;
  for (int i = 0; i < 4; ++i) landmarks.push_back(groundNumber("B1-" + std::to_string(i), i, 0, 0));
  const map::MapAccuracy fallback{0.1 / 3.0, 0.004};
  for (auto& l : landmarks) l.accuracy = fallback;
  landmarks[1].accuracy.position_sigma = 1.0 / 7.0;
  landmarks[2].accuracy.heading_sigma = 0.0;
  landmarks[3].accuracy = {};  // states nothing, and the map has a default: reads as the default
  const map::HdMap original(landmarks, "sigmas", fallback);
  saveMap(original, path("map.geojson"));
  const map::HdMap back = loadMap(path("map.geojson"));
  EXPECT_EQ(back.accuracy(), fallback);
  for (size_t i = 0; i < 3; ++i)
    EXPECT_EQ(back.landmarks()[i].accuracy, original.landmarks()[i].accuracy) << i;
  EXPECT_EQ(back.landmarks()[3].accuracy, fallback);
  EXPECT_EQ(mapToGeoJson(back), mapToGeoJson(original));
  // The map-wide default is written once, at the top, and not per feature.
  const std::string text = mapToGeoJson(back);
  EXPECT_NE(text.find(R"("properties": {"position_sigma":)"), std::string::npos) << text;
  size_t features_with_position_sigma = 0;
  for (size_t at = text.find("\"position_sigma\""); at != std::string::npos;
       at = text.find("\"position_sigma\"", at + 1))
    ++features_with_position_sigma;
  EXPECT_EQ(features_with_position_sigma, 2u);  // the map's and landmark 1's
}

TEST_F(MapGeoJsonTest, BadFeatureSigmaNamesTheFeature) {
  EXPECT_EQ(errorFor(collection(feature(kGood + R"(, "position_sigma": -0.01)"))),
            "map m.geojson: feature #0 (id 'a'): position_sigma: -0.01 is not a sigma in [0, 10] m");
  EXPECT_EQ(errorFor(collection(feature(kGood + R"(, "position_sigma": 10.5)"))),
            "map m.geojson: feature #0 (id 'a'): position_sigma: 10.5 is not a sigma in [0, 10] m");
  EXPECT_EQ(errorFor(collection(feature(kGood + R"(, "heading_sigma": 0.6)"))),
            "map m.geojson: feature #0 (id 'a'): heading_sigma: 0.6 is not a sigma in [0, 0.5] rad");
  EXPECT_EQ(errorFor(collection(feature(kGood + R"(, "heading_sigma": "1 deg")"))),
            "map m.geojson: feature #0 (id 'a'): property 'heading_sigma': expected a number, got "
            "string");
  EXPECT_EQ(errorFor(collection(feature(kGood + R"(, "position_sigma": 1e400)"))).rfind(
                "map m.geojson: malformed JSON", 0),
            0u);
}

TEST_F(MapGeoJsonTest, BadMapWideSigmaIsOneLine) {
  EXPECT_EQ(errorFor(collectionWith(R"({"position_sigma": -1})", feature(kGood))),
            "map m.geojson: map-wide properties: position_sigma: -1 is not a sigma in [0, 10] m");
  EXPECT_EQ(errorFor(collectionWith(R"({"heading_sigma": 3.2})", feature(kGood))),
            "map m.geojson: map-wide properties: heading_sigma: 3.2 is not a sigma in [0, 0.5] rad");
  EXPECT_EQ(errorFor(collectionWith(R"({"heading_sigma": null})", feature(kGood))),
            "map m.geojson: map-wide properties: 'heading_sigma': expected a number, got null");
  EXPECT_EQ(errorFor(collectionWith("[1, 2]", feature(kGood))),
            "map m.geojson: map-wide properties: expected an object, got array");
}

TEST_F(MapGeoJsonTest, AMapIsCompleteUnlessItSaysOtherwise) {
  const map::HdMap complete({groundNumber("B1-1", 0, 0, 0)}, "survey");
  saveMap(complete, path("survey.geojson"));
  EXPECT_TRUE(loadMap(path("survey.geojson")).complete());
  EXPECT_EQ(mapToGeoJson(complete).find("complete"), std::string::npos);
  const map::HdMap built({groundNumber("B1-1", 0, 0, 0)}, "built", {}, /*complete=*/false);
  saveMap(built, path("built.geojson"));
  EXPECT_FALSE(loadMap(path("built.geojson")).complete());
  EXPECT_EQ(errorFor(collectionWith(R"({"complete": "no"})", feature(kGood))),
            "map m.geojson: map-wide properties: 'complete': expected true or false, got string");
}

TEST_F(MapGeoJsonTest, MapBuiltInCodeRejectsANonFiniteSigma) {
  map::Landmark l = groundNumber("B1-1", 0, 0, 0);
  l.accuracy.position_sigma = std::nan("");
  EXPECT_THROW(map::HdMap({l}), InputError);
  EXPECT_THROW(map::HdMap({}, "", map::MapAccuracy{std::nullopt, -1e-3}), InputError);
}

}  // namespace
}  // namespace parkloc::io
