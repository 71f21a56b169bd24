#include "ocr/ppocr/pp_ocr_networks.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <opencv2/imgproc.hpp>

namespace parkloc::ocr {
namespace {

// Writes an 8-bit BGR image into an NCHW float tensor slot as (x / 255 - mean) / std per
// channel, in PaddleOCR's channel order (it feeds OpenCV's BGR as is). Columns beyond the
// image width stay as they are (zero padding).
void packImage(const cv::Mat& bgr, const float mean[3], const float stdev[3], int width,
               float* slot) {
  const int h = bgr.rows;
  const size_t plane = static_cast<size_t>(h) * width;
  for (int y = 0; y < h; ++y) {
    const auto* row = bgr.ptr<cv::Vec3b>(y);
    for (int x = 0; x < bgr.cols; ++x)
      for (int c = 0; c < 3; ++c)
        slot[c * plane + static_cast<size_t>(y) * width + x] =
            (row[x][c] / 255.f - mean[c]) / stdev[c];
  }
}

constexpr float kDetMean[3] = {0.485f, 0.456f, 0.406f};
constexpr float kDetStd[3] = {0.229f, 0.224f, 0.225f};
constexpr float kRecMean[3] = {0.5f, 0.5f, 0.5f};
constexpr float kRecStd[3] = {0.5f, 0.5f, 0.5f};

}  // namespace

DbDetector::DbDetector(const std::string& model_path, const OnnxOptions& options)
    : model_(model_path, options) {}

std::vector<cv::Mat> DbDetector::probability(const std::vector<cv::Mat>& images) const {
  if (images.empty()) return {};
  const int h = images[0].rows, w = images[0].cols;
  Tensor input;
  input.shape = {static_cast<int64_t>(images.size()), 3, h, w};
  const size_t slot = 3 * static_cast<size_t>(h) * w;
  input.data.assign(slot * images.size(), 0.f);
  for (size_t i = 0; i < images.size(); ++i) {
    CV_Assert(images[i].rows == h && images[i].cols == w && images[i].type() == CV_8UC3);
    packImage(images[i], kDetMean, kDetStd, w, input.data.data() + i * slot);
  }
  const Tensor out = model_.run(input);
  const int oh = static_cast<int>(out.shape[2]), ow = static_cast<int>(out.shape[3]);
  std::vector<cv::Mat> maps;
  for (size_t i = 0; i < images.size(); ++i) {
    cv::Mat map(oh, ow, CV_32F, const_cast<float*>(out.data.data()) + i * oh * ow);
    maps.push_back(map.clone());
  }
  return maps;
}

CtcRecognizer::CtcRecognizer(const std::string& model_path, const OnnxOptions& options)
    : model_(model_path, options) {}

std::vector<RecognitionOutput> CtcRecognizer::recognize(const std::vector<cv::Mat>& crops,
                                                        int batch_size) const {
  std::vector<RecognitionOutput> outputs(crops.size());
  // Batch crops of similar width so little of each batch is padding.
  std::vector<size_t> order(crops.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](size_t a, size_t b) { return crops[a].cols < crops[b].cols; });
  batch_size = std::max(batch_size, 1);
  for (size_t begin = 0; begin < order.size(); begin += batch_size) {
    const size_t end = std::min(order.size(), begin + batch_size);
    int width = kInputWidth;
    for (size_t k = begin; k < end; ++k) width = std::max(width, crops[order[k]].cols);
    width = (width + 7) / 8 * 8;
    Tensor input;
    input.shape = {static_cast<int64_t>(end - begin), 3, kHeight, width};
    const size_t slot = 3 * static_cast<size_t>(kHeight) * width;
    input.data.assign(slot * (end - begin), 0.f);
    for (size_t k = begin; k < end; ++k) {
      const cv::Mat& crop = crops[order[k]];
      CV_Assert(crop.rows == kHeight && crop.type() == CV_8UC3);
      packImage(crop, kRecMean, kRecStd, width, input.data.data() + (k - begin) * slot);
    }
    const Tensor out = model_.run(input);
    const int steps = static_cast<int>(out.shape[1]), classes = static_cast<int>(out.shape[2]);
    const size_t per = static_cast<size_t>(steps) * classes;
    for (size_t k = begin; k < end; ++k) {
      RecognitionOutput& o = outputs[order[k]];
      o.steps = steps;
      o.classes = classes;
      const float* src = out.data.data() + (k - begin) * per;
      o.probs.assign(src, src + per);
    }
  }
  return outputs;
}

DirectionClassifier::DirectionClassifier(const std::string& model_path, const OnnxOptions& options)
    : model_(model_path, options) {}

std::vector<float> DirectionClassifier::upsideDownProbability(
    const std::vector<cv::Mat>& crops) const {
  if (crops.empty()) return {};
  constexpr int kH = 48, kW = 192;
  Tensor input;
  input.shape = {static_cast<int64_t>(crops.size()), 3, kH, kW};
  const size_t slot = 3 * static_cast<size_t>(kH) * kW;
  input.data.assign(slot * crops.size(), 0.f);
  for (size_t i = 0; i < crops.size(); ++i) {
    // Keep the aspect ratio, pad the right as PaddleOCR's classifier pre-processing does.
    const cv::Mat& crop = crops[i];
    const int w =
        std::clamp(static_cast<int>(std::ceil(kH * crop.cols / double(crop.rows))), 1, kW);
    cv::Mat resized;
    cv::resize(crop, resized, {w, kH});
    packImage(resized, kRecMean, kRecStd, kW, input.data.data() + i * slot);
  }
  const Tensor out = model_.run(input);
  std::vector<float> upside_down(crops.size());
  for (size_t i = 0; i < crops.size(); ++i) upside_down[i] = out.data[i * 2 + 1];
  return upside_down;
}

}  // namespace parkloc::ocr
