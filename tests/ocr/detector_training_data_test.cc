#include "ocr/detector_training_data.h"

#include "geometry/rig.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "common/error.h"
#include "small_sequence.h"

namespace parkloc::ocr {
namespace {

namespace fs = std::filesystem;

struct LabelLine {
  std::array<cv::Point2f, 4> corners;
  int care = -1;
  int cls = -1;
  std::string text;
};

// x1,y1,...,x4,y4,care,class,text; empty when the line does not parse.
std::optional<LabelLine> parseLine(const std::string& line) {
  std::istringstream in(line);
  std::string field;
  std::vector<std::string> fields;
  while (fields.size() < 10 && std::getline(in, field, ',')) fields.push_back(field);
  LabelLine out;
  if (fields.size() < 10 || !std::getline(in, out.text) || out.text.empty()) return std::nullopt;
  try {
    for (int k = 0; k < 4; ++k)
      out.corners[k] = cv::Point2f(std::stof(fields[2 * k]), std::stof(fields[2 * k + 1]));
    out.care = std::stoi(fields[8]);
    out.cls = std::stoi(fields[9]);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  return out;
}

using testing::writeSmallSequence;

TEST(DetectorTrainingData, WritesGroundViewsWithTheirTextPolygons) {
  const fs::path root =
      fs::temp_directory_path() / ("parkloc_detector_data_" + std::to_string(::getpid()));
  const std::string sequence = writeSmallSequence(root);

  DetectorDataOptions options;
  options.out_dir = (root / "out").string();
  size_t progress_calls = 0;
  options.progress = [&](size_t done, size_t total) {
    EXPECT_EQ(total, 1u);
    progress_calls = done;
  };
  const DetectorDataStats stats = writeDetectorTrainingData({sequence}, options);
  EXPECT_EQ(stats.images, 8u);  // 2 frame sets x 4 cameras
  EXPECT_EQ(progress_calls, 1u);

  std::ifstream index(root / "out" / "index.txt");
  std::string image_rel, labels_rel, condition;
  size_t images = 0, care = 0, dont_care = 0, care_numbers = 0, care_cut_by_the_edge = 0;
  while (index >> image_rel >> labels_rel >> condition) {
    ++images;
    EXPECT_EQ(condition, "bright");
    const cv::Mat view = cv::imread((root / "out" / image_rel).string(), cv::IMREAD_COLOR);
    ASSERT_FALSE(view.empty()) << image_rel;
    EXPECT_EQ(view.cols % 32, 0);
    std::ifstream labels(root / "out" / labels_rel);
    ASSERT_TRUE(labels.is_open()) << labels_rel;
    std::string line;
    while (std::getline(labels, line)) {
      const auto parsed = parseLine(line);
      ASSERT_TRUE(parsed) << labels_rel << ": " << line;
      ASSERT_TRUE(parsed->care == 0 || parsed->care == 1) << line;
      ASSERT_TRUE(parsed->cls >= 0 && parsed->cls <= 2) << line;
      if (parsed->care == 0) {
        ++dont_care;
        continue;
      }
      ++care;
      if (parsed->cls == 1) ++care_numbers;
      cv::Point2f centre(0.f, 0.f);
      bool at_edge = false;
      for (const auto& c : parsed->corners) {
        at_edge |= c.x < 0.5f || c.y < 0.5f || c.x > view.cols - 1.5f || c.y > view.rows - 1.5f;
        EXPECT_GE(c.x, 0.f) << line;
        EXPECT_GE(c.y, 0.f) << line;
        EXPECT_LE(c.x, view.cols - 1.f) << line;
        EXPECT_LE(c.y, view.rows - 1.f) << line;
        centre += 0.25f * c;
      }
      // Care text lies where the camera sees the floor, not in the view's black margin.
      EXPECT_NE(view.at<cv::Vec3b>(cvRound(centre.y), cvRound(centre.x)), cv::Vec3b(0, 0, 0))
          << line;
      if (at_edge) ++care_cut_by_the_edge;
    }
  }
  EXPECT_EQ(images, stats.images);
  EXPECT_EQ(care, stats.care_instances);
  EXPECT_EQ(dont_care, stats.dont_care_instances);
  EXPECT_GT(care_numbers, 0u);
  // Text cut by the view's edge is labelled by its part inside (this sequence has some).
  EXPECT_GT(care_cut_by_the_edge, 0u);
  fs::remove_all(root);
}

TEST(DetectorTrainingData, WritesRawBandsWithTextOfEveryClass) {
  const fs::path root =
      fs::temp_directory_path() / ("parkloc_band_data_" + std::to_string(::getpid()));
  const std::string sequence = writeSmallSequence(root);
  DetectorDataOptions options;
  options.out_dir = (root / "out").string();
  options.source = DetectorSource::kRawBand;
  const DetectorDataStats stats = writeDetectorTrainingData({sequence}, options);
  EXPECT_EQ(stats.images, 8u);

  std::ifstream index(root / "out" / "index.txt");
  std::string image_rel, labels_rel, condition;
  std::array<size_t, 3> care_by_class{};
  size_t images = 0;
  while (index >> image_rel >> labels_rel >> condition) {
    ++images;
    const cv::Mat band = cv::imread((root / "out" / image_rel).string(), cv::IMREAD_COLOR);
    ASSERT_FALSE(band.empty()) << image_rel;
    // The rows of a default-rig image that bandRect gives: [64, 512).
    const cv::Rect rows = bandRect(options.band, geometry::defaultRig().cameras[0].model);
    EXPECT_EQ(rows, cv::Rect(0, 64, 1280, 448));
    EXPECT_EQ(band.size(), rows.size()) << image_rel;
    std::ifstream labels(root / "out" / labels_rel);
    std::string line;
    while (std::getline(labels, line)) {
      const auto parsed = parseLine(line);
      ASSERT_TRUE(parsed) << labels_rel << ": " << line;
      if (parsed->care != 1) continue;
      ++care_by_class.at(static_cast<size_t>(parsed->cls));
      for (const auto& c : parsed->corners) {  // wholly inside the band
        EXPECT_GE(c.y, 0.f) << line;
        EXPECT_LE(c.y, band.rows - 1.f) << line;
      }
    }
  }
  EXPECT_EQ(images, stats.images);
  // Unlike the floor view, the band teaches pillar text as well as parking numbers.
  EXPECT_GT(care_by_class[0], 0u);
  EXPECT_GT(care_by_class[1], 0u);
  fs::remove_all(root);
}

TEST(DetectorTrainingData, RejectsABandOutsideTheImage) {
  DetectorDataOptions options;
  options.out_dir = (fs::temp_directory_path() / "parkloc_band_data_unused").string();
  options.source = DetectorSource::kRawBand;
  options.band.top = 0.7;
  options.band.bottom = 0.6;
  EXPECT_THROW(writeDetectorTrainingData({}, options), InputError);
  options.band.top = 0.1;
  options.band.bottom = 1.6;
  EXPECT_THROW(writeDetectorTrainingData({}, options), InputError);
}

TEST(DetectorTrainingData, RejectsBadViewOptions) {
  DetectorDataOptions options;
  EXPECT_THROW(writeDetectorTrainingData({}, options), InputError);  // no output folder
  options.out_dir = (fs::temp_directory_path() / "parkloc_detector_data_unused").string();
  options.view.resolution = 0.0;
  EXPECT_THROW(writeDetectorTrainingData({}, options), InputError);
  options.view.resolution = 1e-4;  // a view of 180000 px
  EXPECT_THROW(writeDetectorTrainingData({}, options), InputError);
  options.view.resolution = 0.015;
  options.view.far = options.view.near - 0.5;  // before near
  EXPECT_THROW(writeDetectorTrainingData({}, options), InputError);
  options.view.near = -2.0;
  options.view.far = -3.0;
  EXPECT_THROW(writeDetectorTrainingData({}, options), InputError);
}

}  // namespace
}  // namespace parkloc::ocr
