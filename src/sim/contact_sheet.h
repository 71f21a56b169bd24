#pragma once
// A contact sheet of dataset frames: each row one frame set (all cameras side by side),
// optionally with the label polygons drawn (green visible, red occluded >= 0.5), for looking
// at what the simulator makes.
#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace parkloc::sim {

struct ContactSheetRow {
  std::string sequence_dir;  // DIR/sequences/<name>
  double timestamp = 0.0;
  std::string caption;
};

// Reads the images (and labels when `draw_labels`) of each row; each image is scaled to
// fit a `tile_width` x 10/16 `tile_width` tile, its aspect kept. Missing images are drawn grey.
cv::Mat makeContactSheet(const std::vector<ContactSheetRow>& rows,
                         const std::vector<std::string>& cameras, int tile_width = 480,
                         bool draw_labels = false);

}  // namespace parkloc::sim
