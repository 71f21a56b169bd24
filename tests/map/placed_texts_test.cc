#include "map/placed_texts.h"

#include <gtest/gtest.h>

#include <cmath>

namespace parkloc::map {
namespace {

Landmark text(const std::string& id, const std::string& content, const std::string& level, double x,
              double y, Surface surface = Surface::kGround) {
  Landmark l;
  l.id = id;
  l.text = content;
  l.level = level;
  l.position = {x, y, surface == Surface::kGround ? 0.0 : 1.5};
  l.width = 1.0;
  l.height = 0.5;
  l.surface = surface;
  if (surface == Surface::kVertical) {
    l.cls = TextClass::kPillar;
    l.normal = Eigen::Vector3d::UnitX();
    l.heading = M_PI / 2;
  }
  return l;
}

// A vehicle at (10, 5) heading north (+y): a text 3 m north of it lies 3 m ahead (+x in the
// vehicle frame), one 2 m east of it 2 m to its right (-y).
TEST(PlaceFloorTexts, PutsTheFloorTextsOfTheLevelAroundTheVehicleInItsFrame) {
  const HdMap m({text("a", "A001", "B1", 10.0, 8.0), text("b", "A002", "B1", 12.0, 5.0),
                 text("c", "A001", "B2", 10.0, 8.0),
                 text("p", "B1", "B1", 10.0, 6.0, Surface::kVertical),
                 text("far", "A009", "B1", 30.0, 5.0)});
  const geometry::Pose2 map_from_vehicle(10.0, 5.0, M_PI / 2);
  const auto placed = placeFloorTexts(m, map_from_vehicle, 10.0, "B1");
  ASSERT_EQ(placed.size(), 2u);  // not B2's, not the pillar's, not the one 20 m away
  for (const PlacedText& p : placed) {
    EXPECT_EQ(p.cls, TextClass::kParkingNumber);
    EXPECT_EQ(p.width, 1.0);  // the map's size, which a frame change keeps
    EXPECT_EQ(p.height, 0.5);
    // Both read east (heading 0): to the vehicle's right.
    EXPECT_NEAR(p.reading.x(), 0.0, 1e-9);
    EXPECT_NEAR(p.reading.y(), -1.0, 1e-9);
    if (p.text == "A001") {
      EXPECT_NEAR(p.vehicle_xy.x(), 3.0, 1e-9);
      EXPECT_NEAR(p.vehicle_xy.y(), 0.0, 1e-9);
    } else {
      EXPECT_EQ(p.text, "A002");
      EXPECT_NEAR(p.vehicle_xy.x(), 0.0, 1e-9);
      EXPECT_NEAR(p.vehicle_xy.y(), -2.0, 1e-9);
    }
  }
  EXPECT_EQ(placeFloorTexts(m, map_from_vehicle, 10.0, "").size(), 3u);  // every level
}

TEST(TextsNear, KeepsThoseWithinTheRadiusOnceEachNearestFirst) {
  const std::vector<PlacedText> placed = {{"C003", {3.0, 0.0}},
                                          {"C001", {0.5, 0.0}},
                                          {"C002", {0.0, 0.9}},
                                          {"C001", {0.2, 0.0}},
                                          {"C004", {1.0, 1.0}}};
  EXPECT_EQ(textsNear(placed, {0.0, 0.0}, 1.0), (std::vector<std::string>{"C001", "C002"}));
  EXPECT_EQ(textsNear(placed, {0.0, 0.0}, 1.5), (std::vector<std::string>{"C001", "C002", "C004"}));
  EXPECT_TRUE(textsNear(placed, {-5.0, 0.0}, 1.0).empty());
  EXPECT_TRUE(textsNear({}, {0.0, 0.0}, 1.0).empty());
}

TEST(NearestPlaced, IsTheNearestWithinTheRadiusOfThoseThatReadTheText) {
  const std::vector<PlacedText> placed = {
      {"C001", {0.8, 0.0}}, {"C002", {0.3, 0.0}}, {"C001", {0.5, 0.0}}, {"C003", {3.0, 0.0}}};
  ASSERT_NE(nearestPlaced(placed, {0.0, 0.0}, 1.0), nullptr);
  EXPECT_EQ(nearestPlaced(placed, {0.0, 0.0}, 1.0), &placed[1]);          // any text
  EXPECT_EQ(nearestPlaced(placed, {0.0, 0.0}, 1.0, "C001"), &placed[2]);  // the nearer C001
  EXPECT_EQ(nearestPlaced(placed, {0.0, 0.0}, 1.0, "C003"), nullptr);     // too far
  EXPECT_EQ(nearestPlaced(placed, {0.0, 0.0}, 1.0, "C009"), nullptr);     // not placed
}

TEST(PlacedTextUnder, IsTheTextWhoseFootprintHoldsThePoint) {
  // C001 reads east, 1.0 x 0.4 m, at the origin; C002 reads north, 1.0 x 0.4 m, at (2, 0);
  // C003's size is not known.
  const Eigen::Vector2d east(1.0, 0.0), north(0.0, 1.0);
  const std::vector<PlacedText> placed = {
      {"C001", {0.0, 0.0}, east, TextClass::kParkingNumber, 1.0, 0.4},
      {"C002", {2.0, 0.0}, north, TextClass::kParkingNumber, 1.0, 0.4},
      {"C003", {0.0, 5.0}, east}};
  EXPECT_EQ(placedTextUnder(placed, {0.45, 0.15}, 0.0), &placed[0]);  // inside, near a corner
  EXPECT_EQ(placedTextUnder(placed, {0.0, 0.3}, 0.0), nullptr);       // beyond its height
  EXPECT_EQ(placedTextUnder(placed, {0.0, 0.3}, 0.15), &placed[0]);   // ... within the margin
  // C002 reads north: its length lies along y, its height along x.
  EXPECT_EQ(placedTextUnder(placed, {2.0, 0.45}, 0.0), &placed[1]);
  EXPECT_EQ(placedTextUnder(placed, {2.45, 0.0}, 0.0), nullptr);
  EXPECT_EQ(placedTextUnder(placed, {0.0, 5.0}, 1.0), nullptr);  // no footprint known
}

TEST(ReadingDirectionNear, IsTheWayTheTextsPlacedThereReadWhenTheyAgree) {
  const Eigen::Vector2d east(1.0, 0.0), west(-1.0, 0.0), north_east(1.0, 1.0);
  const std::vector<PlacedText> placed = {{"C001", {0.0, 0.0}, east},
                                          {"C002", {1.3, 0.0}, north_east / std::sqrt(2.0)},
                                          {"D001", {0.0, 3.0}, west}};
  const double radius = 1.0, max_angle = M_PI / 6;
  const auto near_c001 = readingDirectionNear(placed, {0.1, 0.0}, radius, max_angle);
  ASSERT_TRUE(near_c001);
  EXPECT_NEAR(near_c001->x(), 1.0, 1e-9);  // the nearest's own direction
  // Between C001 and C002, which read 45 degrees apart: no direction within 30 degrees.
  EXPECT_FALSE(readingDirectionNear(placed, {0.65, 0.0}, radius, max_angle));
  EXPECT_TRUE(readingDirectionNear(placed, {0.65, 0.0}, radius, M_PI / 3));
  const auto near_d001 = readingDirectionNear(placed, {0.0, 2.5}, radius, max_angle);
  ASSERT_TRUE(near_d001);
  EXPECT_NEAR(near_d001->x(), -1.0, 1e-9);
  EXPECT_FALSE(readingDirectionNear(placed, {0.0, 1.5}, radius, max_angle));  // none near
}

}  // namespace
}  // namespace parkloc::map
