#include "ocr/cut_parts.h"

#include <gtest/gtest.h>

namespace parkloc::ocr {
namespace {

using Texts = std::vector<std::string>;

TEST(PartsLeftByACut, AreTheEndsThatShowLongestFirst) {
  EXPECT_EQ(partsLeftByACut("C008", true, false, 2), (Texts{"008", "08"}));
  EXPECT_EQ(partsLeftByACut("C008", false, true, 2), (Texts{"C00", "C0"}));
  EXPECT_EQ(partsLeftByACut("C008", true, true, 3), (Texts{"008", "C00"}));
  EXPECT_TRUE(partsLeftByACut("C008", false, false, 1).empty());
  EXPECT_TRUE(partsLeftByACut("C8", true, true, 2).empty());
  EXPECT_EQ(partsLeftByACut("B2-117", true, false, 5), (Texts{"2-117"}));
}

TEST(WithCutParts, AddsTheUnambiguousPartsOfAtLeastHalfEachStandingForItsWhole) {
  // Cut at the start: C008 leaves 008 and 08; C018 leaves 018 and 18. Cut at the end both leave
  // C0, which stands for neither.
  const CutCandidates c = withCutParts({"C008", "C018"}, true, true, 2);
  const Texts expected_texts = {"C008", "C018", "008", "C00", "08", "018", "C01", "18"};
  const Texts expected_whole = {"C008", "C018", "C008", "C008", "C008", "C018", "C018", "C018"};
  EXPECT_EQ(c.texts, expected_texts);
  EXPECT_EQ(c.whole, expected_whole);
  // Half a six-character text is three characters; "117" is also a text of its own.
  const CutCandidates d = withCutParts({"B2-117", "117"}, true, false, 2);
  EXPECT_EQ(d.texts, (Texts{"B2-117", "117", "2-117", "-117", "17"}));
  EXPECT_EQ(d.whole, (Texts{"B2-117", "117", "B2-117", "B2-117", "117"}));
  const CutCandidates none = withCutParts({"C008"}, false, false, 2);
  EXPECT_EQ(none.texts, (Texts{"C008"}));
}

TEST(WholeOfPart, IsTheTextAReadingIsOneEndOfGlyphForGlyph) {
  const CutCandidates parts = withCutParts({"D008", "D009", "C008"}, true, true, 2);
  EXPECT_EQ(wholeOfPart("09", parts), std::optional<std::string>("D009"));
  EXPECT_EQ(wholeOfPart("009", parts), std::optional<std::string>("D009"));
  EXPECT_EQ(wholeOfPart("C0", parts), std::optional<std::string>("C008"));
  EXPECT_EQ(wholeOfPart("CO", parts), std::optional<std::string>("C008"));  // O looks like 0
  EXPECT_FALSE(wholeOfPart("08", parts));    // the end of D008 and of C008
  EXPECT_FALSE(wholeOfPart("D0", parts));    // the start of two texts
  EXPECT_FALSE(wholeOfPart("D009", parts));  // a whole text
  EXPECT_FALSE(wholeOfPart("9", parts));     // under half of any text
  EXPECT_FALSE(wholeOfPart("07", parts));    // no part
}

}  // namespace
}  // namespace parkloc::ocr
