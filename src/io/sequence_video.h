#pragma once
// A sequence's image folders recorded as videos: videos/<camera>.<ext> and videos/<camera>.csv
// (io/video_timestamps.h), the layout a vehicle's recorder gives. Used to store a drive
// compactly and to check that the pipeline reads a recording as it reads the image folders.
#include <string>

#include "io/sequence.h"

namespace parkloc::io {

struct SequenceVideoOptions {
  // FourCC of the codec and the file extension. "MJPG" in ".avi" is written by OpenCV's own
  // Motion-JPEG encoder at `mjpeg_quality`, so each frame is a JPEG as close to the source image
  // as a second JPEG pass allows; every other FourCC ("avc1" for H.264, "mp4v") goes through
  // FFmpeg at the bit rate OpenCV chooses for it (about one bit per pixel and frame).
  std::string fourcc = "MJPG";
  std::string extension = ".avi";
  // JPEG quality (1-100) of the MJPG frames. FFmpeg's MJPEG at OpenCV's bit rate reaches about
  // 41 dB PSNR on a render, quality 95 about 47 dB; the coarser frames cost fine print its
  // corner accuracy (docs/RESULTS.md, video input).
  int mjpeg_quality = 95;
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
