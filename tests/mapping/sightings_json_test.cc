#include "mapping/sightings_json.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "common/error.h"

namespace parkloc::mapping {
namespace {

TEST(SightingsJson, RoundTripsAndRejectsAMalformedLine) {
  const std::string path =
      (std::filesystem::temp_directory_path() / "parkloc_sightings_test.jsonl").string();
  Sighting s;
  s.drive = 1;
  s.frame = 17;
  s.camera = 2;
  s.text = "B1-017";
  s.pixels = {Eigen::Vector2d(1.5, 2.5), {3.0, 4.0}, {5.0, 6.0}, {7.0, 8.25}};
  s.recognition_score = 0.75;
  Sighting second = s;
  second.second_opinion = true;
  second.off_numbering = true;
  second.box_only = true;
  saveSightings({s, second}, path);
  const auto back = loadSightings(path);
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[1].text, "B1-017");
  EXPECT_EQ(back[1].frame, 17u);
  EXPECT_EQ(back[1].camera, 2);
  EXPECT_EQ(back[1].pixels[3], Eigen::Vector2d(7.0, 8.25));
  EXPECT_FALSE(back[0].second_opinion);
  EXPECT_TRUE(back[1].second_opinion);
  EXPECT_FALSE(back[0].off_numbering);
  EXPECT_TRUE(back[1].off_numbering);
  EXPECT_FALSE(back[0].box_only);
  EXPECT_TRUE(back[1].box_only);
  std::ofstream(path, std::ios::app) << "{\"drive\": 0}\n";
  EXPECT_THROW(loadSightings(path), InputError);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace parkloc::mapping
