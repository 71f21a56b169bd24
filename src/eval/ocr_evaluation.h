#pragma once
// Table 3 of the paper: the text spotter alone, full frame, on every labelled camera image of
// the drives, scored against the labels (ICDAR matching, eval/ocr_metrics.h) overall, per
// class, per condition and for the parking numbers per frame set and per drive.
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "eval/ocr_metrics.h"
#include "io/labels.h"
#include "io/tum.h"
#include "map/placed_texts.h"
#include "ocr/text_spotter.h"

namespace parkloc::eval {

struct Progress {
  std::string stage;  // e.g. "sequence 2/5 test_garage_b1_tour"
  size_t done = 0;    // frame sets done in this stage
  size_t total = 0;
};
using ProgressCallback = std::function<void(const Progress&)>;

struct OcrRunOptions {
  OcrEvaluationOptions metrics;
  size_t max_frames_per_sequence = 0;  // 0: all
  bool use_lexicon = true;             // decode against the map's texts
  // A localization run's estimated poses per drive (its folder name; `parkloc run`'s
  // trajectory.tum): each frame set's floor boxes then decode against the texts the map
  // places near them under the pose predicted from the estimate before it
  // (eval/pose_prediction.h, map/placed_texts.h). Drives without one, and frame sets with no
  // recent estimate before them, decode against the whole lexicon as without.
  std::map<std::string, std::vector<io::StampedPose>> estimated_poses;
  double placement_range_m =
      map::kFloorViewReachM;        // texts placed around the vehicle (the floor views' reach)
  double placement_radius_m = 1.0;  // ocr::SpotRequest::placement_radius_m
  ProgressCallback progress;
  // Called with every scored image: the drive's folder name, its labels and what the
  // spotter found (for per-instance outcomes, eval/text_outcomes.h).
  std::function<void(const std::string& sequence, const io::ImageLabels& labels,
                     const std::vector<ocr::TextInstance>& found)>
      on_image;
};

// Table 3 of the paper: full-frame spotting of every labelled camera image.
OcrEvaluation evaluateOcr(const std::vector<std::string>& sequences, ocr::TextSpotter& spotter,
                          const OcrRunOptions& options = {});

}  // namespace parkloc::eval
