#pragma once
// A per-frame budget for map-guided spotting (beyond the paper, for real time). Each
// region costs the OCR engine a warp, a detection and a recognition (~18 ms of CPU), and
// a tracked vehicle predicts dozens of them per frame set; the EKF with wheel odometry
// carries the pose between measurements, so a few well-chosen regions per frame suffice.
// Chosen are the largest (nearest) predicted texts, at least one per camera that sees
// something, the cameras served in turn, preferring landmarks not asked for lately.
#include <map>
#include <string>
#include <vector>

#include "ocr/text_spotter.h"

namespace parkloc::localize {

// One predicted region with what the budget needs to rank it.
struct RegionCandidate {
  ocr::RegionOfInterest roi;
  std::string landmark_id;
  double size_px = 0.0;    // longest side of the predicted text quad
  double height_px = 0.0;  // extent across the reading direction (small: grazing view)
  // While the level is undecided: a place whose text differs between levels (a level sign),
  // whose reading tells the level.
  bool tells_level = false;
};

struct RegionBudgetOptions {
  int max_regions = 4;            // per frame set over all cameras; <= 0: no budget
  int first_camera = 0;           // served first (the caller rotates it frame by frame)
  double min_height_px = 6.0;     // flatter predicted text is not read reliably: skipped
  double max_rank_size_px = 256;  // larger text ranks as this (patches are 256 px wide)
  int max_age_frames = 10;        // "not asked for in this many frames" counts as never
};

// Per camera, the indices of the chosen candidates (in the order given). `last_asked`
// holds, per landmark id, the frame index at which it was last chosen; `frame_index` is
// the current one. Without a budget every candidate is chosen (tiny ones included).
std::vector<std::vector<size_t>> selectRegionsWithinBudget(
    const std::vector<std::vector<RegionCandidate>>& per_camera,
    const std::map<std::string, int>& last_asked, int frame_index,
    const RegionBudgetOptions& options = {});

}  // namespace parkloc::localize
