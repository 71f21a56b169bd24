#include "ocr/visible_part.h"

#include <algorithm>
#include <vector>

namespace parkloc::ocr {
namespace {

// Bilinear point of the quad: u along the reading direction (TL -> TR), v across (TL -> BL).
cv::Point2f pointAt(const Quad& q, float u, float v) {
  const cv::Point2f top = (1.f - u) * q[0] + u * q[1];
  const cv::Point2f bottom = (1.f - u) * q[3] + u * q[2];
  return (1.f - v) * top + v * bottom;
}

// Sample k of n at the centre of its cell, so the samples cover [0, 1] evenly.
float centreOf(int k, int n) { return (static_cast<float>(k) + 0.5f) / static_cast<float>(n); }

// First and last index whose share reaches `min_share`; empty when none does.
std::optional<std::pair<int, int>> seenRange(const std::vector<float>& shares, float min_share) {
  int first = -1, last = -1;
  for (int k = 0; k < static_cast<int>(shares.size()); ++k)
    if (shares[k] >= min_share) {
      if (first < 0) first = k;
      last = k;
    }
  if (first < 0) return std::nullopt;
  return std::make_pair(first, last);
}

}  // namespace

std::optional<VisiblePart> visiblePart(const Quad& quad,
                                       const std::function<bool(const cv::Point2f&)>& visible,
                                       const VisiblePartOptions& options) {
  const int nu = std::max(options.samples_along, 1), nv = std::max(options.samples_across, 1);
  std::vector<unsigned char> seen(static_cast<size_t>(nu * nv));
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j)
      seen[i * nv + j] = visible(pointAt(quad, centreOf(i, nu), centreOf(j, nv))) ? 1 : 0;

  std::vector<float> column_share(nu, 0.f);
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) column_share[i] += seen[i * nv + j];
    column_share[i] /= static_cast<float>(nv);
  }
  const auto columns = seenRange(column_share, options.min_share);
  if (!columns) return std::nullopt;
  // Rows are judged over the seen columns only, so a cut along the length does not hide them.
  const int span = columns->second - columns->first + 1;
  std::vector<float> row_share(nv, 0.f);
  for (int j = 0; j < nv; ++j) {
    for (int i = columns->first; i <= columns->second; ++i) row_share[j] += seen[i * nv + j];
    row_share[j] /= static_cast<float>(span);
  }
  const auto rows = seenRange(row_share, options.min_share);
  if (!rows) return std::nullopt;

  // The span runs over whole grid cells; a text wholly seen gives the quad itself.
  const float u0 = static_cast<float>(columns->first) / nu;
  const float u1 = static_cast<float>(columns->second + 1) / nu;
  const float v0 = static_cast<float>(rows->first) / nv;
  const float v1 = static_cast<float>(rows->second + 1) / nv;
  VisiblePart part;
  part.quad = {pointAt(quad, u0, v0), pointAt(quad, u1, v0), pointAt(quad, u1, v1),
               pointAt(quad, u0, v1)};
  part.length_fraction = u1 - u0;
  part.height_fraction = v1 - v0;
  return part;
}

}  // namespace parkloc::ocr
