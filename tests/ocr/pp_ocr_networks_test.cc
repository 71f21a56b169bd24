#include "ocr/ppocr/pp_ocr_networks.h"

#include <gtest/gtest.h>

#include "synthetic_text.h"

namespace parkloc::ocr {
namespace {

const std::string kRecognizer = std::string(PARKLOC_MODEL_DIR) + "/ch_PP-OCRv4_rec_infer.onnx";

cv::Mat crop(const std::string& text, int width) {
  cv::Mat line = testing::renderTextLine(text, 30, 8), out;
  cv::resize(line, out, {width, CtcRecognizer::kHeight}, 0, 0, cv::INTER_AREA);
  return out;
}

// PaddleOCR's input width: a short crop is padded to it, so it is read the same alone or
// batched beside a wider crop (before, the batch's widest crop set the padding).
TEST(CtcRecognizer, AShortCropIsPaddedToTheInputWidthAloneOrInABatch) {
  const CtcRecognizer recognizer(kRecognizer, {});
  const cv::Mat short_crop = crop("A7", 40), wide_crop = crop("B2-117 LIFT", 300);
  const auto alone = recognizer.recognize({short_crop}, 1);
  const auto batched = recognizer.recognize({short_crop, wide_crop}, 2);
  ASSERT_EQ(alone.size(), 1u);
  ASSERT_EQ(batched.size(), 2u);
  EXPECT_EQ(alone[0].steps, CtcRecognizer::kInputWidth / 8);  // one step per 8 columns
  ASSERT_EQ(alone[0].probs.size(), batched[0].probs.size());
  for (size_t i = 0; i < alone[0].probs.size(); ++i)
    ASSERT_NEAR(alone[0].probs[i], batched[0].probs[i], 1e-4f) << i;
}

// A crop wider than the input width widens its batch instead of being cut.
TEST(CtcRecognizer, ACropWiderThanTheInputWidthWidensItsBatch) {
  const CtcRecognizer recognizer(kRecognizer, {});
  const auto out = recognizer.recognize({crop("A7", 40), crop("B2-117 B2-118 B2-119", 440)}, 2);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].steps, 440 / 8);
  EXPECT_EQ(out[1].steps, 440 / 8);
}

}  // namespace
}  // namespace parkloc::ocr
