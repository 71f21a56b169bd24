#pragma once
// Height of each level's floor in the map frame, so that a landmark's corners can be
// expressed as heights above the floor the vehicle stands on (the solver's plane z = 0).
#include <Eigen/Core>
#include <array>
#include <map>
#include <string>

#include "map/hd_map.h"

namespace parkloc::localize {

class FloorHeights {
 public:
  FloorHeights() = default;
  // The median height of the ground (painted) text of each level; 0 for a level without.
  explicit FloorHeights(const map::HdMap& map);

  double of(const std::string& level) const;
  // The landmark's corners (reading order) with z relative to its level's floor.
  std::array<Eigen::Vector3d, 4> cornersAboveFloor(const map::Landmark& landmark) const;
  Eigen::Vector3d centreAboveFloor(const map::Landmark& landmark) const;

 private:
  std::map<std::string, double> floor_;
};

}  // namespace parkloc::localize
