#include "ocr/onnx_model.h"

#include <gtest/gtest.h>

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
