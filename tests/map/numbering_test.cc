#include "map/numbering.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace parkloc::map {
namespace {

bool contains(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

TEST(NumberingFormat, ZoneLetterNumbersOpenTheirDigits) {
  const auto formats = learnNumbering({"D004", "C011", "C017", "C023", "D010"}, {});
  ASSERT_EQ(formats.size(), 2u);
  EXPECT_EQ(formats[0].pattern, "C###");  // most supported first
  EXPECT_EQ(formats[0].support, 3);
  EXPECT_EQ(formats[1].pattern, "D###");
}

TEST(NumberingFormat, OneReadingMakesNoFormat) {
  NumberingOptions options;
  options.min_support = 2;
  const auto formats = learnNumbering({"C011", "C017", "7X9"}, options);
  ASSERT_EQ(formats.size(), 1u);
  EXPECT_EQ(formats[0].pattern, "C###");
}

TEST(NumberingFormat, TheLevelDigitStaysWhatTheNumbersShow) {
  // The level digit is shared: part of the format; the bay numbers 086 to 103 and 50 either
  // side span K2-036 to K2-153.
  const auto formats = learnNumbering({"K2-086", "K2-103", "K2-091"}, {});
  ASSERT_EQ(formats.size(), 1u);
  EXPECT_EQ(formats[0].pattern, "K2-###");
  const auto lexicon = numberingLexicon(formats);
  EXPECT_EQ(lexicon.size(), 118u);
  EXPECT_EQ(lexicon.front(), "K2-036");
  EXPECT_EQ(lexicon.back(), "K2-153");
  // Near the start of the level's numbers the margin stops at K2-000, not in K1.
  EXPECT_EQ(numberingLexicon(learnNumbering({"K2-010", "K2-020"}, {})).front(), "K2-000");
}

TEST(NumberingFormat, OpenZoneLettersThatSpanTooMuchCloseAgain) {
  // C001 to C300 in every zone would be 26 x 351 numbers: each zone letter is a format of its
  // own instead.
  NumberingOptions options;
  options.open_letters = true;
  const auto formats = learnNumbering({"C001", "C300", "D010", "D020"}, options);
  ASSERT_EQ(formats.size(), 2u);
  EXPECT_EQ(formats[0].pattern, "C###");
  EXPECT_EQ(formats[1].pattern, "D###");
}

TEST(NumberingFormat, ALearntFormatSpansTheNumbersNearThoseRead) {
  NumberingOptions options;
  options.range_margin = 50;
  const auto formats = learnNumbering({"001", "019", "023"}, options);
  ASSERT_EQ(formats.size(), 1u);
  EXPECT_EQ(formats[0].first, 0);
  EXPECT_EQ(formats[0].last, 73);
  const auto lexicon = numberingLexicon(formats);
  EXPECT_EQ(lexicon.size(), 74u);
  EXPECT_TRUE(contains(lexicon, "008"));   // missed by the first reading
  EXPECT_FALSE(contains(lexicon, "800"));  // 008 upside down
  EXPECT_FALSE(contains(lexicon, "111"));
}

TEST(NumberingFormat, ZoneLettersThatDifferOpenToEveryCapital) {
  NumberingOptions options;
  options.open_letters = true;
  const auto formats = learnNumbering({"C004", "C009", "D002", "K2-086", "K2-091"}, options);
  ASSERT_EQ(formats.size(), 2u);
  EXPECT_EQ(formats[0].pattern, "@###");    // C and D differ: a zone letter
  EXPECT_EQ(formats[1].pattern, "K2-###");  // K2 is shared: part of the format
  const auto lexicon = numberingLexicon({formats[0]});
  EXPECT_EQ(lexicon.size(), 26u * 60u);  // 000 to 059 in every zone
  EXPECT_TRUE(contains(lexicon, "B008"));
  EXPECT_FALSE(contains(lexicon, "B060"));
  EXPECT_EQ(numberingEnds(formats[0]), std::make_pair(lexicon.front(), lexicon.back()));
  EXPECT_EQ(lexicon.front(), "A000");
  EXPECT_EQ(lexicon.back(), "Z059");
  // Closed, C and D are formats of their own; D has one number only.
  const auto closed = learnNumbering({"C004", "C009", "D002"}, {});
  ASSERT_EQ(closed.size(), 1u);
  EXPECT_EQ(closed[0].pattern, "C###");
}

TEST(NumberingFormat, AFormatSpanningTooManyNumbersIsDropped) {
  NumberingOptions options;
  options.max_strings = 100;
  EXPECT_TRUE(learnNumbering({"12-34", "56-78"}, options).empty());  // 1184 to 5728
}

TEST(NumberingFormat, TextsWithoutDigitsHaveNoFormat) {
  EXPECT_TRUE(learnNumbering({"EXIT", "EXIT", "EXIT"}, {}).empty());
}

TEST(NumberingFormat, TheLexiconSpansEveryFormatOnce) {
  const auto lexicon = numberingLexicon({{"C0#", 2}, {"C0#", 0}, {"B#", 1}});
  EXPECT_EQ(lexicon.size(), 20u);
  EXPECT_TRUE(contains(lexicon, "C00"));
  EXPECT_TRUE(contains(lexicon, "C09"));
  EXPECT_TRUE(contains(lexicon, "B5"));
  EXPECT_FALSE(contains(lexicon, "C10"));
}

TEST(NumberingFormat, ValidFormatsHaveAnOpenDigitAndABoundedSpan) {
  EXPECT_TRUE(validNumbering("C###", 2000));
  EXPECT_FALSE(validNumbering("C011", 2000));    // nothing open
  EXPECT_FALSE(validNumbering("C ###", 2000));   // a space
  EXPECT_FALSE(validNumbering("K#-###", 2000));  // 10000 numbers
  EXPECT_FALSE(validNumbering("", 2000));
}

TEST(NumberingFormat, NumbersApartCountsBaysWithinOneFormat) {
  EXPECT_EQ(numbersApart("B2-047", "B2-048"), 1);
  EXPECT_EQ(numbersApart("019", "070"), 51);
  EXPECT_EQ(numbersApart("C099", "C100"), 1);
  EXPECT_EQ(numbersApart("131", "131"), 0);
  EXPECT_FALSE(numbersApart("C021", "021").has_value());   // lengths differ
  EXPECT_FALSE(numbersApart("C021", "D022").has_value());  // zones differ
  EXPECT_FALSE(numbersApart("1A1", "111").has_value());    // a letter where a digit is
  EXPECT_FALSE(numbersApart("EXIT", "EXIT").has_value());  // no digit
}

}  // namespace
}  // namespace parkloc::map
