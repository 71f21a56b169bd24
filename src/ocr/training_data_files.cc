#include "ocr/training_data_files.h"

#include <algorithm>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "common/error.h"

namespace parkloc::ocr {

namespace fs = std::filesystem;

std::string sequenceName(const std::string& dir) {
  const fs::path p = fs::path(dir).lexically_normal();
  return p.has_filename() ? p.filename().string() : p.parent_path().filename().string();
}

std::vector<size_t> sampledFrames(const io::Sequence& sequence, size_t stride, size_t max_frames) {
  size_t frames = sequence.timestamps().size();
  if (max_frames > 0) frames = std::min(frames, max_frames);
  std::vector<size_t> out;
  for (size_t f = 0; f < frames; f += std::max<size_t>(stride, 1)) out.push_back(f);
  return out;
}

cv::Mat loadBgrImage(const io::Sequence& sequence, size_t frame, const std::string& camera) {
  cv::Mat image = sequence.loadImage(frame, camera);
  if (image.empty() || image.depth() != CV_8U) return {};
  if (image.channels() == 1) cv::cvtColor(image, image, cv::COLOR_GRAY2BGR);
  if (image.channels() == 4) cv::cvtColor(image, image, cv::COLOR_BGRA2BGR);
  return image;
}

void createDirectory(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw IoError(dir.string() + ": cannot create folder (" + ec.message() + ")");
}

void writeImage(const fs::path& path, const cv::Mat& image) {
  bool ok = false;
  try {
    ok = cv::imwrite(path.string(), image);
  } catch (const cv::Exception& e) {
    throw IoError(path.string() + ": cannot write image (" + e.what() + ")");
  }
  if (!ok) throw IoError(path.string() + ": cannot write image");
}

}  // namespace parkloc::ocr
