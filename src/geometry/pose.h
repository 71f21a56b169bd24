#pragma once
// Pose types. SE(3) is Eigen::Isometry3d (named Rigid3 here); SE(2) is Pose2, a planar
// pose (x, y, yaw) used for the vehicle on a garage level. Transforms are named by what
// they map, e.g. map_from_vehicle maps vehicle-frame coordinates into the map frame.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

namespace parkloc::geometry {

using Rigid3 = Eigen::Isometry3d;

// Wraps an angle to (-pi, pi].
inline double wrapAngle(double a) {
  a = std::fmod(a + M_PI, 2.0 * M_PI);
  if (a <= 0.0) a += 2.0 * M_PI;
  return a - M_PI;
}

struct Pose2 {
  double x = 0.0;
  double y = 0.0;
  double yaw = 0.0;

  Pose2() = default;
  Pose2(double x_, double y_, double yaw_) : x(x_), y(y_), yaw(wrapAngle(yaw_)) {}

  Eigen::Vector2d translation() const { return {x, y}; }
  Eigen::Matrix2d rotation() const {
    const double c = std::cos(yaw), s = std::sin(yaw);
    return (Eigen::Matrix2d() << c, -s, s, c).finished();
  }
  Eigen::Vector2d operator*(const Eigen::Vector2d& p) const {
    return rotation() * p + translation();
  }
  Pose2 operator*(const Pose2& other) const {
    const Eigen::Vector2d t = (*this) * other.translation();
    return {t.x(), t.y(), yaw + other.yaw};
  }
  Pose2 inverse() const {
    const Eigen::Vector2d t = -(rotation().transpose() * translation());
    return {t.x(), t.y(), -yaw};
  }

  // The same pose as an SE(3) transform in the ground plane (z = 0).
  Rigid3 toRigid3() const {
    Rigid3 T = Rigid3::Identity();
    T.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    T.translation() = Eigen::Vector3d(x, y, 0.0);
    return T;
  }
  // Projects an SE(3) transform onto the ground plane (keeps x, y and the heading).
  static Pose2 fromRigid3(const Rigid3& T) {
    const Eigen::Vector3d heading = T.linear().col(0);
    return {T.translation().x(), T.translation().y(), std::atan2(heading.y(), heading.x())};
  }
};

}  // namespace parkloc::geometry
