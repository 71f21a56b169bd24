#include "mapping/row_sequence.h"

#include <gtest/gtest.h>

namespace parkloc::mapping {
namespace {

// A row along x, numbers growing with x, bays 2.5 m wide and a pillar's 3.2 m every third:
// 273 at 12.7 m and 274 at 15.2 m; another row 7 m away across the aisle.
std::vector<PlacedNumber> rowOfTwo() {
  return {{"273", {12.7, 4.2}}, {"274", {15.2, 4.2}}, {"246", {12.7, -3.0}}};
}

TEST(RowSequence, ConsecutiveLandmarksMakeARowThatCountsTheBaysAlongIt) {
  const RowSequence rows(rowOfTwo(), {});
  EXPECT_EQ(rows.segments(), 1u);
  // 16.4 m back from 273, the true 267 six bays on (pillars between): between 16.4 / 3.3
  // and 16.4 / 2.3 bays.
  EXPECT_TRUE(rows.allows("267", {-3.7, 4.2}));
  EXPECT_TRUE(rows.allows("268", {-3.7, 4.2}));   // a looser count far away
  EXPECT_FALSE(rows.allows("292", {-3.7, 4.2}));  // a misread: the wrong way and too far
  EXPECT_FALSE(rows.allows("279", {-3.7, 4.2}));  // numbers grow the other way
  EXPECT_FALSE(rows.allows("271", {-3.7, 4.2}));  // too few bays for 16 m
  // Next to 274 the next number, on the line only.
  EXPECT_TRUE(rows.allows("275", {17.7, 4.3}));
  EXPECT_FALSE(rows.allows("275", {17.7, 6.0}));
  EXPECT_FALSE(rows.allows("C275", {17.7, 4.3}));  // another format
  // Off the row (across the aisle), or beyond its reach, it allows nothing.
  EXPECT_FALSE(rows.allows("247", {12.7, -3.0}));
  EXPECT_FALSE(rows.allows("272", {12.7, -3.0}));
  EXPECT_TRUE(rows.allows("281", {34.7, 4.2}));   // 19.5 m on: 6 to 8 bays
  EXPECT_FALSE(rows.allows("283", {38.0, 4.2}));  // beyond 20 m
}

TEST(RowSequence, LandmarksFarApartOrNotConsecutiveMakeNoRow) {
  const RowSequence far({{"273", {0.0, 0.0}}, {"274", {6.0, 0.0}}}, {});
  EXPECT_EQ(far.segments(), 0u);
  const RowSequence gap({{"273", {0.0, 0.0}}, {"275", {2.5, 0.0}}}, {});
  EXPECT_EQ(gap.segments(), 0u);
  EXPECT_FALSE(gap.allows("276", {5.0, 0.0}));
}

}  // namespace
}  // namespace parkloc::mapping
