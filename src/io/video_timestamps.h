#pragma once
// The capture time of every frame of a camera's video: videos/<camera>.csv beside
// videos/<camera>.<ext>, a header `frame,timestamp` and one row per frame, the frame's index in
// the video (from 0) and its capture time in seconds on the clock of the odometry. Frames and
// times strictly increase; a frame the file does not list is not used (a dropped or skipped
// frame of the recording).
#include <string>
#include <vector>

namespace parkloc::io {

struct VideoFrameTime {
  int frame = 0;
  double timestamp = 0.0;
};

// Throws InputError naming the file and line of the first problem.
std::vector<VideoFrameTime> loadVideoTimestamps(const std::string& path);

}  // namespace parkloc::io
