#include "ocr/text_classifier.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <opencv2/imgproc.hpp>
#include <random>

#include "common/error.h"
#include "synthetic_text.h"

namespace parkloc::ocr {
namespace {

// Three visually distinct kinds: white floor digits, dark letters on a bright pillar, and
// yellow words; each instance with a little jitter.
struct Sample {
  cv::Mat image;
  Quad quad;
  std::string text;
  map::TextClass cls;
};

Sample makeSample(int kind, std::mt19937& rng) {
  std::uniform_int_distribution<int> digit(0, 9);
  std::uniform_int_distribution<int> shade(-15, 15);
  const int margin = 30;
  std::string text;
  cv::Scalar ink, paper;
  if (kind == 0) {
    text = std::string("B") + char('1' + digit(rng) % 3);
    ink = {40.0 + shade(rng), 40, 40};
    paper = {200.0 + shade(rng), 200, 200};
  } else if (kind == 1) {
    text = std::to_string(100 + digit(rng) * 10 + digit(rng));
    ink = {230, 230, 230.0 + shade(rng)};
    paper = {100.0 + shade(rng), 100, 100};
  } else {
    text = digit(rng) % 2 ? "EXIT" : "SLOW";
    ink = {30, 200.0 + shade(rng), 220};
    paper = {90.0 + shade(rng), 95, 95};
  }
  Sample s;
  s.image = testing::renderTextLine(text, 24, margin, ink, paper);
  const float W = s.image.cols, H = s.image.rows;
  s.quad = {cv::Point2f(margin, margin),
            {W - margin, margin},
            {W - margin, H - margin},
            {margin, H - margin}};
  s.text = text;
  s.cls = static_cast<map::TextClass>(kind);
  return s;
}

// A classifier trained on 60 samples, 20 of each class.
TextClassifier trainedOnSamples(std::mt19937& rng) {
  ClassifierFeatureOptions features;
  std::vector<cv::Mat> rows;
  std::vector<map::TextClass> labels;
  for (int i = 0; i < 60; ++i) {
    const Sample s = makeSample(i % 3, rng);
    rows.push_back(classifierFeatures(s.image, s.quad, s.text, features));
    labels.push_back(s.cls);
  }
  cv::Mat x;
  cv::vconcat(rows, x);
  return TextClassifier::train(x, labels, features);
}

TEST(TextClassifier, LearnsSeparableClassesAndSurvivesASaveLoadRoundTrip) {
  std::mt19937 rng(11);
  const TextClassifier classifier = trainedOnSamples(rng);

  const auto path = (std::filesystem::temp_directory_path() /
                     ("parkloc_classifier_test_" + std::to_string(::getpid()) + ".yml"))
                        .string();
  classifier.save(path);
  const TextClassifier loaded = TextClassifier::load(path);
  std::filesystem::remove(path);
  EXPECT_FLOAT_EQ(loaded.featureOptions().expand_ratio, 2.f);

  int correct = 0;
  for (int i = 0; i < 30; ++i) {
    const Sample s = makeSample(i % 3, rng);
    const auto [cls, score] = loaded.classify(s.image, s.quad, s.text);
    correct += cls == s.cls;
    EXPECT_EQ(cls, classifier.classify(s.image, s.quad, s.text).first);
    EXPECT_GT(score, 0.f);
    EXPECT_LE(score, 1.f);
  }
  EXPECT_GE(correct, 28);
}

TEST(TextClassifier, ChoosesOnlyAmongTheClassesWithAWeight) {
  std::mt19937 rng(11);
  const TextClassifier classifier = trainedOnSamples(rng);
  for (int i = 0; i < 9; ++i) {
    const Sample s = makeSample(i % 3, rng);
    const auto any = classifier.classify(s.image, s.quad, s.text);
    const auto floor = classifier.classify(s.image, s.quad, s.text, kFloorClasses);
    EXPECT_NE(floor.first, map::TextClass::kPillar);
    if (any.first != map::TextClass::kPillar) {
      // Without the pillar output in the softmax: the same class, a score at least as high.
      EXPECT_EQ(floor.first, any.first);
      EXPECT_GE(floor.second, any.second - 1e-6f);
    }
    EXPECT_GT(floor.second, 0.f);
    EXPECT_LE(floor.second, 1.f);
  }
  const Sample s = makeSample(0, rng);
  EXPECT_EQ(classifier.classify(s.image, s.quad, s.text, {0.f, 0.f, 0.f}).second, 0.f);
}

// A prior weight multiplies the class's softmax term: weighing one class far above the other
// makes it the class, and equal weights change nothing.
TEST(TextClassifier, AClassWeightTiltsTheChoice) {
  std::mt19937 rng(12);
  const TextClassifier classifier = trainedOnSamples(rng);
  for (int i = 0; i < 9; ++i) {
    const Sample s = makeSample(i % 3, rng);
    const auto floor = classifier.classify(s.image, s.quad, s.text, kFloorClasses);
    const auto halved = classifier.classify(s.image, s.quad, s.text, {0.f, 0.5f, 0.5f});
    EXPECT_EQ(halved.first, floor.first);
    EXPECT_NEAR(halved.second, floor.second, 1e-6f);
    const auto number = classifier.classify(s.image, s.quad, s.text, {0.f, 1e6f, 1.f});
    EXPECT_EQ(number.first, map::TextClass::kParkingNumber);
    const auto other = classifier.classify(s.image, s.quad, s.text, {0.f, 1.f, 1e6f});
    EXPECT_EQ(other.first, map::TextClass::kOther);
    EXPECT_GT(other.second, 0.99f);
  }
}

TEST(TextClassifier, MissingOrForeignFileIsAnInputError) {
  EXPECT_THROW(TextClassifier::load("/nonexistent/classifier.yml"), InputError);
  const auto path = (std::filesystem::temp_directory_path() /
                     ("parkloc_not_a_classifier_" + std::to_string(::getpid()) + ".yml"))
                        .string();
  {
    cv::FileStorage fs(path, cv::FileStorage::WRITE);
    fs << "kind"
       << "something_else";
  }
  EXPECT_THROW(TextClassifier::load(path), InputError);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace parkloc::ocr
