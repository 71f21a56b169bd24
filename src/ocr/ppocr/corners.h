#pragma once
// Refinement: the reported corners are re-fitted to the text's ink (ocr/corner_refinement.h),
// because the localization measures with them and DB's boxes are loose rectangles in the raw
// fisheye image.
#include <opencv2/core.hpp>
#include <optional>

#include "geometry/rig.h"
#include "ocr/corner_refinement.h"
#include "ocr/quad.h"

namespace parkloc::ocr {

struct CornerOptions {
  bool refine = true;           // false: the detected box is reported as it is
  CornerRefinementOptions fit;  // how the ink is found and the fit checked
};

// The corners fitted to the ink (on the ground plane when `camera` is given, else in the
// crop) when the fit is plausible (plausibleRefinement); empty when it is not, or when
// options.refine is off.
std::optional<Quad> inkFittedCorners(const cv::Mat& image, const Quad& quad,
                                     const CornerOptions& options,
                                     const geometry::RigCamera* camera);

// inkFittedCorners, else `quad` itself.
Quad refinedCorners(const cv::Mat& image, const Quad& quad, const CornerOptions& options,
                    const geometry::RigCamera* camera);

}  // namespace parkloc::ocr
