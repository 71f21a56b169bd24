#include "localize/paper_projection.h"

#include <cmath>
#include <limits>
#include <map>

#include "geometry/pose.h"

namespace parkloc::localize {

Eigen::Vector2d textCentre(const std::array<Eigen::Vector2d, 4>& polygon, bool from_polygon) {
  if (from_polygon) return 0.25 * (polygon[0] + polygon[1] + polygon[2] + polygon[3]);
  Eigen::Vector2d lo = polygon[0], hi = polygon[0];
  for (const auto& p : polygon) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return 0.5 * (lo + hi);
}

std::optional<PaperObservation> paperObserve(const geometry::GroundHomography& homography,
                                             const geometry::CameraModel& model,
                                             const std::array<Eigen::Vector2d, 4>& polygon,
                                             bool centre_from_polygon) {
  const auto centre = homography.groundFromPixel(model, textCentre(polygon, centre_from_polygon));
  if (!centre) return std::nullopt;
  PaperObservation o;
  o.relative = *centre;
  const auto left = homography.groundFromPixel(model, 0.5 * (polygon[0] + polygon[3]));
  const auto right = homography.groundFromPixel(model, 0.5 * (polygon[1] + polygon[2]));
  if (left && right && (*right - *left).norm() > 1e-6) {
    const Eigen::Vector2d d = *right - *left;
    o.reading_angle = std::atan2(d.y(), d.x());
  }
  return o;
}

std::optional<PaperFix> paperFuse(const std::vector<PaperObservation>& observations, double yaw,
                                  bool mcrp, bool mcap) {
  if (observations.empty()) return std::nullopt;
  struct PerLandmark {
    Eigen::Vector2d map_position;
    Eigen::Vector2d relative_sum = Eigen::Vector2d::Zero();
    int count = 0;
  };
  std::map<std::string, PerLandmark> landmarks;
  for (const auto& o : observations) {
    auto& l = landmarks[o.landmark_id];
    l.map_position = o.map_position;
    if (!mcrp && l.count > 0) continue;  // first camera only
    l.relative_sum += o.relative;
    ++l.count;
  }
  const geometry::Pose2 rotation(0.0, 0.0, yaw);
  PaperFix fix;
  double nearest = std::numeric_limits<double>::infinity();
  for (const auto& [id, l] : landmarks) {
    const Eigen::Vector2d relative = l.relative_sum / l.count;
    const Eigen::Vector2d position = l.map_position - rotation.rotation() * relative;
    if (mcap) {
      fix.position += position;
      ++fix.landmarks;
      fix.observations += l.count;
    } else if (relative.norm() < nearest) {
      nearest = relative.norm();
      fix.position = position;
      fix.landmarks = 1;
      fix.observations = l.count;
    }
  }
  if (mcap) fix.position /= fix.landmarks;
  return fix;
}

std::optional<double> headingFromTextDirections(const std::vector<PaperObservation>& obs) {
  double s = 0.0, c = 0.0;
  int n = 0;
  for (const auto& o : obs) {
    if (!o.reading_angle) continue;
    const double yaw = o.map_heading - *o.reading_angle;
    s += std::sin(yaw);
    c += std::cos(yaw);
    ++n;
  }
  if (n == 0 || std::hypot(s, c) < 1e-9) return std::nullopt;
  return std::atan2(s, c);
}

}  // namespace parkloc::localize
