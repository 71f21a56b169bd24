#pragma once
// The vehicle a rig is mounted on, as one box in the vehicle frame. Its cameras sit on its skin,
// so they see its bumpers and sills, and it hides from them the floor under it and, from the
// front and rear cameras, the floor beside it: a text painted there is not visible to that
// camera, however wide its field of view.
#include <Eigen/Core>

namespace parkloc::geometry {

struct VehicleBody {
  Eigen::Vector3d lo, hi;  // vehicle frame (x forward, y left, z up), metres
};

// True when the segment from `from` to `to` (vehicle frame) runs through the body. `from` may
// lie on the body's skin (a camera): a segment leaving the skin outwards is free.
bool bodyBlocks(const VehicleBody& body, const Eigen::Vector3d& from, const Eigen::Vector3d& to);

// True when the ray from `origin` along `direction` (vehicle frame) meets the body.
bool bodyHitsRay(const VehicleBody& body, const Eigen::Vector3d& origin,
                 const Eigen::Vector3d& direction);

}  // namespace parkloc::geometry
