#include "ocr/tracked_text_fit.h"

#include <cmath>

namespace parkloc::ocr {

std::optional<Quad> fitTrackedText(const cv::Mat& image, const Quad& predicted,
                                   const geometry::RigCamera* camera,
                                   const TrackedFitOptions& options,
                                   const CornerRefinementOptions& ink) {
  CornerRefinementOptions refinement = ink;
  refinement.search_expand_x = options.search_expand_x;
  refinement.search_expand_y = options.search_expand_y;
  refinement.crop_height = options.crop_height;
  std::optional<Quad> fitted;
  if (camera != nullptr) fitted = refineOnGround(image, predicted, *camera, refinement);
  if (!fitted) fitted = refineInCrop(image, predicted, refinement);
  if (!fitted) return std::nullopt;

  const float w = quadWidth(predicted), h = quadHeight(predicted);
  if (w <= 0.f || h <= 0.f) return std::nullopt;
  const float rw = quadWidth(*fitted) / w, rh = quadHeight(*fitted) / h;
  if (rw < options.min_width_ratio || rw > options.max_width_ratio) return std::nullopt;
  if (rh < options.min_height_ratio || rh > options.max_height_ratio) return std::nullopt;
  const cv::Point2f shift = 0.25f * (((*fitted)[0] + (*fitted)[1] + (*fitted)[2] + (*fitted)[3]) -
                                     (predicted[0] + predicted[1] + predicted[2] + predicted[3]));
  if (std::hypot(shift.x, shift.y) > options.max_centre_shift * w) return std::nullopt;
  return fitted;
}

}  // namespace parkloc::ocr
