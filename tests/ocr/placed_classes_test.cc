#include "ocr/placed_classes.h"

#include <gtest/gtest.h>

namespace parkloc::ocr {
namespace {

using map::TextClass;

TEST(FloorClassWeightsNear, FavourTheClassesOfTheTextsPlacedThere) {
  const Eigen::Vector2d east(1.0, 0.0);
  const std::vector<map::PlacedText> placed = {
      {"C001", {0.0, 0.0}, east, TextClass::kParkingNumber},
      {"STOP", {1.5, 0.0}, east, TextClass::kOther},
      {"B1", {0.0, 5.0}, east, TextClass::kPillar}};
  const double radius = 1.0;
  const float unplaced_other = 0.2f;
  const ClassWeights number = {0.f, 1.f, unplaced_other};
  const ClassWeights both = {0.f, 1.f, 1.f};
  const ClassWeights other = {0.f, 0.f, 1.f};
  EXPECT_EQ(floorClassWeightsNear(placed, {0.2, 0.0}, radius, unplaced_other), number);
  EXPECT_EQ(floorClassWeightsNear(placed, {0.75, 0.0}, radius, unplaced_other), both);
  EXPECT_EQ(floorClassWeightsNear(placed, {2.0, 0.0}, radius, unplaced_other), other);
  // Nothing placed near (the pillar's text is not on the floor): other floor text only.
  EXPECT_EQ(floorClassWeightsNear(placed, {-3.0, 0.0}, radius, unplaced_other), other);
  EXPECT_EQ(floorClassWeightsNear(placed, {0.0, 5.0}, radius, unplaced_other), other);
  EXPECT_EQ(floorClassWeightsNear({}, {0.0, 0.0}, radius, unplaced_other), other);
  const ClassWeights number_only = {0.f, 1.f, 0.f};
  EXPECT_EQ(floorClassWeightsNear(placed, {0.2, 0.0}, radius, 0.f), number_only);
}

}  // namespace
}  // namespace parkloc::ocr
