#include "ocr/classifier_training.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "small_sequence.h"

namespace parkloc::ocr {
namespace {

namespace fs = std::filesystem;

// One small simulated sequence for the whole suite.
class ClassifierTraining : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = fs::temp_directory_path() / ("parkloc_classifier_data_" + std::to_string(::getpid()));
    sequence_ = testing::writeSmallSequence(root_);
  }
  static void TearDownTestSuite() { fs::remove_all(root_); }

  static fs::path root_;
  static std::string sequence_;
};

fs::path ClassifierTraining::root_;
std::string ClassifierTraining::sequence_;

TEST_F(ClassifierTraining, EachInstanceComesReadUnreadOrBoth) {
  SampleOptions options;
  options.text = SampleText::kBoth;
  const ClassifierSamples both = collectClassifierSamples({sequence_}, options);
  options.text = SampleText::kRead;
  const ClassifierSamples read = collectClassifierSamples({sequence_}, options);
  options.text = SampleText::kUnread;
  const ClassifierSamples unread = collectClassifierSamples({sequence_}, options);
  ASSERT_GT(read.labels.size(), 0u);
  ASSERT_EQ(both.labels.size(), 2 * read.labels.size());
  ASSERT_EQ(both.unread.size(), both.labels.size());
  ASSERT_EQ(unread.labels.size(), read.labels.size());
  for (size_t i = 0; i < read.labels.size(); ++i) {
    // Row 2i as read, row 2i + 1 the same box unread: same label and pixels, and only the
    // reading's features (length and character mix, 7 values) differ.
    const int r = static_cast<int>(i);
    EXPECT_FALSE(both.unread[2 * i]);
    EXPECT_TRUE(both.unread[2 * i + 1]);
    EXPECT_EQ(both.labels[2 * i + 1], read.labels[i]);
    EXPECT_EQ(cv::norm(both.features.row(2 * r), read.features.row(r)), 0.0);
    EXPECT_EQ(cv::norm(both.features.row(2 * r + 1), unread.features.row(r)), 0.0);
    EXPECT_TRUE(unread.unread[i]);
    cv::Mat differs = both.features.row(2 * r) != both.features.row(2 * r + 1);
    EXPECT_GE(cv::countNonZero(differs), 1);
    EXPECT_LE(cv::countNonZero(differs), 7);
  }
}

TEST_F(ClassifierTraining, ScoresTheReadAndTheUnreadSamplesApart) {
  SampleOptions options;
  options.text = SampleText::kBoth;
  const ClassifierSamples samples = collectClassifierSamples({sequence_}, options);
  const TextClassifier classifier =
      TextClassifier::train(samples.features, samples.labels, SampleOptions{}.features, {});
  const ClassifierScore all = scoreClassifier(classifier, samples);
  const ClassifierScore read = scoreClassifier(classifier, samples, false);
  const ClassifierScore unread = scoreClassifier(classifier, samples, true);
  EXPECT_EQ(all.samples, samples.labels.size());
  EXPECT_EQ(read.samples + unread.samples, all.samples);
  EXPECT_EQ(read.samples, unread.samples);
  EXPECT_EQ(read.correct + unread.correct, all.correct);
}

}  // namespace
}  // namespace parkloc::ocr
