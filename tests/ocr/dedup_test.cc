#include "ocr/ppocr/dedup.h"

#include <gtest/gtest.h>

namespace parkloc::ocr {
namespace {

TextInstance at(float x, float y, float w, float h, const std::string& text) {
  TextInstance inst;
  inst.polygon = {cv::Point2f(x, y), {x + w, y}, {x + w, y + h}, {x, y + h}};
  inst.text = text;
  return inst;
}

TEST(SeenBefore, AsksWhetherTheCentreLiesInOneOfTheFirstPolygons) {
  const std::vector<TextInstance> found = {at(0, 0, 100, 20, "A"), at(200, 0, 100, 20, "B")};
  EXPECT_TRUE(seenBefore(at(40, 5, 30, 10, "a"), found, 2));    // centre (55, 10) in A
  EXPECT_TRUE(seenBefore(at(80, 0, 40, 20, "a"), found, 2));    // centre (100, 10) on A's edge
  EXPECT_FALSE(seenBefore(at(120, 0, 40, 20, "c"), found, 2));  // centre (140, 10) between
  EXPECT_FALSE(seenBefore(at(220, 0, 40, 20, "b"), found, 1));  // B is not among the first one
  EXPECT_TRUE(seenBefore(at(220, 0, 40, 20, "b"), found, 2));
}

TEST(AppendUnseen, DropsWhatWasFoundBeforeButNotWhatItAddsItself) {
  std::vector<TextInstance> out = {at(0, 0, 100, 20, "A")};
  // The second and third overlap each other, not A: both stay (only earlier finds count).
  appendUnseen(out, {at(10, 0, 20, 20, "a"), at(300, 0, 100, 20, "C"), at(320, 0, 40, 20, "c")});
  ASSERT_EQ(out.size(), 3u);
  EXPECT_EQ(out[0].text, "A");
  EXPECT_EQ(out[1].text, "C");
  EXPECT_EQ(out[2].text, "c");
}

}  // namespace
}  // namespace parkloc::ocr
