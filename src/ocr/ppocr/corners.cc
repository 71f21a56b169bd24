#include "ocr/ppocr/corners.h"

#include <optional>

namespace parkloc::ocr {

Quad refinedCorners(const cv::Mat& image, const Quad& quad, const CornerOptions& options,
                    const geometry::RigCamera* camera) {
  if (!options.refine) return quad;
  std::optional<Quad> refined;
  if (camera != nullptr) refined = refineOnGround(image, quad, *camera, options.fit);
  if (!refined) refined = refineInCrop(image, quad, options.fit);
  return refined && plausibleRefinement(quad, *refined, options.fit) ? *refined : quad;
}

}  // namespace parkloc::ocr
