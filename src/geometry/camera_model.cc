#include "geometry/camera_model.h"

#include <Eigen/LU>
#include <cmath>

namespace parkloc::geometry {
namespace {

// theta_d(theta) of the Kannala-Brandt model and its derivative.
double fisheyeDistort(const std::array<double, 4>& k, double theta) {
  const double t2 = theta * theta;
  return theta * (1.0 + t2 * (k[0] + t2 * (k[1] + t2 * (k[2] + t2 * k[3]))));
}
double fisheyeDistortDerivative(const std::array<double, 4>& k, double theta) {
  const double t2 = theta * theta;
  return 1.0 + t2 * (3.0 * k[0] + t2 * (5.0 * k[1] + t2 * (7.0 * k[2] + t2 * 9.0 * k[3])));
}

Eigen::Vector2d radtanDistort(const std::array<double, 4>& d, const Eigen::Vector2d& p) {
  const double x = p.x(), y = p.y();
  const double r2 = x * x + y * y;
  const double radial = 1.0 + r2 * (d[0] + r2 * d[1]);
  return {x * radial + 2.0 * d[2] * x * y + d[3] * (r2 + 2.0 * x * x),
          y * radial + d[2] * (r2 + 2.0 * y * y) + 2.0 * d[3] * x * y};
}

}  // namespace

std::string toString(CameraModelType type) {
  return type == CameraModelType::kFisheye ? "fisheye" : "pinhole";
}

std::optional<CameraModelType> cameraModelTypeFromString(const std::string& name) {
  if (name == "fisheye" || name == "kannala_brandt") return CameraModelType::kFisheye;
  if (name == "pinhole") return CameraModelType::kPinhole;
  return std::nullopt;
}

std::optional<Eigen::Vector2d> CameraModel::project(const Eigen::Vector3d& p) const {
  if (type == CameraModelType::kPinhole) {
    if (p.z() <= 1e-12) return std::nullopt;
    const Eigen::Vector2d d = radtanDistort(distortion, p.head<2>() / p.z());
    return Eigen::Vector2d(fx * d.x() + cx, fy * d.y() + cy);
  }
  const double r_xy = p.head<2>().norm();
  if (r_xy < 1e-15) {
    if (p.z() <= 0.0) return std::nullopt;
    return Eigen::Vector2d(cx, cy);
  }
  // atan2 keeps the model valid past 90 degrees from the axis (195-degree lenses).
  const double theta = std::atan2(r_xy, p.z());
  if (theta > max_theta) return std::nullopt;
  const double scale = fisheyeDistort(distortion, theta) / r_xy;
  return Eigen::Vector2d(fx * p.x() * scale + cx, fy * p.y() * scale + cy);
}

std::optional<Eigen::Vector3d> CameraModel::unproject(const Eigen::Vector2d& pixel) const {
  const Eigen::Vector2d m((pixel.x() - cx) / fx, (pixel.y() - cy) / fy);
  if (type == CameraModelType::kPinhole) {
    // Invert the distortion by Newton's method on the 2x2 system.
    Eigen::Vector2d u = m;
    for (int iter = 0; iter < 30; ++iter) {
      const Eigen::Vector2d f = radtanDistort(distortion, u) - m;
      if (f.squaredNorm() < 1e-28) break;
      Eigen::Matrix2d J;
      const double h = 1e-7;
      for (int c = 0; c < 2; ++c) {
        Eigen::Vector2d du = Eigen::Vector2d::Zero();
        du[c] = h;
        J.col(c) =
            (radtanDistort(distortion, u + du) - radtanDistort(distortion, u - du)) / (2 * h);
      }
      u -= J.inverse() * f;
    }
    if ((radtanDistort(distortion, u) - m).norm() > 1e-9) return std::nullopt;
    return Eigen::Vector3d(u.x(), u.y(), 1.0).normalized();
  }
  const double theta_d = m.norm();
  if (theta_d < 1e-15) return Eigen::Vector3d(0.0, 0.0, 1.0);
  // Newton's method on theta_d(theta) = theta_d; the model is monotonic on [0, max_theta].
  double theta = theta_d;
  bool converged = false;
  for (int iter = 0; iter < 50; ++iter) {
    const double f = fisheyeDistort(distortion, theta) - theta_d;
    const double df = fisheyeDistortDerivative(distortion, theta);
    if (df <= 0.0) return std::nullopt;
    const double step = f / df;
    theta -= step;
    if (std::abs(step) < 1e-14) {
      converged = true;
      break;
    }
  }
  if (!converged || theta < 0.0 || theta > max_theta) return std::nullopt;
  const double s = std::sin(theta) / theta_d;
  return Eigen::Vector3d(m.x() * s, m.y() * s, std::cos(theta));
}

bool CameraModel::inImage(const Eigen::Vector2d& pixel, double margin) const {
  return pixel.x() >= -0.5 + margin && pixel.y() >= -0.5 + margin &&
         pixel.x() <= width - 0.5 - margin && pixel.y() <= height - 0.5 - margin;
}

}  // namespace parkloc::geometry
