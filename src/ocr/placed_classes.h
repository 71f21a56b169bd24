#pragma once
// Under a predicted pose the map says which classes a floor box is likely to take: those of
// the texts it places near the box. A number read as what shows of it ("008" for the cut
// "C008"), or not read at all, is still a parking number where the map paints one, and a box
// where the map paints none is not one: every parking number is in the map, not every mark on
// the floor.
#include <Eigen/Core>
#include <vector>

#include "map/placed_texts.h"
#include "ocr/text_classifier.h"

namespace parkloc::ocr {

// Prior weights of the floor classes for a box at `vehicle_xy`: 1 for the classes of the
// texts placed within `radius` metres of it; for other floor text, `unplaced_other` when only
// parking numbers are placed there (a mark or a plate beside a number) and 1 where nothing is;
// 0 for a parking number placed nowhere near, and for pillar text (text found on the floor is
// not a pillar's).
ClassWeights floorClassWeightsNear(const std::vector<map::PlacedText>& placed,
                                   const Eigen::Vector2d& vehicle_xy, double radius,
                                   float unplaced_other);

}  // namespace parkloc::ocr
