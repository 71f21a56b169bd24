#pragma once
// Frames of one camera's video file, decoded by FFmpeg through OpenCV (any container and codec
// the installed FFmpeg reads). A drive is read front to back, so the reader decodes forward
// from where it stands and seeks only when asked for an earlier frame or one far ahead.
#include <memory>
#include <mutex>
#include <opencv2/core.hpp>
#include <string>

namespace cv {
class VideoCapture;
}

namespace parkloc::io {

class VideoReader {
 public:
  // Throws InputError when FFmpeg cannot open the file.
  explicit VideoReader(const std::string& path);
  ~VideoReader();
  VideoReader(const VideoReader&) = delete;
  VideoReader& operator=(const VideoReader&) = delete;

  const std::string& path() const { return path_; }
  // Frames as the container states them (0 when it does not say).
  int frameCount() const { return frame_count_; }

  // Frame `index` (from 0) as BGR; empty when it cannot be decoded, the reason in *why.
  // Safe to call from several threads (they take turns).
  cv::Mat frame(int index, std::string* why = nullptr);

 private:
  bool seekTo(int index);

  std::string path_;
  std::unique_ptr<cv::VideoCapture> capture_;
  int frame_count_ = 0;
  int next_ = 0;  // the index the next read() returns
  std::mutex mutex_;  // one decoder position
  // A frame decoded ahead of the one asked for (a damaged one skipped), and its index.
  cv::Mat ahead_;
  int ahead_index_ = -1;
};

}  // namespace parkloc::io
