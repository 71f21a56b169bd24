#include "localize/level_vote.h"

#include <gtest/gtest.h>

namespace parkloc::localize {
namespace {

map::Landmark landmark(const std::string& text, const std::string& level) {
  map::Landmark l;
  l.id = level + "/" + text;
  l.text = text;
  l.level = level;
  l.cls = map::TextClass::kParkingNumber;
  l.width = 0.9;
  l.height = 0.4;
  return l;
}

// "117" is painted on both levels, "201" on B2 only, "301" on B1 only.
map::HdMap twoLevels() {
  return map::HdMap(
      {landmark("117", "B1"), landmark("117", "B2"), landmark("201", "B2"), landmark("301", "B1")},
      "two levels");
}

std::vector<CameraResult> seeing(const std::vector<std::string>& texts) {
  CameraResult c;
  for (const auto& t : texts) {
    ocr::TextInstance i;
    i.text = t;
    i.cls = map::TextClass::kParkingNumber;
    c.instances.push_back(i);
  }
  return {c};
}

TEST(LevelVoteTest, TheLevelWithMostTextsWinsAndATieDecidesNothing) {
  const map::HdMap map = twoLevels();
  LevelVote vote;
  vote.update(seeing({"117"}), map, false);
  EXPECT_EQ(vote.current(), "");  // on both levels: a tie
  vote.update(seeing({"117", "201"}), map, false);
  EXPECT_EQ(vote.current(), "B2");
  // While not settled, the vote goes on.
  vote.update(seeing({"301", "117"}), map, false);
  EXPECT_EQ(vote.current(), "B1");
}

TEST(LevelVoteTest, ASettledLevelHoldsAndAGivenLevelIsNeverVotedOn) {
  const map::HdMap map = twoLevels();
  LevelVote vote;
  vote.update(seeing({"201"}), map, true);  // settled, but no level yet: votes
  EXPECT_EQ(vote.current(), "B2");
  vote.update(seeing({"301"}), map, true);
  EXPECT_EQ(vote.current(), "B2");
  LevelVote given("B1");
  given.update(seeing({"201"}), map, false);
  EXPECT_EQ(given.current(), "B1");
}

}  // namespace
}  // namespace parkloc::localize
