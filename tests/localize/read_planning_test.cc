#include "localize/read_planning.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace parkloc::localize {
namespace {

map::Landmark number(const std::string& text, double x) {
  map::Landmark l;
  l.id = "B1:" + text;
  l.text = text;
  l.cls = map::TextClass::kParkingNumber;
  l.level = "B1";
  l.position = {x, 3.0, 0.0};
  l.width = 1.0;
  l.height = 0.5;
  return l;
}

// The lexicon of camera 0's full frame before the first fix.
std::vector<std::string> searchLexicon(const map::HdMap& map) {
  const geometry::Rig rig = geometry::defaultRig();
  const FloorHeights floors(map);
  ReadPlanner planner(rig, rig, map, floors, ReadingOptions{}, /*guided=*/true);
  const PoseEkf ekf;
  const LevelEstimate level(map, LevelOptions{}, "B1");
  ReadPlan plan = planner.plan(/*tracking=*/false, ekf, level, std::nullopt, false, false);
  for (size_t c = 0; c < rig.cameras.size(); ++c)
    if (plan.choice.full_frame[c]) return planner.request(c, plan, {}).lexicon;
  return {};
}

bool contains(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

TEST(ReadPlanning, AMapBuiltFromDrivesLetsTheNumbersItLacksCompete) {
  const std::vector<map::Landmark> numbers = {number("C004", 0.0), number("C008", 2.5),
                                              number("D002", 5.0)};
  // Complete: the full frame reads against the map's texts only.
  const auto complete = searchLexicon(map::HdMap(numbers));
  EXPECT_EQ(complete.size(), 3u);
  // Built (not complete): B008 is a number of the garage that the map lacks; read as itself,
  // it matches no landmark instead of being taken for C008.
  const auto built = searchLexicon(map::HdMap(numbers, "built", {}, /*complete=*/false));
  EXPECT_TRUE(contains(built, "C008"));
  EXPECT_TRUE(contains(built, "B008"));
  EXPECT_TRUE(contains(built, "D058"));
  EXPECT_FALSE(contains(built, "C059"));  // beyond 50 past the largest known number, 008
}

}  // namespace
}  // namespace parkloc::localize
