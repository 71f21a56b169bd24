#include "ocr/text_classifier.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <opencv2/imgproc.hpp>
#include <opencv2/objdetect.hpp>

#include "common/error.h"

namespace parkloc::ocr {
namespace {

constexpr int kClassCount = 3;

const cv::HOGDescriptor& hog(const cv::Size& window) {
  // 16x16 blocks without overlap keep the vector (and the committed model) small.
  static thread_local cv::HOGDescriptor descriptor;
  if (descriptor.winSize != window)
    descriptor = cv::HOGDescriptor(window, {16, 16}, {16, 16}, {8, 8}, 9);
  return descriptor;
}

void appendTextFeatures(const std::string& text, std::vector<float>& out) {
  int digits = 0, letters = 0, dashes = 0, others = 0;
  for (unsigned char c : text) {
    if (std::isdigit(c))
      ++digits;
    else if (std::isalpha(c))
      ++letters;
    else if (c == '-')
      ++dashes;
    else
      ++others;
  }
  const float n = static_cast<float>(std::max<size_t>(text.size(), 1));
  out.push_back(static_cast<float>(text.size()) / 8.f);
  out.push_back(digits / n);
  out.push_back(letters / n);
  out.push_back(dashes > 0 ? 1.f : 0.f);
  out.push_back(others / n);
  out.push_back(!text.empty() && std::isalpha(static_cast<unsigned char>(text[0])) ? 1.f : 0.f);
  out.push_back(!text.empty() && std::isdigit(static_cast<unsigned char>(text.back())) ? 1.f : 0.f);
}

}  // namespace

cv::Mat classifierFeatures(const cv::Mat& image, const Quad& quad, const std::string& text,
                           const ClassifierFeatureOptions& options) {
  const Quad expanded = expandQuad(quad, options.expand_ratio, options.expand_ratio);
  const cv::Size size = options.patch_size;
  cv::Mat patch;
  cv::warpPerspective(image, patch, rectifyingHomography(expanded, size.width, size.height), size,
                      cv::INTER_AREA, cv::BORDER_REPLICATE);
  cv::Mat gray;
  cv::cvtColor(patch, gray, cv::COLOR_BGR2GRAY);
  std::vector<float> values;
  hog(size).compute(gray, values);

  // Colour: mean and spread of each HSV channel (yellow paint, grey concrete, pillar paint).
  cv::Mat hsv;
  cv::cvtColor(patch, hsv, cv::COLOR_BGR2HSV);
  cv::Scalar mean, stddev;
  cv::meanStdDev(hsv, mean, stddev);
  for (int c = 0; c < 3; ++c) {
    values.push_back(static_cast<float>(mean[c] / 255.0));
    values.push_back(static_cast<float>(stddev[c] / 255.0));
  }
  appendTextFeatures(text, values);

  // Geometry: text height and aspect, where the box sits in the image, its tilt.
  const float w = quadWidth(quad), h = std::max(quadHeight(quad), 1.f);
  const cv::Point2f centre = quadCentre(quad);
  const cv::Point2f along = quad[1] - quad[0];
  values.push_back(std::log(h) / 5.f);
  values.push_back(std::log(std::max(w / h, 0.1f)));
  values.push_back(centre.x / std::max(image.cols, 1));
  values.push_back(centre.y / std::max(image.rows, 1));
  values.push_back(static_cast<float>(std::atan2(along.y, along.x) / CV_PI));
  return cv::Mat(values, true).reshape(1, 1);
}

TextClassifier TextClassifier::train(const cv::Mat& features,
                                     const std::vector<map::TextClass>& labels,
                                     const ClassifierFeatureOptions& feature_options,
                                     const ClassifierTrainOptions& options) {
  if (features.empty() || features.rows != static_cast<int>(labels.size()))
    throw InputError("classifier training needs one label per feature row");
  TextClassifier out;
  out.options_ = feature_options;
  cv::reduce(features, out.mean_, 0, cv::REDUCE_AVG);
  cv::Mat centred = features - cv::repeat(out.mean_, features.rows, 1);
  cv::Mat var;
  cv::reduce(centred.mul(centred), var, 0, cv::REDUCE_AVG);
  cv::sqrt(var, var);
  out.inv_std_ = 1.0 / (var + 1e-3);
  cv::Mat x = centred.mul(cv::repeat(out.inv_std_, features.rows, 1));

  // One-hot targets in the symmetric sigmoid's range.
  cv::Mat y(features.rows, kClassCount, CV_32F, cv::Scalar(-1.f));
  for (int i = 0; i < features.rows; ++i) y.at<float>(i, static_cast<int>(labels[i])) = 1.f;

  cv::theRNG().state = options.seed;
  out.mlp_ = cv::ml::ANN_MLP::create();
  out.mlp_->setLayerSizes(std::vector<int>{features.cols, options.hidden_units, kClassCount});
  out.mlp_->setActivationFunction(cv::ml::ANN_MLP::SIGMOID_SYM, 1.0, 1.0);
  out.mlp_->setTrainMethod(cv::ml::ANN_MLP::RPROP);
  out.mlp_->setTermCriteria(
      {cv::TermCriteria::MAX_ITER + cv::TermCriteria::EPS, options.max_iterations, 1e-5});
  out.mlp_->train(cv::ml::TrainData::create(x, cv::ml::ROW_SAMPLE, y));
  return out;
}

void TextClassifier::save(const std::string& path) const {
  cv::FileStorage fs(path, cv::FileStorage::WRITE);
  if (!fs.isOpened()) throw IoError("cannot write classifier " + path);
  fs << "kind"
     << "parkloc_text_classifier";
  fs << "expand_ratio" << options_.expand_ratio;
  fs << "patch_size" << options_.patch_size;
  fs << "mean" << mean_ << "inv_std" << inv_std_;
  fs << "mlp"
     << "{";
  mlp_->write(fs);
  fs << "}";
}

TextClassifier TextClassifier::load(const std::string& path) {
  if (!std::filesystem::is_regular_file(path)) throw IoError("classifier file not found: " + path);
  TextClassifier out;
  try {
    cv::FileStorage fs(path, cv::FileStorage::READ);
    if (!fs.isOpened() || static_cast<std::string>(fs["kind"]) != "parkloc_text_classifier")
      throw InputError("not a parkloc text classifier: " + path);
    fs["expand_ratio"] >> out.options_.expand_ratio;
    fs["patch_size"] >> out.options_.patch_size;
    fs["mean"] >> out.mean_;
    fs["inv_std"] >> out.inv_std_;
    out.mlp_ = cv::ml::ANN_MLP::create();
    out.mlp_->read(fs["mlp"]);
  } catch (const cv::Exception& e) {
    throw InputError("cannot read classifier " + path + ": " + e.what());
  }
  if (out.mean_.empty() || !out.mlp_->isTrained())
    throw InputError("incomplete classifier file " + path);
  return out;
}

std::pair<map::TextClass, float> TextClassifier::predict(const cv::Mat& feature_row,
                                                         const ClassWeights& weights) const {
  if (empty()) return {map::TextClass::kOther, 0.f};
  cv::Mat x = (feature_row - mean_).mul(inv_std_);
  cv::Mat response;
  mlp_->predict(x, response);
  // Softmax of the outputs (in (-1.7, 1.7)) as a score, times the weights.
  const int n = std::min<int>(response.cols, static_cast<int>(weights.size()));
  double top = -1e9;
  for (int c = 0; c < n; ++c)
    if (weights[c] > 0.f) top = std::max(top, double(response.at<float>(0, c)));
  double best = 0.0, sum = 0.0;
  int best_class = -1;
  for (int c = 0; c < n; ++c) {
    if (!(weights[c] > 0.f)) continue;
    const double term = weights[c] * std::exp(3.0 * (response.at<float>(0, c) - top));
    sum += term;
    if (term > best) {
      best = term;
      best_class = c;
    }
  }
  if (best_class < 0) return {map::TextClass::kOther, 0.f};  // nothing allowed
  return {static_cast<map::TextClass>(best_class), static_cast<float>(best / sum)};
}

std::pair<map::TextClass, float> TextClassifier::classify(const cv::Mat& image, const Quad& quad,
                                                          const std::string& text,
                                                          const ClassWeights& weights) const {
  if (empty()) return {map::TextClass::kOther, 0.f};
  return predict(classifierFeatures(image, quad, text, options_), weights);
}

}  // namespace parkloc::ocr
