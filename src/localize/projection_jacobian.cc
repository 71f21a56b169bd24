#include "localize/projection_jacobian.h"

#include <cmath>

namespace parkloc::localize {
namespace {

std::optional<ProjectionWithJacobian> fisheye(const geometry::CameraModel& m,
                                              const Eigen::Vector3d& p) {
  const auto& k = m.distortion;
  const double x = p.x(), y = p.y(), z = p.z();
  const double r2 = x * x + y * y;
  const double r = std::sqrt(r2);
  ProjectionWithJacobian out;
  if (r < 1e-15) {
    if (z <= 0.0) return std::nullopt;
    // On the axis theta_d / r -> 1 / z (theta_d ~ theta ~ r / z).
    out.pixel = {m.cx, m.cy};
    out.J_pixel_point << m.fx / z, 0.0, 0.0, 0.0, m.fy / z, 0.0;
    return out;
  }
  const double theta = std::atan2(r, z);
  if (theta > m.max_theta) return std::nullopt;
  const double t2 = theta * theta;
  const double theta_d = theta * (1.0 + t2 * (k[0] + t2 * (k[1] + t2 * (k[2] + t2 * k[3]))));
  const double dtheta_d =
      1.0 + t2 * (3.0 * k[0] + t2 * (5.0 * k[1] + t2 * (7.0 * k[2] + t2 * 9.0 * k[3])));
  const double s = theta_d / r;  // pixel = f * s * (x, y) + c
  // theta = atan2(r, z): d theta / d(x, y, z) = (z x / r, z y / r, -r) / (r^2 + z^2).
  const double rho2 = r2 + z * z;
  const Eigen::Vector3d dtheta(z * x / (r * rho2), z * y / (r * rho2), -r / rho2);
  // s = theta_d(theta) / r: ds = dtheta_d dtheta / r - theta_d dr / r^2, dr = (x, y, 0) / r.
  const Eigen::Vector3d dr(x / r, y / r, 0.0);
  const Eigen::Vector3d ds = (dtheta_d / r) * dtheta - (theta_d / r2) * dr;
  out.pixel = {m.fx * s * x + m.cx, m.fy * s * y + m.cy};
  out.J_pixel_point.row(0) = m.fx * (x * ds.transpose() + Eigen::RowVector3d(s, 0.0, 0.0));
  out.J_pixel_point.row(1) = m.fy * (y * ds.transpose() + Eigen::RowVector3d(0.0, s, 0.0));
  return out;
}

std::optional<ProjectionWithJacobian> pinhole(const geometry::CameraModel& m,
                                              const Eigen::Vector3d& p) {
  if (p.z() <= 1e-12) return std::nullopt;
  const auto& d = m.distortion;  // k1, k2, p1, p2
  const double iz = 1.0 / p.z();
  const double a = p.x() * iz, b = p.y() * iz;
  const double r2 = a * a + b * b;
  const double radial = 1.0 + r2 * (d[0] + r2 * d[1]);
  const double dradial_dr2 = d[0] + 2.0 * d[1] * r2;
  const double xd = a * radial + 2.0 * d[2] * a * b + d[3] * (r2 + 2.0 * a * a);
  const double yd = b * radial + d[2] * (r2 + 2.0 * b * b) + 2.0 * d[3] * a * b;
  // d(xd, yd) / d(a, b)
  Eigen::Matrix2d J_d_ab;
  J_d_ab(0, 0) = radial + a * dradial_dr2 * 2.0 * a + 2.0 * d[2] * b + d[3] * 6.0 * a;
  J_d_ab(0, 1) = a * dradial_dr2 * 2.0 * b + 2.0 * d[2] * a + d[3] * 2.0 * b;
  J_d_ab(1, 0) = b * dradial_dr2 * 2.0 * a + d[2] * 2.0 * a + 2.0 * d[3] * b;
  J_d_ab(1, 1) = radial + b * dradial_dr2 * 2.0 * b + d[2] * 6.0 * b + 2.0 * d[3] * a;
  // d(a, b) / d(x, y, z)
  Eigen::Matrix<double, 2, 3> J_ab_p;
  J_ab_p << iz, 0.0, -a * iz, 0.0, iz, -b * iz;
  ProjectionWithJacobian out;
  out.pixel = {m.fx * xd + m.cx, m.fy * yd + m.cy};
  out.J_pixel_point = Eigen::DiagonalMatrix<double, 2>(m.fx, m.fy) * J_d_ab * J_ab_p;
  return out;
}

}  // namespace

std::optional<ProjectionWithJacobian> projectWithJacobian(const geometry::CameraModel& model,
                                                          const Eigen::Vector3d& point_in_camera) {
  if (model.type == geometry::CameraModelType::kPinhole) return pinhole(model, point_in_camera);
  return fisheye(model, point_in_camera);
}

}  // namespace parkloc::localize
