#include "localize/floor_heights.h"

#include <algorithm>
#include <vector>

namespace parkloc::localize {

FloorHeights::FloorHeights(const map::HdMap& map) {
  std::map<std::string, std::vector<double>> heights;
  for (const auto& l : map.landmarks())
    if (l.surface == map::Surface::kGround) heights[l.level].push_back(l.position.z());
  for (auto& [level, z] : heights) {
    std::nth_element(z.begin(), z.begin() + z.size() / 2, z.end());
    floor_[level] = z[z.size() / 2];
  }
}

double FloorHeights::of(const std::string& level) const {
  const auto it = floor_.find(level);
  return it == floor_.end() ? 0.0 : it->second;
}

std::array<Eigen::Vector3d, 4> FloorHeights::cornersAboveFloor(
    const map::Landmark& landmark) const {
  auto corners = landmark.corners();
  const double floor = of(landmark.level);
  for (auto& c : corners) c.z() -= floor;
  return corners;
}

Eigen::Vector3d FloorHeights::centreAboveFloor(const map::Landmark& landmark) const {
  return landmark.position - Eigen::Vector3d(0.0, 0.0, of(landmark.level));
}

}  // namespace parkloc::localize
