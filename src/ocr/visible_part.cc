#include "ocr/visible_part.h"

#include "geometry/seen_span.h"

namespace parkloc::ocr {
namespace {

// Bilinear point of the quad: u along the reading direction (TL -> TR), v across (TL -> BL).
cv::Point2f pointAt(const Quad& q, float u, float v) {
  const cv::Point2f top = (1.f - u) * q[0] + u * q[1];
  const cv::Point2f bottom = (1.f - u) * q[3] + u * q[2];
  return (1.f - v) * top + v * bottom;
}

}  // namespace

std::optional<VisiblePart> visiblePart(const Quad& quad,
                                       const std::function<bool(const cv::Point2f&)>& visible,
                                       const VisiblePartOptions& options) {
  geometry::SeenSpanOptions grid;
  grid.samples_u = options.samples_along;
  grid.samples_v = options.samples_across;
  grid.min_share = options.min_share;
  const auto span = geometry::seenSpan(
      [&](double u, double v) {
        return visible(pointAt(quad, static_cast<float>(u), static_cast<float>(v)));
      },
      grid);
  if (!span) return std::nullopt;
  // The span runs over whole grid cells; a text wholly seen gives the quad itself.
  const auto u0 = static_cast<float>(span->u0), u1 = static_cast<float>(span->u1);
  const auto v0 = static_cast<float>(span->v0), v1 = static_cast<float>(span->v1);
  VisiblePart part;
  part.quad = {pointAt(quad, u0, v0), pointAt(quad, u1, v0), pointAt(quad, u1, v1),
               pointAt(quad, u0, v1)};
  part.length_fraction = u1 - u0;
  part.height_fraction = v1 - v0;
  return part;
}

}  // namespace parkloc::ocr
