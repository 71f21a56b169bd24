#include "ocr/recognizer_training_data.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <opencv2/imgcodecs.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "common/error.h"
#include "small_sequence.h"

namespace parkloc::ocr {
namespace {

namespace fs = std::filesystem;

struct IndexLine {
  std::string crop, text;
  int cls = -1;
};

std::vector<IndexLine> readIndex(const fs::path& path) {
  std::vector<IndexLine> lines;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    IndexLine l;
    std::string cls;
    if (std::getline(fields, l.crop, '\t') && std::getline(fields, l.text, '\t') &&
        std::getline(fields, cls))
      l.cls = std::stoi(cls);
    lines.push_back(l);
  }
  return lines;
}

// One small simulated dataset for the whole suite (simulating takes seconds).
class RecognizerTrainingData : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = fs::temp_directory_path() / ("parkloc_recognizer_data_" + std::to_string(::getpid()));
    sequence_ = testing::writeSmallSequence(root_);
  }
  static void TearDownTestSuite() { fs::remove_all(root_); }

  static RecognizerDataOptions options(const std::string& out) {
    RecognizerDataOptions o;
    o.out_dir = (root_ / out).string();
    return o;
  }

  static fs::path root_;
  static std::string sequence_;
};

fs::path RecognizerTrainingData::root_;
std::string RecognizerTrainingData::sequence_;

TEST_F(RecognizerTrainingData, WritesUprightCropsWithTheirTexts) {
  RecognizerDataOptions o = options("out");
  o.variants = 3;
  o.other_class_variants = 1;
  const RecognizerDataStats stats = writeRecognizerTrainingData({sequence_}, o);
  const auto lines = readIndex(root_ / "out" / "index.tsv");
  ASSERT_EQ(lines.size(), stats.crops);
  ASSERT_GT(stats.texts, 0u);
  std::map<std::string, int> crops_per_stem_text;
  size_t numbers = 0;
  for (const auto& l : lines) {
    ASSERT_TRUE(l.cls >= 0 && l.cls <= 2) << l.crop;
    ASSERT_FALSE(l.text.empty()) << l.crop;
    for (char c : l.text) EXPECT_NE(o.alphabet.find(c), std::string::npos) << l.text;
    const cv::Mat crop = cv::imread((root_ / "out" / l.crop).string(), cv::IMREAD_COLOR);
    ASSERT_FALSE(crop.empty()) << l.crop;
    EXPECT_EQ(crop.rows, 48) << l.crop;
    EXPECT_GE(crop.cols, 16) << l.crop;
    EXPECT_LE(crop.cols, 480) << l.crop;
    if (l.cls == 1) ++numbers;
  }
  EXPECT_GT(numbers, 0u);
  // Parking numbers three crops each, the other classes one.
  EXPECT_EQ(stats.crops, stats.texts + 2 * (numbers / 3));
  EXPECT_EQ(numbers % 3, 0u);
}

TEST_F(RecognizerTrainingData, TheSameSeedWritesTheSameCropsAndAnotherSeedOtherBoxes) {
  RecognizerDataOptions a = options("a"), b = options("b"), c = options("c");
  c.seed = a.seed + 1;
  writeRecognizerTrainingData({sequence_}, a);
  writeRecognizerTrainingData({sequence_}, b);
  writeRecognizerTrainingData({sequence_}, c);
  const auto la = readIndex(root_ / "a" / "index.tsv");
  ASSERT_EQ(la.size(), readIndex(root_ / "c" / "index.tsv").size());
  size_t same_b = 0, same_c = 0;
  for (const auto& l : la) {
    const cv::Mat ia = cv::imread((root_ / "a" / l.crop).string());
    const cv::Mat ib = cv::imread((root_ / "b" / l.crop).string());
    const cv::Mat ic = cv::imread((root_ / "c" / l.crop).string());
    same_b += ia.size() == ib.size() && cv::norm(ia, ib, cv::NORM_INF) == 0.0;
    same_c += ia.size() == ic.size() && cv::norm(ia, ic, cv::NORM_INF) == 0.0;
  }
  EXPECT_EQ(same_b, la.size());
  // Only the true boxes (the first crop of each text) agree across seeds.
  EXPECT_LT(same_c, la.size());
}

TEST_F(RecognizerTrainingData, RejectsBadOptions) {
  RecognizerDataOptions o;
  EXPECT_THROW(writeRecognizerTrainingData({sequence_}, o), InputError);  // no output folder
  o = options("bad");
  o.variants = 0;
  EXPECT_THROW(writeRecognizerTrainingData({sequence_}, o), InputError);
  o = options("bad");
  o.max_grow_x = 0.5;
  EXPECT_THROW(writeRecognizerTrainingData({sequence_}, o), InputError);
}

}  // namespace
}  // namespace parkloc::ocr
