#pragma once
// The classification head (paper section 3.2): pillar / parking number / other, from the
// instance box expanded by a ratio (the paper takes 2) so the classifier sees the text's
// surroundings (floor paint vs pillar face), plus simple shape features of the reading.
// A small multilayer perceptron (cv::ml::ANN_MLP) on HOG + colour + text features, trained
// by `parkloc train classifier` and stored as one YAML file.
#include <array>
#include <opencv2/core.hpp>
#include <opencv2/ml.hpp>
#include <string>
#include <utility>
#include <vector>

#include "map/landmark.h"
#include "ocr/quad.h"

namespace parkloc::ocr {

struct ClassifierFeatureOptions {
  float expand_ratio = 2.f;     // the paper's choice; 1 is the ablation
  cv::Size patch_size{64, 32};  // the expanded box is warped to this, upright
};

// Feature vector (CV_32F, one row) of one instance: HOG and colour statistics of the
// expanded, rectified box; the reading's length and character mix; the box's size and
// position in the image.
cv::Mat classifierFeatures(const cv::Mat& image, const Quad& quad, const std::string& text,
                           const ClassifierFeatureOptions& options);

// Prior weights of the classes, indexed by map::TextClass: the classifier's softmax is
// multiplied by them and renormalised, so 0 rules a class out (where the text was found can:
// pillar text is not on the floor) and 1 leaves it as the classifier sees it.
using ClassWeights = std::array<float, 3>;
inline constexpr ClassWeights kAnyClass = {1.f, 1.f, 1.f};
// Text found on the floor: a parking number or other floor text, never a pillar's.
inline constexpr ClassWeights kFloorClasses = {0.f, 1.f, 1.f};

struct ClassifierTrainOptions {
  int hidden_units = 8;
  int max_iterations = 400;
  unsigned seed = 7;
};

class TextClassifier {
 public:
  TextClassifier() = default;
  bool empty() const { return !mlp_; }
  const ClassifierFeatureOptions& featureOptions() const { return options_; }

  // `features`: one row per instance (classifierFeatures); `labels`: TextClass per row.
  static TextClassifier train(const cv::Mat& features, const std::vector<map::TextClass>& labels,
                              const ClassifierFeatureOptions& feature_options,
                              const ClassifierTrainOptions& options = {});
  // Throws InputError naming the path when missing or not a classifier file.
  static TextClassifier load(const std::string& path);
  void save(const std::string& path) const;

  // Class and its softmax-normalised score for one feature row, under the classes' prior
  // weights.
  std::pair<map::TextClass, float> predict(const cv::Mat& feature_row,
                                           const ClassWeights& weights = kAnyClass) const;
  std::pair<map::TextClass, float> classify(const cv::Mat& image, const Quad& quad,
                                            const std::string& text,
                                            const ClassWeights& weights = kAnyClass) const;

 private:
  ClassifierFeatureOptions options_;
  cv::Mat mean_, inv_std_;  // feature standardisation
  cv::Ptr<cv::ml::ANN_MLP> mlp_;
};

}  // namespace parkloc::ocr
