#include "io/video_reader.h"

#include <fmt/format.h>

#include <algorithm>
#include <opencv2/videoio.hpp>

#include "common/error.h"

namespace parkloc::io {
namespace {

// Decoding forward this many frames is cheaper than a seek (which decodes from the previous
// key frame anyway, and is inexact in some containers).
constexpr int kMaxSkipByDecoding = 30;

}  // namespace

VideoReader::VideoReader(const std::string& path)
    : path_(path), capture_(std::make_unique<cv::VideoCapture>()) {
  bool opened = false;
  try {
    opened = capture_->open(path, cv::CAP_FFMPEG);
  } catch (const cv::Exception&) {
    opened = false;
  }
  if (!opened) throw InputError(fmt::format("video {}: cannot open (not a video FFmpeg reads)", path));
  frame_count_ = std::max(0, static_cast<int>(capture_->get(cv::CAP_PROP_FRAME_COUNT)));
}

VideoReader::~VideoReader() = default;

bool VideoReader::seekTo(int index) {
  if (index == next_) return true;
  if (index > next_ && index - next_ <= kMaxSkipByDecoding) {
    while (next_ < index) {
      if (!capture_->grab()) return false;
      ++next_;
    }
    return true;
  }
  if (!capture_->set(cv::CAP_PROP_POS_FRAMES, static_cast<double>(index))) return false;
  next_ = static_cast<int>(capture_->get(cv::CAP_PROP_POS_FRAMES));
  return next_ == index;
}

cv::Mat VideoReader::frame(int index, std::string* why) {
  const auto failed = [&](const std::string& reason) {
    if (why) *why = fmt::format("video {}: frame {}: {}", path_, index, reason);
    return cv::Mat();
  };
  if (index < 0) return failed("negative index");
  const std::lock_guard<std::mutex> lock(mutex_);
  if (index == ahead_index_ && !ahead_.empty()) {
    if (why) why->clear();
    return ahead_;
  }
  cv::Mat image;
  try {
    if (!seekTo(index)) {
      // The decoder's position is unknown after a failed seek: start over on the next call.
      capture_->open(path_, cv::CAP_FFMPEG);
      next_ = 0;
      return failed("cannot seek there (past the end, or a damaged stream)");
    }
    const bool ok = capture_->read(image);
    // A damaged packet is skipped by the decoder, which then returns a later frame: its
    // position tells, and that frame is kept for when it is asked for.
    const int position = static_cast<int>(capture_->get(cv::CAP_PROP_POS_FRAMES));
    next_ = position > index ? position : index + 1;
    if (!ok || image.empty()) return failed("cannot decode");
    if (position > index + 1) {
      ahead_index_ = position - 1;
      ahead_ = image;
      return failed(fmt::format("cannot decode (the stream goes on at frame {})", ahead_index_));
    }
  } catch (const cv::Exception& e) {
    return failed(fmt::format("cannot decode ({})", e.what()));
  }
  if (why) why->clear();
  return image;
}

}  // namespace parkloc::io
