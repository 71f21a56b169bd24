#include "mapping/numbering_format.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace parkloc::mapping {
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

TEST(NumberingFormat, SharedLeadingDigitsAreHeldUntilTheSpanFits) {
  // Four digits would span 10000: the level digit every number shares is held, the bay
  // number's hundreds (also shared here) stay open because the span already fits.
  const auto formats = learnNumbering({"K2-086", "K2-103", "K2-091"}, {});
  ASSERT_EQ(formats.size(), 1u);
  EXPECT_EQ(formats[0].pattern, "K2-###");
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

TEST(NumberingFormat, AFormatThatCannotBeNarrowedIsDropped) {
  NumberingOptions options;
  options.max_strings = 100;
  // No digit is shared: "##-##" would span 10000.
  EXPECT_TRUE(learnNumbering({"12-34", "56-78"}, options).empty());
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

}  // namespace
}  // namespace parkloc::mapping
