#include "ocr/placed_size.h"

namespace parkloc::ocr {
namespace {

// Moves the two corners of each pair toward their midpoint by `factor` (< 1 tightens).
void pullTogether(cv::Point2f& a, cv::Point2f& b, float factor) {
  const cv::Point2f mid = 0.5f * (a + b);
  a = mid + factor * (a - mid);
  b = mid + factor * (b - mid);
}

}  // namespace

PlacedSizeFit fitToPlacedSize(const Quad& quad, float width, float height, bool whole,
                              const PlacedSizeOptions& options) {
  PlacedSizeFit fit{PlacedSize::kKept, quad};
  if (width <= 0.f || height <= 0.f) return fit;
  const float length = quadWidth(quad), across = quadHeight(quad);
  if (whole && length < options.min_length_share * width) {
    fit.verdict = PlacedSize::kRefused;
    return fit;
  }
  Quad& q = fit.quad;
  if (across > options.max_height_ratio * height) {
    // Left edge (TL, BL) and right edge (TR, BR) shrink about their midpoints.
    pullTogether(q[0], q[3], height / across);
    pullTogether(q[1], q[2], height / across);
    fit.verdict = PlacedSize::kTightened;
  }
  if (whole && length > options.max_length_ratio * width) {
    pullTogether(q[0], q[1], width / length);
    pullTogether(q[3], q[2], width / length);
    fit.verdict = PlacedSize::kTightened;
  }
  return fit;
}

PlacedSizeFit fitUnmatchedToPlacedSize(const Quad& quad, float width, float height,
                                       const cv::Point2f& reading,
                                       const PlacedSizeOptions& options) {
  if (!orientedAlong(quad, reading, options.unmatched_max_angle)) return {PlacedSize::kKept, quad};
  return fitToPlacedSize(quad, width, height, true, options);
}

}  // namespace parkloc::ocr
