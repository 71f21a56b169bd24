#include "geometry/planar_fit.h"

#include <Eigen/Geometry>
#include <cmath>

namespace parkloc::geometry {

std::optional<PlanarFit> fitPlanar(const std::vector<Eigen::Vector2d>& from,
                                   const std::vector<Eigen::Vector2d>& to, bool with_scale) {
  const size_t n = from.size();
  if (n < 2 || to.size() != n) return std::nullopt;
  Eigen::Matrix2Xd a(2, n), b(2, n);
  for (size_t i = 0; i < n; ++i) {
    a.col(i) = from[i];
    b.col(i) = to[i];
  }
  const Eigen::Vector2d mean_a = a.rowwise().mean();
  if ((a.colwise() - mean_a).squaredNorm() < 1e-12) return std::nullopt;
  const Eigen::Matrix3d T = Eigen::umeyama(a, b, with_scale);
  PlanarFit fit;
  const Eigen::Matrix2d sR = T.topLeftCorner<2, 2>();
  fit.scale = with_scale ? std::sqrt(std::fabs(sR.determinant())) : 1.0;
  const double yaw = std::atan2(sR(1, 0), sR(0, 0));
  fit.to_from_from = Pose2(T(0, 2), T(1, 2), yaw);
  double sum = 0.0;
  for (size_t i = 0; i < n; ++i) {
    const double r = (fit.apply(from[i]) - to[i]).norm();
    fit.residuals.push_back(r);
    sum += r * r;
  }
  fit.rms = std::sqrt(sum / static_cast<double>(n));
  return fit;
}

}  // namespace parkloc::geometry
