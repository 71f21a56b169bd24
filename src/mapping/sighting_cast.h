#pragma once
// A sighting cast into the map through the vehicle pose of its frame set: each image corner's
// ray meets the floor (the plane z = 0 of the vehicle frame, where parking numbers are
// painted), and the points go into the map frame. It places a sighting for the consensus and
// gives the landmarks their first guess; the estimation itself works in the image.
#include <Eigen/Core>
#include <array>
#include <optional>

#include "geometry/pose.h"
#include "geometry/rig.h"
#include "mapping/sightings.h"

namespace parkloc::mapping {

struct CastSighting {
  // Map x, y in reading order.
  std::array<Eigen::Vector2d, 4> corners{Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero(),
                                         Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()};
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double range_m = 0.0;  // from the vehicle's origin to the text's centre
};

// Empty when a corner's ray does not meet the floor.
std::optional<CastSighting> castOnFloor(const Sighting& sighting, const geometry::Rig& rig,
                                        const geometry::Pose2& map_from_vehicle);

}  // namespace parkloc::mapping
