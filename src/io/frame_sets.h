#pragma once
// Frame sets from the capture times of each camera: the cameras of a surround-view rig are
// rarely triggered together, so a frame set holds one image per camera, each the one captured
// nearest to the set's time. The camera with the most images sets the pace (a set per image of
// it); another camera's image joins the set nearest in time when within the tolerance, and
// images that join none (the pacing camera dropped that frame) form sets among themselves,
// spanning at most twice the tolerance. A set's time is its earliest image's; each image keeps
// its own capture time.
#include <map>
#include <string>
#include <vector>

namespace parkloc::io {

struct FrameSet {
  double timestamp = 0.0;  // the earliest capture time of its images
  // camera -> index into that camera's capture times
  std::map<std::string, size_t> images;
};

// The tolerance that goes with the cameras' frame rates: 0.45 times the smallest median
// interval between a camera's consecutive frames (cameras may lead or lag one another by up to
// that much, an image is never nearer to two sets), and 1 microsecond when no camera has two
// frames (identical times only).
double frameSetTolerance(const std::map<std::string, std::vector<double>>& times);

// `times`: per camera, ascending capture times. Sets in ascending time.
std::vector<FrameSet> groupFrameSets(const std::map<std::string, std::vector<double>>& times,
                                     double tolerance);

}  // namespace parkloc::io
