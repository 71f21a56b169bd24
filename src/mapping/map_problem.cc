#include "mapping/map_problem.h"

#include <ceres/ceres.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "common/error.h"
#include "mapping/corner_factor.h"
#include "mapping/odometry_factor.h"

namespace parkloc::mapping {

namespace {

// `calibrated`: the drive's constant scale error is estimated, so the white noise is all the
// odometry factor has to allow for.
OdometrySigmas odometrySigmas(const geometry::Pose2& motion, const EstimationOptions& o,
                              bool calibrated) {
  const double distance = motion.translation().norm();
  const double per_m = calibrated ? o.odometry_calibrated_sigma_per_m : o.odometry_sigma_per_m;
  const double position = std::max(o.odometry_min_sigma_m, per_m * distance);
  return {position, position,
          std::max(o.odometry_min_yaw_sigma_rad, o.odometry_yaw_sigma_per_m * distance)};
}

// Every sigma and scale divides a residual: zero or less would fill the solution with NaN.
void requirePositive(const EstimationOptions& o) {
  const std::pair<const char*, double> values[] = {
      {"pixel_sigma", o.pixel_sigma},
      {"robust_scale", o.robust_scale},
      {"margin_prior_sigma_px", o.margin_prior_sigma_px},
      {"odometry_min_sigma_m", o.odometry_min_sigma_m},
      {"odometry_min_yaw_sigma_rad", o.odometry_min_yaw_sigma_rad},
      {"distance_scale_prior_sigma", o.distance_scale_prior_sigma},
      {"yaw_rate_bias_prior_sigma", o.yaw_rate_bias_prior_sigma}};
  for (const auto& [name, value] : values)
    if (!(value > 0.0))
      throw InputError(
          fmt::format("map_build.estimation.{} must be positive, not {}", name, value));
  if (!(o.odometry_sigma_per_m >= 0.0) || !(o.odometry_calibrated_sigma_per_m >= 0.0) ||
      !(o.odometry_yaw_sigma_per_m >= 0.0))
    throw InputError(
        "map_build.estimation.odometry_sigma_per_m, odometry_calibrated_sigma_per_m and "
        "odometry_yaw_sigma_per_m must not be negative");
}

}  // namespace

MapProblem::MapProblem(std::vector<DriveState>& drives, std::vector<LandmarkEstimate>& landmarks,
                       const std::vector<Sighting>& sightings, const std::vector<TextTrack>& tracks,
                       const EstimationOptions& options)
    : drives_(drives), landmarks_(landmarks), options_(options) {
  requirePositive(options);
  ceres::Problem::Options problem_options;
  // Factors are owned by the problem; the loss is shared by all corners and owned here.
  problem_options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  problem_ = std::make_unique<ceres::Problem>(problem_options);
  loss_ = std::make_unique<ceres::CauchyLoss>(options.robust_scale);

  for (DriveState& drive : drives_) {
    for (auto& pose : drive.poses) problem_->AddParameterBlock(pose.data(), 3);
    double* calibration = drive.odometry_calibration.data();
    problem_->AddParameterBlock(calibration, 2);
    double distance = 0.0;
    for (const geometry::Pose2& m : drive.motion) distance += m.translation().norm();
    const bool calibrated =
        options.estimate_odometry_calibration && distance >= options.calibration_min_distance_m;
    if (calibrated)
      problem_->AddResidualBlock(
          OdometryCalibrationPrior::create(options.distance_scale_prior_sigma,
                                           options.yaw_rate_bias_prior_sigma),
          nullptr, calibration);
    else
      problem_->SetParameterBlockConstant(calibration);
    for (double& margin : drive.corner_margin_px) {
      problem_->AddParameterBlock(&margin, 1);
      if (options.estimate_corner_margin)
        problem_->AddResidualBlock(CornerMarginPrior::create(options.margin_prior_sigma_px),
                                   nullptr, &margin);
      else
        problem_->SetParameterBlockConstant(&margin);
    }
    for (size_t i = 0; i + 1 < drive.poses.size() && i < drive.motion.size(); ++i) {
      const double seconds = i < drive.seconds.size() ? drive.seconds[i] : 0.0;
      problem_->AddResidualBlock(
          OdometryFactor::create(drive.motion[i], seconds,
                                 odometrySigmas(drive.motion[i], options, calibrated)),
          nullptr, drive.poses[i].data(), drive.poses[i + 1].data(), calibration);
      ++odometry_factors_;
    }
  }
  if (!drives_.empty() && !drives_.front().poses.empty())
    problem_->SetParameterBlockConstant(drives_.front().poses.front().data());

  for (size_t t = 0; t < tracks.size() && t < landmarks_.size(); ++t) {
    double* landmark = landmarks_[t].parameters.data();
    problem_->AddParameterBlock(landmark, 5);
    // A text is at least a few centimetres across: keeps the size away from the sign flip.
    problem_->SetParameterLowerBound(landmark, kWidth, 0.02);
    problem_->SetParameterLowerBound(landmark, kHeight, 0.02);
    for (size_t i : tracks[t].sightings) {
      const Sighting& s = sightings[i];
      DriveState& drive = drives_[s.drive];
      const geometry::RigCamera& camera = drive.rig->cameras[static_cast<size_t>(s.camera)];
      double* margin = &drive.corner_margin_px[s.box_only ? 1 : 0];
      for (int k = 0; k < 4; ++k) {
        auto factor = std::make_unique<CornerFactor>(camera, k, s.pixels, options.pixel_sigma);
        // A corner that does not project into its camera from where the landmark starts (a
        // sighting cast far off its landmark's seed) would fail the solver's first evaluation
        // and with it the whole solve: it is left out.
        const double* at[3] = {drive.poses[s.frame].data(), landmark, margin};
        double residual[2];
        if (!factor->Evaluate(at, residual, nullptr)) {
          ++unprojected_corners_;
          continue;
        }
        const ceres::ResidualBlockId id = problem_->AddResidualBlock(
            factor.release(), loss_.get(), drive.poses[s.frame].data(), landmark, margin);
        corners_.push_back({t, id});
      }
    }
  }
}

MapProblem::~MapProblem() = default;

EstimationSummary MapProblem::solve() {
  ceres::Solver::Options options;
  options.max_num_iterations = options_.max_iterations;
  options.num_threads = options_.threads;
  options.linear_solver_type =
      ceres::IsSparseLinearAlgebraLibraryTypeAvailable(ceres::SUITE_SPARSE) ||
              ceres::IsSparseLinearAlgebraLibraryTypeAvailable(ceres::EIGEN_SPARSE)
          ? ceres::SPARSE_NORMAL_CHOLESKY
          : ceres::DENSE_QR;
  ceres::Solver::Summary summary;
  ceres::Solve(options, problem_.get(), &summary);
  EstimationSummary out;
  out.converged = summary.termination_type == ceres::CONVERGENCE;
  out.message = summary.message;
  out.iterations = static_cast<int>(summary.iterations.size());
  out.initial_cost = summary.initial_cost;
  out.final_cost = summary.final_cost;
  out.seconds = summary.total_time_in_seconds;
  out.corner_factors = static_cast<int>(corners_.size());
  out.unprojected_corners = unprojected_corners_;
  out.odometry_factors = odometry_factors_;
  for (LandmarkEstimate& l : landmarks_)
    l.parameters[kHeading] = geometry::wrapAngle(l.parameters[kHeading]);
  return out;
}

void MapProblem::measureResiduals() {
  std::vector<double> sum(landmarks_.size(), 0.0);
  std::vector<int> count(landmarks_.size(), 0);
  std::vector<std::vector<double>> errors(landmarks_.size());
  for (LandmarkEstimate& l : landmarks_) l.outlier_corners = 0;
  for (const CornerBlock& block : corners_) {
    const auto id = static_cast<ceres::ResidualBlockId>(block.residual_id);
    double r[2];
    double cost = 0.0;
    if (!problem_->EvaluateResidualBlock(id, /*apply_loss_function=*/false, &cost, r, nullptr))
      continue;
    const double px2 = (r[0] * r[0] + r[1] * r[1]) * options_.pixel_sigma * options_.pixel_sigma;
    sum[block.landmark] += px2;
    ++count[block.landmark];
    errors[block.landmark].push_back(std::sqrt(px2));
    if (std::sqrt(px2) > options_.robust_scale * options_.pixel_sigma)
      ++landmarks_[block.landmark].outlier_corners;
  }
  for (size_t t = 0; t < landmarks_.size(); ++t) {
    landmarks_[t].rms_px = count[t] > 0 ? std::sqrt(sum[t] / count[t]) : 0.0;
    auto& e = errors[t];
    if (e.empty()) continue;
    std::nth_element(e.begin(), e.begin() + static_cast<long>(e.size() / 2), e.end());
    landmarks_[t].median_px = e[e.size() / 2];
  }
}

}  // namespace parkloc::mapping
