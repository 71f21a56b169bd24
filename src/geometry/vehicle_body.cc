#include "geometry/vehicle_body.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace parkloc::geometry {

namespace {

// Slab test of the line origin + t * direction against the box for t in (0, t_max]: true when
// some such t lies inside. A start on the skin (t = 0 on a face) counts only when the line
// goes inwards, so a camera mounted on the body does not hide what lies outside it.
bool entersBox(const VehicleBody& body, const Eigen::Vector3d& origin,
               const Eigen::Vector3d& direction, double t_max) {
  constexpr double kSkin = 1e-6;
  double t0 = 0.0, t1 = t_max;
  for (int a = 0; a < 3; ++a) {
    if (std::abs(direction[a]) < 1e-12) {
      if (origin[a] <= body.lo[a] || origin[a] >= body.hi[a]) return false;
      continue;
    }
    double ta = (body.lo[a] - origin[a]) / direction[a];
    double tb = (body.hi[a] - origin[a]) / direction[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  return t1 - t0 > kSkin;
}

}  // namespace

bool bodyBlocks(const VehicleBody& body, const Eigen::Vector3d& from, const Eigen::Vector3d& to) {
  return entersBox(body, from, to - from, 1.0);
}

bool bodyHitsRay(const VehicleBody& body, const Eigen::Vector3d& origin,
                 const Eigen::Vector3d& direction) {
  return entersBox(body, origin, direction, std::numeric_limits<double>::infinity());
}

}  // namespace parkloc::geometry
