#pragma once
// Stage 3 of map building, the estimation: the vehicle poses of every frame set and the
// landmarks (x, y, heading, width, height) as one sparse nonlinear least-squares problem
// (Ceres Solver). Odometry factors tie consecutive poses; a reprojection factor per corner of
// every sighting ties a pose to a landmark, under a robust loss so that a corner the detector
// put on a neighbour's ink or a shadow weighs little. A text seen again after a loop ties the
// poses of both passes to one landmark: that is the loop closure, with no place recognition
// needed, since each number is unique on its level.
//
// The gauge: the first pose of the first drive is held (the map's origin); anchors move the
// whole map afterwards (anchor_fit.h).
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "geometry/pose.h"
#include "geometry/rig.h"
#include "mapping/consensus.h"
#include "mapping/landmark_estimate.h"
#include "mapping/sightings.h"

namespace ceres {
class Problem;
class LossFunction;
}  // namespace ceres

namespace parkloc::mapping {

struct EstimationOptions {
  // Corner noise of the spotter (1 sigma, pixels).
  double pixel_sigma = 1.0;
  // Estimate each drive's corner margins (corner_factor.h): what the ink fits, and apart the
  // detector's boxes without a fit, add around the glyphs, in pixels, under a prior of
  // margin_prior_sigma_px. False: the corners are taken as the glyphs' own.
  bool estimate_corner_margin = true;
  double margin_prior_sigma_px = 2.0;
  // Cauchy loss scale on a corner's whitened error (in sigmas): a corner off by much more
  // is mostly ignored.
  double robust_scale = 3.0;
  // Odometry between consecutive frame sets (1 sigma): a floor for standstill plus a share of
  // the distance (slip), and the same for the yaw (gyro noise), once the drive's constant scale
  // and yaw-rate bias are estimated (below). On 60 s survey tours of a train and a validation
  // garage, 0.002 rad/m rather than 0.005 took the position RMS from 2.04 and 4.23 cm to 1.87
  // and 2.31 cm. The distance's share is larger where the drive's scale error is not
  // estimated, since it must take that up too: on the train and validation surveys
  // (calibrated) 0.01 rather than 0.02 per metre took the position RMS from 1.85 to 1.66 cm
  // (0.005: 1.64 cm) and the max from 4.55 to 3.86 cm, where on their ten short drives (taken
  // as measured) it took 1.69 to 1.76 cm.
  double odometry_min_sigma_m = 0.002;
  double odometry_sigma_per_m = 0.02;
  double odometry_calibrated_sigma_per_m = 0.01;
  double odometry_min_yaw_sigma_rad = 0.0005;
  double odometry_yaw_sigma_per_m = 0.002;
  // The drive's odometry calibration (odometry_factor.h) is estimated with the poses, under a
  // prior of these sigmas: a distance scale error of a few percent (the simulator's wheels err
  // by 0.5 % per drive, a wrong wheel radius by more) and a gyro bias of a fraction of a degree
  // per second (0.1 deg/s in the simulator). False: the odometry is taken as measured.
  // Only over a drive at least calibration_min_distance_m long: on the train and validation
  // drives of 12-19 s (18-28 m) the calibration made the maps no better (position RMS 1.58
  // against 1.44 cm on average; 3.35 against 2.02 cm on one), since over a short drive the
  // constant errors add up to little and their estimate takes up the corners' biases, while
  // on the 60 s surveys (127-139 m) it took the RMS from 3.02 and 2.50 to 1.87 and 2.31 cm.
  bool estimate_odometry_calibration = true;
  double calibration_min_distance_m = 100.0;
  double distance_scale_prior_sigma = 0.05;
  double yaw_rate_bias_prior_sigma = 0.01;  // rad/s
  int max_iterations = 100;
  int threads = 2;
};

// One drive's poses (x, y, yaw per frame set, the unknowns) and its odometry between them.
struct DriveState {
  const geometry::Rig* rig = nullptr;
  std::vector<std::array<double, 3>> poses;
  std::vector<geometry::Pose2> motion;  // motion[i]: pose i+1 in the frame of pose i
  std::vector<double> seconds;          // seconds[i]: the time from pose i to pose i+1
  // The odometry's distance scale and yaw-rate bias (rad/s; odometry_factor.h).
  std::array<double, 2> odometry_calibration{0.0, 0.0};
  // The corner margins (pixels; corner_factor.h) of the ink-fitted sightings and of those
  // without a fit (Sighting::box_only).
  std::array<double, 2> corner_margin_px{0.0, 0.0};
};

struct EstimationSummary {
  bool converged = false;
  std::string message;  // the solver's own line on how it ended
  int iterations = 0;
  double initial_cost = 0.0;
  double final_cost = 0.0;
  double seconds = 0.0;
  int corner_factors = 0;
  int unprojected_corners = 0;  // left out: behind their camera where the estimation starts
  int odometry_factors = 0;
};

class MapProblem {
 public:
  // `landmarks[t]` is the landmark of `tracks[t]`. The problem refers to `drives` and
  // `landmarks`: they must outlive it, and the solve writes into them.
  MapProblem(std::vector<DriveState>& drives, std::vector<LandmarkEstimate>& landmarks,
             const std::vector<Sighting>& sightings, const std::vector<TextTrack>& tracks,
             const EstimationOptions& options);
  ~MapProblem();

  EstimationSummary solve();
  // Fills each landmark's rms_px, median_px and outlier_corners from the corner factors'
  // errors.
  void measureResiduals();
  // Fills each landmark's position_sigma and heading_sigma from the covariance of the
  // solution; false (and the sigmas left empty) when Ceres cannot compute it (rank
  // deficient: a landmark seen from one place only along one ray).
  bool computeUncertainty(std::string* why);

 private:
  struct CornerBlock {
    size_t landmark;
    void* residual_id;
  };
  std::vector<DriveState>& drives_;
  std::vector<LandmarkEstimate>& landmarks_;
  EstimationOptions options_;
  std::unique_ptr<ceres::LossFunction> loss_;  // shared by the corner factors
  std::unique_ptr<ceres::Problem> problem_;
  std::vector<CornerBlock> corners_;
  int odometry_factors_ = 0;
  int unprojected_corners_ = 0;
};

}  // namespace parkloc::mapping
