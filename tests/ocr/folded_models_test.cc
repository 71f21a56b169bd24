// The set-up rewrites PaddleOCR's models into the same function with fewer element-wise
// passes (tools/model_folding/fold_affine.py): what parkloc loads must compute what the
// models as shipped (third_party/models/paddleocr) do.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "ocr/onnx_model.h"

namespace parkloc::ocr {
namespace {

const std::string kModels = PARKLOC_MODEL_DIR;

Tensor randomInput(int height, int width) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> value(-2.f, 2.f);
  Tensor t{{1, 3, height, width}, std::vector<float>(3 * height * width)};
  for (float& v : t.data) v = value(rng);
  return t;
}

void expectSameFunction(const std::string& file, int height, int width) {
  const OnnxModel shipped(kModels + "/paddleocr/" + file), folded(kModels + "/" + file);
  const Tensor input = randomInput(height, width);
  const Tensor a = shipped.run(input), b = folded.run(input);
  ASSERT_EQ(a.shape, b.shape) << file;
  float worst = 0.f;
  for (size_t i = 0; i < a.data.size(); ++i)
    worst = std::max(worst, std::abs(a.data[i] - b.data[i]));
  EXPECT_LT(worst, 1e-4f) << file;
}

TEST(FoldedModels, TheDetectorComputesWhatPaddleOcrsDoes) {
  expectSameFunction("ch_PP-OCRv4_det_infer.onnx", 96, 128);
}

TEST(FoldedModels, TheRecognizerComputesWhatPaddleOcrsDoes) {
  expectSameFunction("ch_PP-OCRv4_rec_infer.onnx", 48, 320);
}

TEST(FoldedModels, TheDirectionClassifierComputesWhatPaddleOcrsDoes) {
  expectSameFunction("ch_ppocr_mobile_v2.0_cls_infer.onnx", 48, 192);
}

}  // namespace
}  // namespace parkloc::ocr
