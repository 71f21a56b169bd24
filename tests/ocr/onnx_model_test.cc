#include "ocr/onnx_model.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "common/error.h"

namespace parkloc::ocr {
namespace {

const std::string kDetector = std::string(PARKLOC_MODEL_DIR) + "/ch_PP-OCRv4_det_infer.onnx";

Tensor randomImage(int height, int width) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> value(-2.f, 2.f);
  Tensor t{{1, 3, height, width}, std::vector<float>(3 * height * width)};
  for (float& v : t.data) v = value(rng);
  return t;
}

// A model on the shared pool and one with a pool of its own compute the same map.
TEST(OnnxModel, ModelsOnTheSharedPoolAndOnTheirOwnAgree) {
  const OnnxModel shared(kDetector);
  const OnnxModel own(kDetector, OnnxOptions{1, 1});
  const Tensor input = randomImage(64, 96);
  const Tensor a = shared.run(input), b = own.run(input);
  ASSERT_EQ(a.shape, (std::vector<int64_t>{1, 1, 64, 96}));
  ASSERT_EQ(a.shape, b.shape);
  for (size_t i = 0; i < a.data.size(); ++i) ASSERT_NEAR(a.data[i], b.data[i], 1e-4f) << i;
}

// Two models on the shared pool run one after the other, each with its own result.
TEST(OnnxModel, TwoModelsOnTheSharedPoolKeepTheirResults) {
  const OnnxModel first(kDetector), second(kDetector);
  const Tensor small = randomImage(32, 32), large = randomImage(64, 128);
  const Tensor a1 = first.run(small), b = second.run(large), a2 = first.run(small);
  EXPECT_EQ(b.shape, (std::vector<int64_t>{1, 1, 64, 128}));
  EXPECT_EQ(a1.data, a2.data);
}

// The set-up rewrites PaddleOCR's models into the same function with fewer element-wise
// passes (tools/model_folding/fold_affine.py): what parkloc loads must compute what the models
// as shipped (third_party/models/paddleocr) do.
void expectTheShippedFunction(const std::string& file, int height, int width) {
  const std::string dir = PARKLOC_MODEL_DIR;
  const OnnxModel shipped(dir + "/paddleocr/" + file), folded(dir + "/" + file);
  const Tensor input = randomImage(height, width);
  const Tensor a = shipped.run(input), b = folded.run(input);
  ASSERT_EQ(a.shape, b.shape) << file;
  float worst = 0.f;
  for (size_t i = 0; i < a.data.size(); ++i)
    worst = std::max(worst, std::abs(a.data[i] - b.data[i]));
  EXPECT_LT(worst, 1e-4f) << file;
}

TEST(FoldedModels, TheDetectorComputesWhatPaddleOcrsDoes) {
  expectTheShippedFunction("ch_PP-OCRv4_det_infer.onnx", 96, 128);
}

TEST(FoldedModels, TheRecognizerComputesWhatPaddleOcrsDoes) {
  expectTheShippedFunction("ch_PP-OCRv4_rec_infer.onnx", 48, 320);
}

TEST(FoldedModels, TheDirectionClassifierComputesWhatPaddleOcrsDoes) {
  expectTheShippedFunction("ch_ppocr_mobile_v2.0_cls_infer.onnx", 48, 192);
}

TEST(OnnxModel, AMissingFileIsAnErrorNamingThePath) {
  try {
    OnnxModel model("/nonexistent/model.onnx");
    FAIL() << "no error";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/model.onnx"), std::string::npos);
  }
}

}  // namespace
}  // namespace parkloc::ocr
