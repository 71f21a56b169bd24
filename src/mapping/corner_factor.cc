#include "mapping/corner_factor.h"

#include <cmath>

#include "localize/pose_solver.h"
#include "mapping/landmark_estimate.h"

namespace parkloc::mapping {

namespace {

constexpr double kWidthSign[4] = {-1.0, 1.0, 1.0, -1.0};
constexpr double kHeightSign[4] = {1.0, 1.0, -1.0, -1.0};

Eigen::Vector2d unitOrZero(const Eigen::Vector2d& v) {
  const double n = v.norm();
  return n > 0.0 ? Eigen::Vector2d(v / n) : Eigen::Vector2d::Zero();
}

}  // namespace

CornerFactor::CornerFactor(const geometry::RigCamera& camera, int corner,
                           const std::array<Eigen::Vector2d, 4>& quad, double pixel_sigma)
    : camera_(camera),
      corner_(corner),
      pixel_(quad[static_cast<size_t>(corner)]),
      pixel_sigma_(pixel_sigma) {
  // Along the reading (left to right) and down the text (top to bottom), as the image shows it.
  const Eigen::Vector2d along = unitOrZero(quad[1] - quad[0] + quad[2] - quad[3]);
  const Eigen::Vector2d down = unitOrZero(quad[3] - quad[0] + quad[2] - quad[1]);
  outward_ = kWidthSign[corner] * along - kHeightSign[corner] * down;
}

bool CornerFactor::Evaluate(double const* const* parameters, double* residuals,
                            double** jacobians) const {
  const double* pose = parameters[0];
  const double* landmark = parameters[1];
  const double margin = parameters[2][0];
  double corners[4][3];
  floorCorners(landmark, corners);
  const Eigen::Vector3d corner(corners[corner_][0], corners[corner_][1], corners[corner_][2]);
  const auto projected =
      localize::projectMapCorner(camera_, geometry::Pose2(pose[0], pose[1], pose[2]), corner);
  if (!projected) return false;
  Eigen::Map<Eigen::Vector2d> r(residuals);
  r = (projected->pixel + margin * outward_ - pixel_) / pixel_sigma_;
  if (jacobians == nullptr) return true;
  if (jacobians[0] != nullptr) {
    Eigen::Map<Eigen::Matrix<double, 2, 3, Eigen::RowMajor>> J_pose(jacobians[0]);
    J_pose = projected->J_pixel_pose / pixel_sigma_;
  }
  if (jacobians[1] != nullptr) {
    // d corner / d (x, y, heading, width, height), as floorCorners builds it.
    const double c = std::cos(landmark[kHeading]), s = std::sin(landmark[kHeading]);
    const double sw = kWidthSign[corner_], sh = kHeightSign[corner_];
    const double hw = 0.5 * landmark[kWidth], hh = 0.5 * landmark[kHeight];
    Eigen::Matrix<double, 3, 5> J_corner_landmark = Eigen::Matrix<double, 3, 5>::Zero();
    J_corner_landmark(0, kX) = 1.0;
    J_corner_landmark(1, kY) = 1.0;
    J_corner_landmark(0, kHeading) = -sw * hw * s - sh * hh * c;
    J_corner_landmark(1, kHeading) = sw * hw * c - sh * hh * s;
    J_corner_landmark(0, kWidth) = 0.5 * sw * c;
    J_corner_landmark(1, kWidth) = 0.5 * sw * s;
    J_corner_landmark(0, kHeight) = -0.5 * sh * s;
    J_corner_landmark(1, kHeight) = 0.5 * sh * c;
    Eigen::Map<Eigen::Matrix<double, 2, 5, Eigen::RowMajor>> J_landmark(jacobians[1]);
    J_landmark = projected->J_pixel_corner * J_corner_landmark / pixel_sigma_;
  }
  if (jacobians[2] != nullptr) {
    Eigen::Map<Eigen::Vector2d> J_margin(jacobians[2]);
    J_margin = outward_ / pixel_sigma_;
  }
  return true;
}

}  // namespace parkloc::mapping
