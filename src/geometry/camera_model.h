#pragma once
// Camera models: Kannala-Brandt fisheye (the k1..k4 model of OpenCV's cv::fisheye) and
// pinhole with radial-tangential distortion (OpenCV's k1, k2, p1, p2).
//
// Camera frame as OpenCV: x right, y down, z forward. Pixel convention as OpenCV:
// integer coordinates at pixel centres, (0, 0) is the centre of the top-left pixel.
#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>

namespace parkloc::geometry {

enum class CameraModelType { kFisheye, kPinhole };

std::string toString(CameraModelType type);
std::optional<CameraModelType> cameraModelTypeFromString(const std::string& name);

struct CameraModel {
  CameraModelType type = CameraModelType::kFisheye;
  int width = 0;
  int height = 0;
  double fx = 0.0, fy = 0.0, cx = 0.0, cy = 0.0;
  // Fisheye: k1, k2, k3, k4 of theta_d = theta (1 + k1 theta^2 + ... + k4 theta^8).
  // Pinhole: k1, k2, p1, p2.
  std::array<double, 4> distortion{0.0, 0.0, 0.0, 0.0};
  // Largest angle from the optical axis that the model maps (fisheye only), radians.
  double max_theta = 1.75;

  // 3-D point in the camera frame -> pixel. Empty when the point is behind a pinhole
  // camera, outside the fisheye's field of view, or at the centre of projection.
  std::optional<Eigen::Vector2d> project(const Eigen::Vector3d& point_in_camera) const;

  // Pixel -> unit ray in the camera frame. Empty when the distortion cannot be inverted
  // there (outside the model's valid domain).
  std::optional<Eigen::Vector3d> unproject(const Eigen::Vector2d& pixel) const;

  bool inImage(const Eigen::Vector2d& pixel, double margin = 0.0) const;
};

}  // namespace parkloc::geometry
