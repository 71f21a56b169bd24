#pragma once
// Tracking a text that is already identified (beyond the paper, for real time): while the
// vehicle's pose is tracked, the map predicts where each known text lies in the image to
// a few pixels. Reading it again every frame costs the recognizer ~10 ms per crop on two
// CPU cores; fitting its corners to the ink costs well under a millisecond. The fit is
// accepted only when the ink box has the predicted size, so a fit that caught a slot
// line, a neighbour or half a number (occlusion, a wrong prediction) gives nothing.
#include <opencv2/core.hpp>
#include <optional>

#include "geometry/rig.h"
#include "ocr/corner_refinement.h"
#include "ocr/quad.h"

namespace parkloc::ocr {

struct TrackedFitOptions {
  // The predicted text box is searched for ink within these multiples of its size.
  float search_expand_x = 1.3f;
  float search_expand_y = 2.0f;
  // Fitted width (along the reading direction) and height over the predicted ones.
  float min_width_ratio = 0.8f, max_width_ratio = 1.25f;
  float min_height_ratio = 0.65f, max_height_ratio = 1.5f;
  // The fitted centre may be off the predicted one by this share of the predicted width.
  float max_centre_shift = 0.35f;
  int crop_height = 64;
};

// The ink's corners (reading order of `predicted`) around the predicted text quad: on the
// ground plane when `camera` is given and the text lies on the floor, else in the
// rectified crop. Empty when no ink of the predicted size and place is found. `ink` says how
// ink is told from the floor (its search window and crop come from `options`).
std::optional<Quad> fitTrackedText(const cv::Mat& image, const Quad& predicted,
                                   const geometry::RigCamera* camera,
                                   const TrackedFitOptions& options = {},
                                   const CornerRefinementOptions& ink = {});

}  // namespace parkloc::ocr
