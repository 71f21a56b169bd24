#include "eval/map_comparison.h"

#include <gtest/gtest.h>

namespace parkloc::eval {
namespace {

map::Landmark number(const std::string& text, double x, double y, double heading = 0.0) {
  map::Landmark l;
  l.text = text;
  l.id = "B1:" + text;
  l.level = "B1";
  l.position = {x, y, 0.0};
  l.heading = heading;
  l.width = 1.0;
  l.height = 0.5;
  return l;
}

map::HdMap truthMap() {
  std::vector<map::Landmark> l;
  for (int i = 0; i < 6; ++i) l.push_back(number("N" + std::to_string(i), 2.5 * i, 3.0));
  return map::HdMap(l);
}

TEST(MapComparison, AlignsTheBuiltFrameAndMeasuresEachError) {
  // The built map: the truth in another frame, N1 2 cm off, N2 turned 1 degree and 10 %
  // wider, N5 missing, a phantom text and a right text at a wrong place.
  const geometry::Pose2 built_from_true(-3.0, 7.0, 1.1);
  const map::HdMap truth = truthMap();
  std::vector<map::Landmark> built;
  for (const map::Landmark& t : truth.landmarks()) {
    if (t.text == "N5") continue;
    map::Landmark b = t;
    if (t.text == "N1") b.position.x() += 0.02;
    if (t.text == "N2") {
      b.heading += M_PI / 180.0;
      b.width = 1.1;
    }
    if (t.text == "N4") b.position.y() += 2.0;
    b.position.head<2>() = built_from_true * Eigen::Vector2d(b.position.head<2>());
    b.heading += built_from_true.yaw;
    built.push_back(b);
  }
  built.push_back(number("Q9", 0.0, 0.0));
  const MapComparison c = compareMaps(map::HdMap(built), truth, "", /*legible_frames=*/{}, {});
  EXPECT_EQ(c.level, "B1");
  ASSERT_TRUE(c.fit);
  EXPECT_EQ(c.position_m.count, 4u);
  EXPECT_NEAR(c.position_m.max, 0.015, 0.006);  // the 2 cm, less what the fit spreads
  EXPECT_NEAR(c.abs_heading_deg.max, 1.0, 1e-6);
  EXPECT_NEAR(c.abs_width_rel.max, 0.1, 1e-9);
  EXPECT_EQ(c.built, 6);
  ASSERT_EQ(c.phantoms.size(), 2u);  // Q9 (no such text) and N4 (wrong place)
  EXPECT_EQ(c.legible, 6);
  EXPECT_EQ(c.legible_found, 4);
  EXPECT_NEAR(c.completeness, 4.0 / 6.0, 1e-12);
}

TEST(MapComparison, CompletenessCountsOnlyWhatTheDriveShowedLegibly) {
  const map::HdMap truth = truthMap();
  std::vector<map::Landmark> built;
  for (const map::Landmark& t : truth.landmarks())
    if (t.text != "N5" && t.text != "N4") built.push_back(t);
  // N5 was legible in 2 frame sets only: not counted; N4 in 3: counted, and missing.
  const std::map<std::string, int> legible = {{"B1:N0", 9}, {"B1:N1", 9}, {"B1:N2", 9},
                                              {"B1:N3", 9}, {"B1:N4", 3}, {"B1:N5", 2}};
  const MapComparison c = compareMaps(map::HdMap(built), truth, "B1", legible, {});
  EXPECT_EQ(c.legible, 5);
  EXPECT_EQ(c.legible_found, 4);
  ASSERT_EQ(c.missing.size(), 1u);
  EXPECT_EQ(c.missing[0], "N4");
  EXPECT_TRUE(c.phantoms.empty());
  EXPECT_LT(c.position_m.max, 1e-9);
}

TEST(MapComparison, ALandmarkFarOffDoesNotPullTheAlignmentAway) {
  // Two of three texts right, one 30 m off: a fit over all three puts none within 0.5 m of
  // its true place; the alignment must follow the two that agree.
  const map::HdMap truth = truthMap();
  std::vector<map::Landmark> built = {number("N0", 0.0, 3.0), number("N1", 2.5, 3.0),
                                      number("N2", 35.0, 3.0)};
  const MapComparison c = compareMaps(map::HdMap(built), truth, "B1", /*legible_frames=*/{}, {});
  ASSERT_TRUE(c.fit);
  EXPECT_EQ(c.position_m.count, 2u);
  EXPECT_LT(c.position_m.max, 1e-9);
  ASSERT_EQ(c.phantoms.size(), 1u);
  EXPECT_EQ(c.phantoms[0], "N2");
}

}  // namespace
}  // namespace parkloc::eval
