// A sequence recorded as videos (videos/<camera>.<ext> + .csv): read like the image folders,
// and every broken input gives one line.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "common/error.h"
#include "geometry/rig.h"
#include "io/calibration_yaml.h"
#include "io/map_geojson.h"
#include "io/sequence.h"
#include "io/sequence_video.h"
#include "io/video_timestamps.h"
#include "test_dir.h"

namespace parkloc::io {
namespace {
namespace fs = std::filesystem;

// Frame k of a camera: a grey level that tells the frame apart after MJPG compression.
cv::Mat frameImage(int k) { return cv::Mat(48, 64, CV_8UC3, cv::Scalar::all(20.0 + 20.0 * k)); }

class VideoSequenceTest : public testing::TempDirTest {
 protected:
  // A rig and map, and images of front and rear at 10 Hz, the rear 30 ms late.
  void makeImageSequence(const fs::path& root, int frames) {
    fs::create_directories(root);
    saveCalibration(geometry::defaultRig(), (root / "calib.yaml").string());
    map::Landmark l;
    l.id = l.text = "101";
    l.width = 0.6;
    l.height = 0.3;
    saveMap(map::HdMap({l}), (root / "map.geojson").string());
    for (const auto& [camera, offset] : {std::pair{"front", 0.0}, std::pair{"rear", 0.03}}) {
      fs::create_directories(root / "images" / camera);
      for (int k = 0; k < frames; ++k)
        cv::imwrite((root / "images" / camera / (timestampStem(0.1 * k + offset) + ".png")).string(),
                    frameImage(k));
    }
  }

