#pragma once
// Single-frame SE(2) pose from every corner of every associated text (beyond the paper):
// robust (Huber IRLS) Gauss-Newton on the reprojection error in the image, with analytic
// Jacobians.
//
// Why the image and not the ground: the corner noise is in pixels and roughly isotropic
// there, while its footprint on the ground grows with range and is strongly anisotropic on
// a fisheye; reprojection weights every corner correctly, needs no plane assumption for
// pillar text (its map corners are 3-D) and degrades gracefully near the horizon, where a
// ray/ground intersection blows up. Ray/plane casting is used only to initialise.
//
// The map is not exact: each landmark's position (x, y), heading, width and height carry a
// survey error, and the size is the nominal painted one, not the ink box. These five are
// nuisance parameters of each text, marginalised into its residuals: the 8 corner residuals
// of one text have the covariance pixel_sigma^2 I + J_l Sigma_l J_l^T, with J_l = d(corner
// pixels) / d(landmark x, y, heading, log width, log height) and Sigma_l the map's sigmas, so
// one landmark's position error moves all four of its corners together instead of counting as
// four independent measurements. Each text's residuals are whitened by the Cholesky factor of
// that covariance (in units of pixel_sigma^2); Huber IRLS then acts on the whitened corners,
// and the covariance comes from the whitened normal equations.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "geometry/pose.h"
#include "geometry/rig.h"
#include "localize/landmark_observation.h"
#include "localize/map_error_term.h"

namespace parkloc::localize {

struct SolverOptions {
  double pixel_sigma = 1.5;         // corner noise (1 sigma, pixels) for the covariance
  double huber_threshold_px = 3.0;  // Huber IRLS threshold on a corner's pixel error
  int max_iterations = 20;
  double step_tolerance = 1e-8;  // converged when |dx| + |dy| + |dyaw| falls below
  // (or when a step lowers the cost by less than 1e-12 of it)
  // Hypothesis scoring: an observation is an inlier when its mean corner error is below.
  double inlier_threshold_px = 10.0;
  // An outlier whose polygon centre (not corners) lies within this of its prediction
  // takes part with its centre only (0: off; on a real-OCR drive it cost accuracy).
  double centre_fallback_px = 0.0;
  int max_hypotheses = 8;  // single-text hypotheses tried by solvePose (the largest texts)
  // A map that states its accuracy is a survey: its width and height are the nominal painted
  // size, not the ink box (relative, 1 sigma; stencils and their paint differ by some per
  // cent).
  double map_size_sigma = 0.05;
  // Where the map states no accuracy (1 sigma). 0: taken as exact, as the maps of parkloc's
  // simulator are (ink boxes at their true place). Measured on the validation drives with
  // real OCR on exact maps: 2 cm / 0.5 degrees / 5 % moved the mean error from 1.6 to 2.4 cm,
  // 0.5 cm / 0.1 degrees / 5 % to 2.3 cm, 0 / 0 / 5 % to 2.1 cm; 0 / 0 / 0 keeps 1.6 cm.
  double assumed_map_position_sigma_m = 0.0;
  double assumed_map_heading_sigma_deg = 0.0;
  double assumed_map_size_sigma = 0.0;
};

struct SolverResult {
  bool ok = false;         // a pose came out (converged, enough corners, well conditioned)
  bool converged = false;  // the Gauss-Newton step fell below step_tolerance
  std::string failure;     // why not ok
  int iterations = 0;
  geometry::Pose2 pose;                                  // map_from_vehicle
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();  // (x, y, yaw)
  // The part of `covariance` the map's error makes: `covariance` less what it would be with
  // an exact map. Unlike the pixel noise it does not average out over frames that see the
  // same landmarks.
  Eigen::Matrix3d map_covariance = Eigen::Matrix3d::Zero();
  // The same split made exact through the solve's linearisation: the pose moves by
  // J_fix_map e for each inlier landmark's map error e (map_terms, landmarks the map states
  // an accuracy for), and by pixel noise with covariance `pixel_covariance`. With Huber
  // weights all 1, pixel_covariance + sum J Sigma_e J^T = covariance.
  std::vector<MapErrorTerm> map_terms;
  Eigen::Matrix3d pixel_covariance = Eigen::Matrix3d::Zero();
  double rms_px = 0.0;  // over inlier corners, whitened
  // Per observation, in input order: mean corner error (pixels, whitened by the map's error;
  // infinity when it does not project) and whether it was used.
  std::vector<double> residual_px;
  std::vector<bool> inlier;
};

// The reprojection of one map corner for pose map_from_vehicle, with d pixel / d (x, y, yaw).
struct CornerProjection {
  Eigen::Vector2d pixel;
  Eigen::Matrix<double, 2, 3> J_pixel_pose;
  Eigen::Matrix<double, 2, 3> J_pixel_corner;  // d pixel / d map corner (x, y, z)
};
std::optional<CornerProjection> projectMapCorner(const geometry::RigCamera& camera,
                                                 const geometry::Pose2& map_from_vehicle,
                                                 const Eigen::Vector3d& map_corner);

// The pose covariance as a landmark's image sees it: the landmark's stated map position error
// (map::MapAccuracy) moves its image as the vehicle's position does, so its variance adds to
// the pose's x and y (its heading error is small beside the pose's yaw for a text's extent).
Eigen::Matrix3d withMapPositionError(const Eigen::Matrix3d& pose_covariance,
                                     const map::MapAccuracy& accuracy);

// Closed-form pose from one observation: each corner's ray meets the horizontal plane at
// the corner's height (the ground for painted text; for pillar text the map gives the
// height), then a 2-D rigid alignment of the four points. Empty when a ray misses.
std::optional<geometry::Pose2> poseFromObservation(const geometry::RigCamera& camera,
                                                   const LandmarkObservation& observation);

// Gauss-Newton with Huber weights from `initial`, using the observations with use[i] set
// (all when `use` is empty).
SolverResult refinePose(const geometry::Rig& rig, const std::vector<LandmarkObservation>& obs,
                        const geometry::Pose2& initial, const SolverOptions& options = {},
                        const std::vector<bool>& use = {});

// Robust solve: hypotheses from each observation alone (and from `prior` when given),
// the one with the most inliers (ties: the smaller error) refined on its inliers.
SolverResult solvePose(const geometry::Rig& rig, const std::vector<LandmarkObservation>& obs,
                       const std::optional<geometry::Pose2>& prior = std::nullopt,
                       const SolverOptions& options = {});

}  // namespace parkloc::localize
