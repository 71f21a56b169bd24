#pragma once
// The three PaddleOCR networks with their pre-processing: DB text detection, CRNN/SVTR
// recognition with CTC output, and the 0/180 degree direction classifier.
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "ocr/ctc.h"
#include "ocr/onnx_model.h"

namespace parkloc::ocr {

// Detection: the probability map of each image of a batch (all the same size, both sides
// multiples of 32), CV_32F at input resolution.
class DbDetector {
 public:
  DbDetector(const std::string& model_path, const OnnxOptions& options);
  std::vector<cv::Mat> probability(const std::vector<cv::Mat>& images_bgr) const;

 private:
  OnnxModel model_;
};

// Recognition output of one crop: [steps x classes] probabilities.
struct RecognitionOutput {
  std::vector<float> probs;
  int steps = 0;
  int classes = 0;
  CtcMatrix matrix() const { return {probs.data(), steps, classes}; }
};

class CtcRecognizer {
 public:
  static constexpr int kHeight = 48;
  // The crop widths the spotter reads, and the training crops are exported at: narrower
  // crops are padded, wider ones squeezed.
  static constexpr int kMinWidth = 16;
  static constexpr int kMaxWidth = 480;
  // Every input is at least this wide, the crops padded on the right, as PaddleOCR feeds its
  // recognizer (rec_image_shape 3,48,320): it was trained on text at the left of such inputs
  // and misreads a short crop fed at its own width (parking numbers of the test split read
  // from their exact boxes: 21.8 % at their own width, 39.1 % padded; docs/OCR.md).
  static constexpr int kInputWidth = 320;
  CtcRecognizer(const std::string& model_path, const OnnxOptions& options);
  // Crops are 8-bit BGR, kHeight rows tall; batched by similar width, padded on the right to
  // the batch's widest and at least kInputWidth.
  std::vector<RecognitionOutput> recognize(const std::vector<cv::Mat>& crops, int batch_size) const;

 private:
  OnnxModel model_;
};

class DirectionClassifier {
 public:
  DirectionClassifier(const std::string& model_path, const OnnxOptions& options);
  // Probability that each crop is upside down (180 degrees).
  std::vector<float> upsideDownProbability(const std::vector<cv::Mat>& crops) const;

 private:
  OnnxModel model_;
};

}  // namespace parkloc::ocr