  void expectInputError(const std::string& dir, const std::string& message) {
    try {
      Sequence seq(dir);
      FAIL() << "no error; expected: " << message;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  }
};

TEST_F(VideoSequenceTest, AVideoSequenceReadsLikeItsImageFolders) {
  makeImageSequence(dir_ / "images_seq", 6);
  const Sequence images((dir_ / "images_seq").string());
  writeSequenceVideos(images, path("video_seq"));
  ASSERT_TRUE(fs::is_regular_file(dir_ / "video_seq/videos/front.avi"));
  const Sequence video(path("video_seq"));
  EXPECT_EQ(video.cameras(), images.cameras());
  EXPECT_EQ(video.timestamps(), images.timestamps());
  ASSERT_EQ(video.timestamps().size(), 6u);  // front and rear 30 ms apart: one set
  for (size_t i = 0; i < 6; ++i) {
    EXPECT_NEAR(*video.captureTime(i, "rear") - *video.captureTime(i, "front"), 0.03, 1e-6);
    for (const std::string camera : {"front", "rear"}) {
      std::string why;
      const cv::Mat a = images.loadImage(i, camera), b = video.loadImage(i, camera, &why);
      ASSERT_FALSE(b.empty()) << why;
      EXPECT_EQ(b.size(), a.size());
      EXPECT_LT(cv::norm(a, b, cv::NORM_INF), 8.0) << camera << " frame " << i;
    }
  }
  // Out of order (a seek back) gives the same frame.
  EXPECT_LT(cv::norm(video.loadImage(1, "front"), frameImage(1), cv::NORM_INF), 8.0);
  EXPECT_TRUE(video.imagePath(0, "front").empty());
}

TEST_F(VideoSequenceTest, BrokenRecordingsAreOneLineErrors) {
  makeImageSequence(dir_ / "images_seq", 4);
  writeSequenceVideos(Sequence((dir_ / "images_seq").string()), path("seq"));
  const std::string seq = path("seq");
  const std::string csv = path("seq/videos/front.csv");

  write("seq/videos/front.csv", "frame;timestamp\n0;0.0\n");
  expectInputError(seq, "timestamps " + csv + ":1: expected the header 'frame,timestamp'");
  write("seq/videos/front.csv", "frame,timestamp\n0,0.0\n1,abc\n");
  expectInputError(seq, csv + ":3: timestamp 'abc' is not a number");
  write("seq/videos/front.csv", "frame,timestamp\n0,0.1\n1,0.1\n");
  expectInputError(seq, csv + ":3: timestamp 0.1 is not after the previous one");
  write("seq/videos/front.csv", "frame,timestamp\n0,0.0\n0,0.1\n");
  expectInputError(seq, csv + ":3: frame 0 does not follow frame 0");
  // A video shorter than its timestamps.
  write("seq/videos/front.csv", "frame,timestamp\n0,0.0\n1,0.1\n2,0.2\n3,0.3\n4,0.4\n");
  expectInputError(seq, "4 frames, but " + csv + " lists frame 4");
  write("seq/videos/front.csv", "frame,timestamp\n0,0.0\n1,0.1\n");
  // No timestamps file.
  fs::remove(dir_ / "seq/videos/rear.csv");
  expectInputError(seq, "has no timestamps file " + path("seq/videos/rear.csv"));
  // A file that is not a video.
  write("seq/videos/rear.csv", "frame,timestamp\n0,0.0\n");
  write("seq/videos/rear.avi", "not a video at all");
  expectInputError(seq, "video " + path("seq/videos/rear.avi") + ": cannot open");
  // Images and a video for one camera.
  fs::remove(dir_ / "seq/videos/rear.avi");
  fs::remove(dir_ / "seq/videos/rear.csv");
  fs::create_directories(dir_ / "seq/images/front");
  expectInputError(seq, "camera 'front' has both");
}

TEST_F(VideoSequenceTest, ADamagedFrameIsAnEmptyImageWithAReasonAndTheOthersStayInPlace) {
  makeImageSequence(dir_ / "images_seq", 8);
  writeSequenceVideos(Sequence((dir_ / "images_seq").string()), path("seq"));
  // Zeros over all of the fourth frame's data in the front video (the AVI chunk "00dc" holds one
  // compressed frame): it cannot be decoded; every frame that is decoded is the one asked for
  // (no frame slips into another's place).
  const fs::path video = dir_ / "seq/videos/front.avi";
  {
    std::ifstream in(video, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    size_t chunk = bytes.find("movi");
    for (int k = 0; k < 4 && chunk != std::string::npos; ++k) chunk = bytes.find("00dc", chunk + 4);
    ASSERT_NE(chunk, std::string::npos);
    uint32_t size = 0;  // the chunk's little-endian length follows its four-letter name
    for (int b = 3; b >= 0; --b)
      size = size << 8 | static_cast<unsigned char>(bytes[chunk + 4 + b]);
    ASSERT_GT(size, 0u);
    std::fstream f(video, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(static_cast<std::streamoff>(chunk + 8));
    const std::string zeros(size, '\0');
    f.write(zeros.data(), static_cast<std::streamsize>(zeros.size()));
  }
  const Sequence seq(path("seq"));
  int decoded = 0, failed = 0;
  for (size_t i = 0; i < seq.timestamps().size(); ++i) {
    std::string why;
    const cv::Mat image = seq.loadImage(i, "front", &why);
    if (image.empty()) {
      ++failed;
      EXPECT_NE(why.find("video " + video.string() + ": frame "), std::string::npos) << why;
    } else {
      ++decoded;
      EXPECT_TRUE(why.empty());
      EXPECT_LT(cv::norm(image, frameImage(static_cast<int>(i)), cv::NORM_INF), 8.0) << i;
    }
  }
  EXPECT_EQ(decoded, 7);
  EXPECT_EQ(failed, 1);
  EXPECT_FALSE(seq.loadImage(7, "rear").empty());
}

TEST_F(VideoSequenceTest, MjpegQualityIsTheJpegQualityOfEachFrame) {
  // A textured frame (fine detail is what a coarser JPEG loses).
  const fs::path root = dir_ / "textured";
  makeImageSequence(root, 2);
  cv::Mat grey(120, 160, CV_8U), texture;
  cv::randu(grey, 0, 255);
  cv::GaussianBlur(grey, grey, cv::Size(), 1.0);
  cv::cvtColor(grey, texture, cv::COLOR_GRAY2BGR);
  for (const char* camera : {"front", "rear"})
    for (const auto& file : fs::directory_iterator(root / "images" / camera))
      cv::imwrite(file.path().string(), texture);
  const Sequence images(root.string());
  SequenceVideoOptions coarse, fine;
  coarse.mjpeg_quality = 20;
  fine.mjpeg_quality = 95;
  writeSequenceVideos(images, path("coarse"), coarse);
  writeSequenceVideos(images, path("fine"), fine);
  EXPECT_LT(fs::file_size(dir_ / "coarse/videos/front.avi"),
            fs::file_size(dir_ / "fine/videos/front.avi"));
  const double coarse_db = cv::PSNR(Sequence(path("coarse")).loadImage(0, "front"), texture);
  const double fine_db = cv::PSNR(Sequence(path("fine")).loadImage(0, "front"), texture);
  EXPECT_GT(fine_db, coarse_db + 3.0);

  SequenceVideoOptions invalid;
  invalid.mjpeg_quality = 0;
  EXPECT_THROW(writeSequenceVideos(images, path("invalid"), invalid), InputError);
}

TEST(VideoTimestamps, ListsFramesWithTheirTimes) {
  const std::string p = (fs::temp_directory_path() / "parkloc_video_timestamps.csv").string();
  std::ofstream(p) << "frame,timestamp\n0,10.000\n2,10.2\n\n3, 10.3 \n";
  const auto rows = loadVideoTimestamps(p);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[1].frame, 2);
  EXPECT_DOUBLE_EQ(rows[2].timestamp, 10.3);
  std::ofstream(p) << "frame,timestamp\n";
  EXPECT_THROW(loadVideoTimestamps(p), InputError);
  fs::remove(p);
}

}  // namespace
}  // namespace parkloc::io
