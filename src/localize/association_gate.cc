#include "localize/association_gate.h"

#include <Eigen/Cholesky>

#include "localize/pose_solver.h"

namespace parkloc::localize {

std::optional<GateResult> gateObservation(const geometry::RigCamera& camera,
                                          const LandmarkObservation& observation,
                                          const geometry::Pose2& predicted,
                                          const Eigen::Matrix3d& covariance,
                                          const GateOptions& options) {
  Eigen::Vector2d predicted_centre = Eigen::Vector2d::Zero();
  Eigen::Matrix<double, 2, 3> J = Eigen::Matrix<double, 2, 3>::Zero();
  std::array<Eigen::Vector2d, 4> predicted_corners;
  for (int i = 0; i < 4; ++i) {
    const auto p = projectMapCorner(camera, predicted, observation.map_corners[i]);
    if (!p) return std::nullopt;
    predicted_corners[i] = p->pixel;
    predicted_centre += 0.25 * p->pixel;
    J += 0.25 * p->J_pixel_pose;
  }
  Eigen::Vector2d observed_centre = Eigen::Vector2d::Zero();
  for (const auto& p : observation.pixels) observed_centre += 0.25 * p;

  Eigen::Matrix3d P = withMapPositionError(covariance, observation.accuracy);
  const double floor_sigma = options.min_radius_m / 3.0;
  P(0, 0) += floor_sigma * floor_sigma;
  P(1, 1) += floor_sigma * floor_sigma;
  const Eigen::Matrix2d S = J * P * J.transpose() + options.centre_sigma_px *
                                                        options.centre_sigma_px *
                                                        Eigen::Matrix2d::Identity();
  const Eigen::Vector2d nu = observed_centre - predicted_centre;

  // Reading direction: from the left edge's midpoint to the right edge's.
  const auto direction = [](const std::array<Eigen::Vector2d, 4>& c) -> Eigen::Vector2d {
    return 0.5 * (c[1] + c[2]) - 0.5 * (c[0] + c[3]);
  };
  GateResult result;
  result.mahalanobis2 = nu.dot(S.ldlt().solve(nu));
  result.reading_order_agrees =
      direction(observation.pixels).dot(direction(predicted_corners)) > 0.0;
  return result;
}

}  // namespace parkloc::localize
