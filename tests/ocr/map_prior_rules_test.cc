#include "ocr/ppocr/map_prior_rules.h"

#include <gtest/gtest.h>

namespace parkloc::ocr {
namespace {

// An instance read freely (no lexicon match) as `reading`.
TextInstance freelyRead(const std::string& reading) {
  TextInstance inst;
  inst.text = inst.raw_text = reading;
  return inst;
}

TEST(OneEndRule, TakesAFreeReadingOfOneEndOfThePlacedTextAsThatText) {
  const std::vector<std::string> placed = {"C008", "C018"};
  ReadJob job;
  job.placed_near = &placed;
  TextInstance inst = freelyRead("008");
  applyOneEndRule(inst, job, MapPriorOptions{});
  EXPECT_EQ(inst.text, "C008");
  EXPECT_TRUE(inst.lexicon_match);
  EXPECT_TRUE(inst.partial);
  EXPECT_EQ(inst.raw_text, "008");
}

TEST(OneEndRule, LeavesOtherReadingsAndBoxesAlone) {
  const std::vector<std::string> placed = {"C008", "C018"};
  ReadJob on_text;
  on_text.placed_near = &placed;
  TextInstance other = freelyRead("XY");  // no end of a placed text
  applyOneEndRule(other, on_text, MapPriorOptions{});
  EXPECT_EQ(other.text, "XY");
  EXPECT_FALSE(other.lexicon_match);
  TextInstance unread = freelyRead("");  // nothing read: nothing to match
  unread.raw_text = "008";
  applyOneEndRule(unread, on_text, MapPriorOptions{});
  EXPECT_EQ(unread.text, "");
  TextInstance off_text = freelyRead("008");  // a box on no placed text
  applyOneEndRule(off_text, ReadJob{}, MapPriorOptions{});
  EXPECT_EQ(off_text.text, "008");
  MapPriorOptions no_parts;
  no_parts.min_cut_part_chars = 0;
  TextInstance without = freelyRead("008");
  applyOneEndRule(without, on_text, no_parts);
  EXPECT_EQ(without.text, "008");
}

}  // namespace
}  // namespace parkloc::ocr
