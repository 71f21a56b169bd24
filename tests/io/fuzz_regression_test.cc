// Replays the inputs under tests/data/fuzz_regressions/ that once crashed or misled a parser
// of outside data (found by the libFuzzer targets in fuzz/, see docs/RELIABILITY.md). The
// contract: a valid result or parkloc::InputError, nothing else; sanitizer reports show up
// when the suite runs under ASan + UBSan (make test-asan).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <limits>
#include <opencv2/imgcodecs.hpp>

#include "common/error.h"
#include "geometry/rig.h"
#include "io/calibration_yaml.h"
#include "io/labels.h"
#include "io/map_geojson.h"
#include "io/sequence.h"
#include "test_dir.h"

namespace parkloc::io {
namespace {

namespace fs = std::filesystem;

const fs::path kRegressions = fs::path(PARKLOC_SOURCE_DIR) / "tests/data/fuzz_regressions";

std::vector<fs::path> inputsOf(const std::string& target) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(kRegressions / target))
    if (entry.is_regular_file()) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

bool expectsRejection(const fs::path& file) {
  return file.filename().string().rfind("reject_", 0) == 0;
}

// Runs `load` on every input of `target`: reject_* must throw InputError, accept_* must not
// throw; any other exception fails the test.
void replay(const std::string& target, const std::function<void(const std::string&)>& load) {
  const auto files = inputsOf(target);
  ASSERT_FALSE(files.empty()) << "no inputs under " << (kRegressions / target);
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.string());
    if (expectsRejection(file))
      EXPECT_THROW(load(file.string()), InputError);
    else
      EXPECT_NO_THROW(load(file.string()));
  }
}

// The lowest free file descriptor: it grows when descriptors leak.
int lowestFreeDescriptor() {
  const int fd = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
  ::close(fd);
  return fd;
}

TEST(FuzzRegressionTest, Calibration) {
  replay("calibration", [](const std::string& path) { loadCalibration(path); });
}

TEST(FuzzRegressionTest, Map) {
  replay("map", [](const std::string& path) {
    const map::HdMap map = loadMap(path);
    // Lookups on far-out or negative positions, and an unbounded query, must find the
    // landmarks (and not loop over 2^64 grid cells).
    for (const map::Landmark& l : map.landmarks())
      EXPECT_EQ(map.withinRadius(l.position.head<2>(), 1.0).size(), 1u) << l.id;
    EXPECT_EQ(
        map.withinRadius(Eigen::Vector2d::Zero(), std::numeric_limits<double>::infinity()).size(),
        map.size());
  });
}

TEST(FuzzRegressionTest, Labels) {
  replay("labels", [](const std::string& path) { loadLabels(path); });
}

class FuzzRegressionFrameTest : public testing::TempDirTest {};

// Each input becomes the one frame of a sequence folder and is read as a drive reads it.
TEST_F(FuzzRegressionFrameTest, ImagesDecodeOrFailWithAReasonWithoutLeaking) {
  saveCalibration(geometry::defaultRig(), path("calib.yaml"));
  saveMap(map::HdMap(), path("map.geojson"));
  fs::create_directories(dir_ / "images/front");
  const std::string frame = path("images/front/0.000000.jpg");
  const auto files = inputsOf("image");
  ASSERT_FALSE(files.empty());
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.string());
    fs::copy_file(file, frame, fs::copy_options::overwrite_existing);
    const Sequence sequence(dir_.string());
    const int free_before = lowestFreeDescriptor();
    std::string why;
    for (int i = 0; i < 3; ++i) {
      const cv::Mat image = sequence.loadImage(0, "front", &why);
      if (expectsRejection(file)) {
        EXPECT_TRUE(image.empty());
        EXPECT_FALSE(why.empty());
      } else {
        EXPECT_EQ(image.type(), CV_8UC3);
        EXPECT_FALSE(image.empty());
        EXPECT_EQ(why, "");
      }
    }
    EXPECT_EQ(lowestFreeDescriptor(), free_before) << "a file descriptor leaked";
  }
}

}  // namespace
}  // namespace parkloc::io
