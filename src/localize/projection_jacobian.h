#pragma once
// Camera projection with its analytic Jacobian d pixel / d point (camera frame), for the
// Gauss-Newton pose solver. Matches geometry::CameraModel::project exactly (tested against
// it and against central differences).
#include <Eigen/Core>
#include <optional>

#include "geometry/camera_model.h"

namespace parkloc::localize {

struct ProjectionWithJacobian {
  Eigen::Vector2d pixel;
  Eigen::Matrix<double, 2, 3> J_pixel_point;
};

// Empty where CameraModel::project is empty.
std::optional<ProjectionWithJacobian> projectWithJacobian(const geometry::CameraModel& model,
                                                          const Eigen::Vector3d& point_in_camera);

}  // namespace parkloc::localize
