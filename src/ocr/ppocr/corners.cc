#include "ocr/ppocr/corners.h"

namespace parkloc::ocr {

std::optional<Quad> inkFittedCorners(const cv::Mat& image, const Quad& quad,
                                     const CornerOptions& options,
                                     const geometry::RigCamera* camera) {
  if (!options.refine) return std::nullopt;
  std::optional<Quad> refined;
  if (camera != nullptr) refined = refineOnGround(image, quad, *camera, options.fit);
  if (!refined) refined = refineInCrop(image, quad, options.fit);
  if (refined && plausibleRefinement(quad, *refined, options.fit)) return refined;
  return std::nullopt;
}

Quad refinedCorners(const cv::Mat& image, const Quad& quad, const CornerOptions& options,
                    const geometry::RigCamera* camera) {
  return inkFittedCorners(image, quad, options, camera).value_or(quad);
}

}  // namespace parkloc::ocr
