#include "mapping/landmark_seed.h"

#include <algorithm>
#include <cmath>

namespace parkloc::mapping {
namespace {

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

}  // namespace

LandmarkEstimate seedLandmark(const TextTrack& track,
                              const std::vector<std::optional<CastSighting>>& cast) {
  std::vector<double> xs, ys, widths, heights;
  Eigen::Vector2d direction = Eigen::Vector2d::Zero();
  for (size_t i : track.sightings) {
    if (!cast[i]) continue;
    const auto& c = cast[i]->corners;
    xs.push_back(cast[i]->centre.x());
    ys.push_back(cast[i]->centre.y());
    const Eigen::Vector2d along = 0.5 * (c[1] - c[0] + c[2] - c[3]);
    const Eigen::Vector2d across = 0.5 * (c[0] - c[3] + c[1] - c[2]);
    widths.push_back(along.norm());
    heights.push_back(across.norm());
    if (along.norm() > 0.0) direction += along.normalized();
  }
  LandmarkEstimate l;
  l.text = track.text;
  l.cls = track.cls;
  l.parameters[kX] = median(xs);
  l.parameters[kY] = median(ys);
  l.parameters[kHeading] = std::atan2(direction.y(), direction.x());
  l.parameters[kWidth] = median(widths);
  l.parameters[kHeight] = median(heights);
  l.sightings = static_cast<int>(track.sightings.size());
  l.frame_sets = track.frame_sets;
  l.misreads = track.misreads;
  return l;
}

}  // namespace parkloc::mapping
