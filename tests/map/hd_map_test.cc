#include "map/hd_map.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "common/error.h"

namespace parkloc::map {
namespace {

Landmark number(const std::string& id, const std::string& text, const std::string& level, double x,
                double y) {
  Landmark l;
  l.id = id;
  l.text = text;
  l.level = level;
  l.position = {x, y, 0.0};
  l.width = 1.0;
  l.height = 0.5;
  return l;
}

// 400 landmarks scattered over 80 m x 60 m on two levels, some sharing texts across levels.
HdMap randomMap(std::mt19937& rng) {
  std::uniform_real_distribution<double> x(-40.0, 40.0), y(-30.0, 30.0);
  std::vector<Landmark> landmarks;
  for (int i = 0; i < 400; ++i) {
    const std::string level = i % 2 ? "B1" : "B2";
    Landmark l =
        number("L" + std::to_string(i), "N-" + std::to_string(i / 2), level, x(rng), y(rng));
    if (i % 7 == 0) l.cls = TextClass::kPillar;
    landmarks.push_back(l);
  }
  return HdMap(landmarks, "random");
}

std::vector<std::string> ids(std::vector<const Landmark*> found) {
  std::vector<std::string> out;
  for (const Landmark* l : found) out.push_back(l->id);
  std::sort(out.begin(), out.end());
  return out;
}

TEST(HdMapTest, WithinRadiusEqualsBruteForce) {
  std::mt19937 rng(42);
  const HdMap m = randomMap(rng);
  std::uniform_real_distribution<double> x(-50.0, 50.0), y(-40.0, 40.0), r(0.0, 15.0);
  int nonempty = 0;
  for (int q = 0; q < 200; ++q) {
    const Eigen::Vector2d center(x(rng), y(rng));
    const double radius = r(rng);
    const std::string level = q % 3 == 0 ? "" : (q % 3 == 1 ? "B1" : "B2");
    std::vector<const Landmark*> expected;
    for (const Landmark& l : m.landmarks())
      if ((l.position.head<2>() - center).norm() <= radius && (level.empty() || l.level == level))
        expected.push_back(&l);
    const auto got = ids(m.withinRadius(center, radius, level));
    EXPECT_EQ(got, ids(expected)) << "query " << q;
    nonempty += !expected.empty();
  }
  EXPECT_GT(nonempty, 50);  // the comparison is not vacuous
}

TEST(HdMapTest, FindByTextAndIdEqualBruteForce) {
  std::mt19937 rng(3);
  const HdMap m = randomMap(rng);
  for (const std::string text : {"N-0", "N-57", "N-199", "N-200"}) {
    for (const std::string level : {"", "B1", "B2"}) {
      std::vector<const Landmark*> expected;
      for (const Landmark& l : m.landmarks())
        if (l.text == text && (level.empty() || l.level == level)) expected.push_back(&l);
      EXPECT_EQ(ids(m.findByText(text, level)), ids(expected)) << text << " " << level;
    }
  }
  EXPECT_EQ(m.findByText("N-57").size(), 2u);
  ASSERT_NE(m.findById("L123"), nullptr);
  EXPECT_EQ(m.findById("L123")->id, "L123");
  EXPECT_EQ(m.findById("L123"), &m.landmarks()[123]);
  EXPECT_EQ(m.findById("nope"), nullptr);
}

TEST(HdMapTest, DistinctTextsAreSortedOnceEachAndFloorOnlyLeavesPillarsOut) {
  Landmark pillar = number("P1", "B1", "B1", 5.0, 0.0);
  pillar.cls = TextClass::kPillar;
  pillar.surface = Surface::kVertical;
  const HdMap map({number("N2", "B1-102", "B1", 0.0, 0.0), pillar,
                   number("N1", "B1-101", "B1", 2.0, 0.0), number("N3", "B1-101", "B2", 2.0, 0.0)},
                  "texts");
  EXPECT_EQ(distinctTexts(map), (std::vector<std::string>{"B1", "B1-101", "B1-102"}));
  EXPECT_EQ(distinctTexts(map, /*floor_only=*/true),
            (std::vector<std::string>{"B1-101", "B1-102"}));
}

TEST(HdMapTest, LevelsAreSortedOnceEachAndTextsKnowTheirLevels) {
  const HdMap map({number("a", "117", "B2", 0, 0), number("b", "117", "B1", 0, 0),
                   number("c", "201", "B2", 5, 0), number("d", "301", "B3", 9, 0)});
  EXPECT_EQ(distinctLevels(map), (std::vector<std::string>{"B1", "B2", "B3"}));
  EXPECT_EQ(levelsWithText(map, "117"), (std::set<std::string>{"B1", "B2"}));
  EXPECT_EQ(levelsWithText(map, "201"), (std::set<std::string>{"B2"}));
  EXPECT_TRUE(levelsWithText(map, "999").empty());
}

TEST(HdMapTest, ValidateRejectsDuplicateId) {
  EXPECT_EQ(HdMap::validate({number("a", "1", "B1", 0, 0), number("a", "2", "B1", 1, 0)}),
            "duplicate id 'a'");
}

TEST(HdMapTest, ValidateRejectsParkingNumberTwiceOnALevel) {
  EXPECT_EQ(HdMap::validate({number("a", "101", "B1", 0, 0), number("b", "101", "B1", 5, 0)}),
            "landmark 'b': parking number '101' appears twice on level 'B1'");
  EXPECT_EQ(HdMap::validate({number("a", "101", "B1", 0, 0), number("b", "101", "B2", 5, 0)}), "");
}

TEST(HdMapTest, ValidateRejectsBadSizesAndText) {
  Landmark l = number("a", "101", "B1", 0, 0);
  l.width = 0.0;
  EXPECT_EQ(HdMap::validate({l}), "landmark 'a': width and height must be positive");
  l = number("a", "", "B1", 0, 0);
  EXPECT_EQ(HdMap::validate({l}), "landmark 'a': empty text");
  l = number("a", "101", "B1", std::nan(""), 0);
  EXPECT_EQ(HdMap::validate({l}), "landmark 'a': non-finite value");
  l = number("a", "101", "B1", 0, 0);
  l.surface = Surface::kVertical;
  l.normal = {2.0, 0.0, 0.0};
  EXPECT_EQ(HdMap::validate({l}), "landmark 'a': vertical text needs a unit face normal");
}

TEST(HdMapTest, ConstructorThrowsOnInvalidLandmarks) {
  EXPECT_THROW(HdMap({number("a", "1", "B1", 0, 0), number("a", "2", "B1", 1, 0)}), InputError);
}

}  // namespace
}  // namespace parkloc::map
