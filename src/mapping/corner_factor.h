#pragma once
// The reprojection factor: one image corner of one sighting against the same corner of its
// landmark, projected through the vehicle pose of the sighting's frame set and the camera's
// calibration. Two residuals (pixels over pixel_sigma), with analytic Jacobians with respect to
// the pose (x, y, yaw), the landmark (x, y, heading, width, height) and the margin.
//
// The margin (pixels) is what the spotter's corners add around the painted glyphs: blur and
// the ink threshold spread an ink fit's edges outward by about a pixel whatever the range, and
// a detector's box is padded. The predicted corner is the projected one moved outward by the
// margin along the text's width and along its height, the directions taken from the sighting's
// own quad. A constant in pixels is many centimetres on the floor far from the camera and few
// close to it, so sightings at several ranges tell the margin from the text's true size;
// ignored, it makes every landmark too large (heights +9.7 % on average on the train and
// validation drives).
//
// Why the image and not the floor: the corner's noise is in pixels and about isotropic there,
// while its footprint on the floor grows with range and stretches along the ray on a fisheye
// (the pose solver of localize argues the same, pose_solver.h).
#include <ceres/autodiff_cost_function.h>
#include <ceres/sized_cost_function.h>

#include <Eigen/Core>
#include <array>

#include "geometry/rig.h"

namespace parkloc::mapping {

class CornerFactor : public ceres::SizedCostFunction<2, 3, 5, 1> {
 public:
  // `camera` must outlive the factor; `corner` indexes the reading order of `quad`, the
  // sighting's four image corners.
  CornerFactor(const geometry::RigCamera& camera, int corner,
               const std::array<Eigen::Vector2d, 4>& quad, double pixel_sigma);

  // Fails (false) where the corner does not project into the camera.
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

 private:
  const geometry::RigCamera& camera_;
  int corner_;
  Eigen::Vector2d pixel_;
  Eigen::Vector2d outward_;  // the corner's move per pixel of margin
  double pixel_sigma_;
};

// A prior on a margin: zero, within `sigma` pixels (1 sigma). Keeps the margin where few
// ranges are seen and it and the texts' sizes could trade places.
struct CornerMarginPrior {
  double sigma = 1.0;

  template <typename T>
  bool operator()(const T* margin, T* residual) const {
    residual[0] = margin[0] / T(sigma);
    return true;
  }

  static ceres::CostFunction* create(double sigma) {
    return new ceres::AutoDiffCostFunction<CornerMarginPrior, 1, 1>(new CornerMarginPrior{sigma});
  }
};

}  // namespace parkloc::mapping
