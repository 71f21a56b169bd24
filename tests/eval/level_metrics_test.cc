#include "eval/level_metrics.h"

#include <gtest/gtest.h>

namespace parkloc::eval {
namespace {

map::Landmark landmark(const std::string& text, const std::string& level, double x) {
  map::Landmark l;
  l.id = level + "/" + text;
  l.text = text;
  l.level = level;
  l.position = {x, 0.0, 0.0};
  l.width = 0.9;
  l.height = 0.4;
  return l;
}

TEST(LevelMetricsTest, TextsTellTheLevelWhenNotOnEveryLevel) {
  const map::HdMap map({landmark("117", "B1", 0), landmark("117", "B2", 0),
                        landmark("A-1", "B2", 5)});
  EXPECT_FALSE(tellsLevel(map, "117"));
  EXPECT_TRUE(tellsLevel(map, "A-1"));
  EXPECT_TRUE(tellsLevel(map, "b1"));  // names a level
  EXPECT_FALSE(tellsLevel(map, "999"));
  const map::HdMap one({landmark("A-1", "B2", 5)});
  EXPECT_FALSE(tellsLevel(one, "A-1"));  // one level: nothing to tell
}

LevelFrame frame(double t, const std::string& truth, bool telling, const std::string& level,
                 bool decided) {
  LevelFrame f;
  f.timestamp = t;
  f.truth = truth;
  f.telling_text_in_view = telling;
  f.has_pose = true;
  f.level = level;
  f.decided = decided;
  return f;
}

TEST(LevelMetricsTest, DelaysCountFromTheFirstTellingTextPerStretch) {
  const std::vector<LevelFrame> drive = {
      frame(0.0, "B1", false, "B1", false), frame(1.0, "B1", true, "B1", false),
      frame(2.0, "B1", false, "B1", true),  frame(3.0, "B1", false, "B2", true),  // wrong
      frame(4.0, "B2", false, "B1", false), frame(5.0, "B2", true, "B1", false),
      frame(6.5, "B2", true, "B2", true)};
  const LevelScore s = scoreLevels(drive);
  EXPECT_EQ(s.frames, 7u);
  EXPECT_EQ(s.decided, 3u);
  EXPECT_EQ(s.decided_right, 2u);
  EXPECT_NEAR(s.rightWhereDecided(), 2.0 / 3.0, 1e-12);
  ASSERT_EQ(s.decision_delays_s.size(), 1u);
  EXPECT_DOUBLE_EQ(s.decision_delays_s[0], 1.0);
  ASSERT_EQ(s.change_delays_s.size(), 1u);
  EXPECT_DOUBLE_EQ(s.change_delays_s[0], 1.5);
  EXPECT_EQ(s.changes, 1u);
  EXPECT_EQ(s.stretches_never_decided, 0u);
}

TEST(LevelMetricsTest, AStretchThatNeverDecidesIsCounted) {
  const LevelScore s = scoreLevels({frame(0.0, "B1", true, "B1", false),
                                    frame(1.0, "B1", true, "B2", true)});
  EXPECT_TRUE(s.decision_delays_s.empty());
  EXPECT_EQ(s.stretches_never_decided, 1u);
}

}  // namespace
}  // namespace parkloc::eval
