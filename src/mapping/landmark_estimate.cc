#include "mapping/landmark_estimate.h"

#include "geometry/pose.h"

namespace parkloc::mapping {

map::Landmark LandmarkEstimate::toLandmark(const std::string& level) const {
  map::Landmark l;
  l.id = level.empty() ? text : level + ":" + text;
  l.text = text;
  l.cls = cls;
  l.level = level;
  l.position = {parameters[kX], parameters[kY], 0.0};
  l.heading = geometry::wrapAngle(parameters[kHeading]);
  l.width = parameters[kWidth];
  l.height = parameters[kHeight];
  l.surface = map::Surface::kGround;
  l.normal = Eigen::Vector3d::UnitZ();
  l.accuracy.position_sigma = position_sigma;
  l.accuracy.heading_sigma = heading_sigma;
  return l;
}

}  // namespace parkloc::mapping
