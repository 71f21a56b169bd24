// levels.csv: round trip, the level-at-time lookup, one test per bad-input case.
#include "io/levels_csv.h"

#include <gtest/gtest.h>

#include "common/error.h"
#include "io/tum.h"
#include "test_dir.h"

namespace parkloc::io {
namespace {

class LevelsCsvTest : public testing::TempDirTest {
 protected:
  std::string errorFor(const std::string& text) const {
    const std::string p = write("levels.csv", text);
    try {
      loadLevels(p);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
  std::string at(int line) const {
    return "levels " + path("levels.csv") + ":" + std::to_string(line);
  }
};

TEST_F(LevelsCsvTest, RoundTripKeepsTimesAndNames) {
  std::vector<StampedLevel> levels;
  for (int k = 0; k < 301; ++k) levels.push_back({k / 10.0, k < 150 ? "B1" : "P-2 east"});
  saveLevels(levels, path("levels.csv"));
  const auto back = loadLevels(path("levels.csv"));
  ASSERT_EQ(back.size(), levels.size());
  for (size_t i = 0; i < levels.size(); ++i) {
    EXPECT_NEAR(back[i].timestamp, levels[i].timestamp, 1e-9);
    EXPECT_EQ(back[i].level, levels[i].level);
  }
}

TEST_F(LevelsCsvTest, TimestampsAreWrittenAsPosesTumWritesThem) {
  const std::vector<double> times = {0.0, 0.1, 2.9000000001, 1234.5};
  std::vector<StampedLevel> levels;
  std::vector<StampedPose> poses;
  for (double t : times) {
    levels.push_back({t, "B2"});
    poses.push_back({t, geometry::Rigid3::Identity()});
  }
  saveLevels(levels, path("levels.csv"));
  saveTum(poses, path("poses.tum"));
  const auto l = loadLevels(path("levels.csv"));
  const auto p = loadTum(path("poses.tum"));
  ASSERT_EQ(l.size(), p.size());
  for (size_t i = 0; i < l.size(); ++i) EXPECT_EQ(l[i].timestamp, p[i].timestamp) << i;
}

TEST_F(LevelsCsvTest, ParsesSpacesCarriageReturnsAndBlankLines) {
  const auto levels =
      loadLevels(write("levels.csv", "timestamp,level\r\n0.0, B1\r\n\n 0.5 ,B2 \n   \n"));
  ASSERT_EQ(levels.size(), 2u);
  EXPECT_EQ(levels[0].timestamp, 0.0);
  EXPECT_EQ(levels[0].level, "B1");
  EXPECT_EQ(levels[1].timestamp, 0.5);
  EXPECT_EQ(levels[1].level, "B2");
}

TEST_F(LevelsCsvTest, LevelAtIsTheLastRowAtOrBeforeTheTime) {
  const std::vector<StampedLevel> levels = {{0.0, "B1"}, {0.1, "B1"}, {0.2, "B2"}, {0.3, "B2"}};
  EXPECT_EQ(levelAt(levels, -0.01), std::nullopt);
  EXPECT_EQ(levelAt(levels, 0.0), "B1");
  EXPECT_EQ(levelAt(levels, 0.19), "B1");
  // A time read back from an image name ("0.200000") a hair under the row's time.
  EXPECT_EQ(levelAt(levels, 0.2 - 4e-7), "B2");
  EXPECT_EQ(levelAt(levels, 0.2), "B2");
  EXPECT_EQ(levelAt(levels, 99.0), "B2");
  EXPECT_EQ(levelAt({}, 1.0), std::nullopt);
}

TEST_F(LevelsCsvTest, MissingHeaderIsRejected) {
  EXPECT_EQ(errorFor("0.0,B1\n"), at(1) + ": expected the header 'timestamp,level'");
  EXPECT_EQ(errorFor(""), at(1) + ": expected the header 'timestamp,level'");
}

TEST_F(LevelsCsvTest, WrongColumnCountNamesTheLine) {
  EXPECT_EQ(errorFor("timestamp,level\n0.0,B1\n0.1\n"),
            at(3) + ": malformed row '0.1' (expected 'timestamp,level')");
  EXPECT_EQ(errorFor("timestamp,level\n0.1,B1,B2\n"),
            at(2) + ": malformed row '0.1,B1,B2' (expected 'timestamp,level')");
}

TEST_F(LevelsCsvTest, TimestampMustBeAFiniteNumber) {
  EXPECT_EQ(errorFor("timestamp,level\nzero,B1\n"), at(2) + ": timestamp 'zero' is not a number");
  EXPECT_EQ(errorFor("timestamp,level\n,B1\n"), at(2) + ": timestamp '' is not a number");
  EXPECT_EQ(errorFor("timestamp,level\nnan,B1\n"), at(2) + ": non-finite timestamp");
  EXPECT_EQ(errorFor("timestamp,level\ninf,B1\n"), at(2) + ": non-finite timestamp");
}

TEST_F(LevelsCsvTest, TimestampsMustIncrease) {
  EXPECT_EQ(errorFor("timestamp,level\n0.0,B1\n0.1,B1\n0.1,B2\n"),
            at(4) + ": timestamp 0.1 is not after the previous one (0.1)");
}

TEST_F(LevelsCsvTest, EmptyLevelNameIsRejected) {
  EXPECT_EQ(errorFor("timestamp,level\n0.0,  \n"), at(2) + ": empty level name");
}

TEST_F(LevelsCsvTest, NamesARowCannotHoldAreNotWritten) {
  for (const std::string bad : {"", "B1,B2", "B1\nB2"}) {
    EXPECT_THROW(saveLevels({{0.0, bad}}, path("out.csv")), InputError) << bad;
  }
}

TEST_F(LevelsCsvTest, MissingFileIsAnIoError) {
  EXPECT_THROW(loadLevels(path("none.csv")), IoError);
}

}  // namespace
}  // namespace parkloc::io
