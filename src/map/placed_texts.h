#pragma once
// A tracked vehicle knows where it is to a few centimetres, so it knows which floor numbers
// can lie under each box it finds: the map's texts placed in the vehicle frame under a
// predicted pose. A box then decodes against the few texts placed near it instead of every
// text of the garage, which the recognizer would otherwise confuse across the garage (D007
// read as D002, five bays away). The "lexicon of the texts near a predicted pose".
#include <Eigen/Core>
#include <string>
#include <vector>

#include "geometry/pose.h"
#include "map/hd_map.h"

namespace parkloc::map {

// A map text and where its centre lies on the floor, in the vehicle frame (metres).
struct PlacedText {
  std::string text;
  Eigen::Vector2d vehicle_xy = Eigen::Vector2d::Zero();
};

// The texts painted on the floor of `level` (every level when empty) whose centre lies within
// `radius` metres of the vehicle at `map_from_vehicle`, placed in the vehicle frame.
std::vector<PlacedText> placeFloorTexts(const HdMap& map, const geometry::Pose2& map_from_vehicle,
                                        double radius, const std::string& level = "");

// The texts placed within `radius` metres of `vehicle_xy`, each once, nearest first.
std::vector<std::string> textsNear(const std::vector<PlacedText>& placed,
                                   const Eigen::Vector2d& vehicle_xy, double radius);

}  // namespace parkloc::map
