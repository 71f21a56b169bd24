#include "mapping/sighting_cast.h"

#include "geometry/ground_projection.h"

namespace parkloc::mapping {

std::optional<CastSighting> castOnFloor(const Sighting& sighting, const geometry::Rig& rig,
                                        const geometry::Pose2& map_from_vehicle) {
  if (sighting.camera < 0 || static_cast<size_t>(sighting.camera) >= rig.cameras.size())
    return std::nullopt;
  const geometry::RigCamera& camera = rig.cameras[static_cast<size_t>(sighting.camera)];
  CastSighting cast;
  Eigen::Vector2d centre_in_vehicle = Eigen::Vector2d::Zero();
  for (int i = 0; i < 4; ++i) {
    const auto on_floor =
        geometry::pixelToPlane(camera, sighting.pixels[i], geometry::Plane::ground());
    if (!on_floor) return std::nullopt;
    centre_in_vehicle += 0.25 * on_floor->head<2>();
    cast.corners[i] = map_from_vehicle * Eigen::Vector2d(on_floor->head<2>());
    cast.centre += 0.25 * cast.corners[i];
  }
  cast.range_m = centre_in_vehicle.norm();
  return cast;
}

}  // namespace parkloc::mapping
