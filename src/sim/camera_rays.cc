#include "sim/camera_rays.h"

#include <algorithm>
#include <cmath>
#include <opencv2/core/utility.hpp>

namespace parkloc::sim {

CameraRays buildCameraRays(const geometry::CameraModel& model, float vignetting) {
  CameraRays r;
  r.width = model.width;
  r.height = model.height;
  const size_t n = static_cast<size_t>(r.width) * r.height;
  r.rays.assign(n, Eigen::Vector3f::Zero());
  r.pixel_angle.assign(n, 0.0f);
  r.vignette.assign(n, 0.0f);
  cv::parallel_for_(cv::Range(0, r.height), [&](const cv::Range& range) {
    for (int y = range.start; y < range.end; ++y)
      for (int x = 0; x < r.width; ++x) {
        const auto ray = model.unproject(Eigen::Vector2d(x, y));
        if (ray) r.rays[static_cast<size_t>(y) * r.width + x] = ray->cast<float>();
      }
  });
  const double rmax = std::hypot(r.width / 2.0, r.height / 2.0);
  for (int y = 0; y < r.height; ++y)
    for (int x = 0; x < r.width; ++x) {
      const size_t i = static_cast<size_t>(y) * r.width + x;
      const Eigen::Vector3f& a = r.rays[i];
      if (a.isZero()) continue;
      const Eigen::Vector3f& b = r.rays[x + 1 < r.width ? i + 1 : i - 1];
      const Eigen::Vector3f& c = r.rays[y + 1 < r.height ? i + r.width : i - r.width];
      const float da = b.isZero() ? 0.0f : std::acos(std::clamp(a.dot(b), -1.0f, 1.0f));
      const float db = c.isZero() ? 0.0f : std::acos(std::clamp(a.dot(c), -1.0f, 1.0f));
      r.pixel_angle[i] =
          std::max(1e-4f, std::sqrt(da * db) > 0.0f ? std::sqrt(da * db) : std::max(da, db));
      const double rr = std::hypot(x - model.cx, y - model.cy) / rmax;
      r.vignette[i] = static_cast<float>(1.0 - vignetting * rr * rr);
    }
  return r;
}

std::vector<CameraRays> buildRigRays(const geometry::Rig& rig) {
  std::vector<CameraRays> out;
  for (const auto& c : rig.cameras) out.push_back(buildCameraRays(c.model));
  return out;
}

}  // namespace parkloc::sim
