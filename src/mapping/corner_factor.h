#pragma once
// The reprojection factor: one image corner of one sighting against the same corner of its
// landmark, projected through the vehicle pose of the sighting's frame set and the camera's
// calibration. Two residuals (pixels over pixel_sigma), with analytic Jacobians with respect to
// the pose (x, y, yaw) and the landmark (x, y, heading, width, height).
//
// Why the image and not the floor: the corner's noise is in pixels and about isotropic there,
// while its footprint on the floor grows with range and stretches along the ray on a fisheye
// (the pose solver of localize argues the same, pose_solver.h).
#include <ceres/sized_cost_function.h>

#include <Eigen/Core>

#include "geometry/rig.h"

namespace parkloc::mapping {

class CornerFactor : public ceres::SizedCostFunction<2, 3, 5> {
 public:
  // `camera` must outlive the factor; `corner` indexes the reading order.
  CornerFactor(const geometry::RigCamera& camera, int corner, const Eigen::Vector2d& pixel,
               double pixel_sigma)
      : camera_(camera), corner_(corner), pixel_(pixel), pixel_sigma_(pixel_sigma) {}

  // Fails (false) where the corner does not project into the camera.
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

 private:
  const geometry::RigCamera& camera_;
  int corner_;
  Eigen::Vector2d pixel_;
  double pixel_sigma_;
};

}  // namespace parkloc::mapping
