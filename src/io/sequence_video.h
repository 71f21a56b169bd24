#pragma once
// A sequence's image folders recorded as videos: videos/<camera>.<ext> and videos/<camera>.csv
// (io/video_timestamps.h), the layout a vehicle's recorder gives. Used to store a drive
// compactly and to check that the pipeline reads a recording as it reads the image folders.
#include <string>

#include "io/sequence.h"

namespace parkloc::io {

struct SequenceVideoOptions {
  // FourCC of the codec and the file extension; "MJPG" in ".avi" decodes to within JPEG
  // quantisation of the images, "mp4v" in ".mp4" is smaller and blurs fine print more.
  std::string fourcc = "MJPG";
  std::string extension = ".avi";
  // Nominal frame rate written to the container (the capture times are in the .csv).
  double fps = 10.0;
};

// Writes every camera of `sequence` that has images as `out_dir`/videos/<camera>.<ext> plus its
// timestamps; a frame set whose image of a camera is missing or corrupt is left out of that
// camera's video and timestamps. Copies calib.yaml, map.geojson and the optional files
// (odometry, ground truth, levels, labels, meta.json) beside them. Throws InputError when
// `out_dir` exists and is not empty, or when the codec is not available.
void writeSequenceVideos(const Sequence& sequence, const std::string& out_dir,
                         const SequenceVideoOptions& options = {});

}  // namespace parkloc::io
