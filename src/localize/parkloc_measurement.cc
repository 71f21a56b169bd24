#include "localize/parkloc_measurement.h"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <string>

namespace parkloc::localize {
namespace {

// The solve's residuals and outliers into the associations of the observations it used.
void markSolve(const std::vector<LandmarkObservation>& obs, const SolverResult& solve,
               FrameResult& result) {
  for (size_t o = 0; o < obs.size(); ++o) {
    auto& a = result.associations[obs[o].tag];
    if (o < solve.residual_px.size() && std::isfinite(solve.residual_px[o]))
      a.residual_px = solve.residual_px[o];
    if (o < solve.inlier.size() && !solve.inlier[o]) a.verdict = AssociationVerdict::kSolverOutlier;
  }
}

// The distinct landmarks among the solve's inliers (only those read by OCR: `read_only`).
std::vector<std::string> landmarkIds(const std::vector<LandmarkObservation>& obs,
                                     const std::vector<bool>& inlier, bool read_only = false) {
  std::vector<std::string> ids;
  for (size_t o = 0; o < obs.size() && o < inlier.size(); ++o)
    if (inlier[o] && (obs[o].read || !read_only) &&
        std::find(ids.begin(), ids.end(), obs[o].landmark_id) == ids.end())
      ids.push_back(obs[o].landmark_id);
  return ids;
}
std::vector<std::string> landmarkIds(const std::vector<LandmarkObservation>& obs,
                                     const SolverResult& s) {
  return landmarkIds(obs, s.inlier);
}
int landmarksIn(const std::vector<LandmarkObservation>& obs, const SolverResult& s) {
  return static_cast<int>(landmarkIds(obs, s).size());
}

}  // namespace

Eigen::Matrix3d fixCovariance(const SolverResult& fix, double pixel_sigma,
                              const MeasurementOptions& options) {
  const double fit = pixel_sigma > 0.0 ? fix.rms_px / pixel_sigma : 0.0;
  Eigen::Matrix3d R =
      options.fix_covariance_inflation * std::max(1.0, fit * fit) *
          (fix.covariance - fix.map_covariance) +
      fix.map_covariance;
  const double yaw_floor = 0.05 * M_PI / 180.0;
  R.diagonal() += Eigen::Vector3d(1e-4, 1e-4, yaw_floor * yaw_floor);  // 1e-4 m^2: (1 cm)^2
  return R;
}

Eigen::Matrix3d fixPixelCovariance(const SolverResult& fix, double pixel_sigma,
                                   const MeasurementOptions& options) {
  const double fit = pixel_sigma > 0.0 ? fix.rms_px / pixel_sigma : 0.0;
  Eigen::Matrix3d R =
      options.fix_covariance_inflation * std::max(1.0, fit * fit) * fix.pixel_covariance;
  const double yaw_floor = 0.05 * M_PI / 180.0;
  R.diagonal() += Eigen::Vector3d(1e-4, 1e-4, yaw_floor * yaw_floor);  // 1e-4 m^2: (1 cm)^2
  return R;
}

PoseFix ParklocMeasurement::toFix(const SolverResult& solve,
                                  const std::vector<LandmarkObservation>& obs) const {
  PoseFix fix;
  fix.pose = solve.pose;
  fix.covariance = fixCovariance(solve, solver_.pixel_sigma, options_);
  fix.map_part = solve.map_covariance;
  fix.landmarks = landmarkIds(obs, solve);
  fix.read_landmarks = landmarkIds(obs, solve.inlier, true);
  fix.floor = options_.map_covariance_floor * solve.map_covariance;
  fix.map_terms = solve.map_terms;
  fix.pixel_part = fixPixelCovariance(solve, solver_.pixel_sigma, options_);
  return fix;
}

FrameFixes ParklocMeasurement::whileTracking(const std::vector<LandmarkObservation>& accepted,
                                             const std::vector<LandmarkObservation>& gated,
                                             const PoseEkf& ekf, bool tentative,
                                             FrameResult& result) const {
  FrameFixes fixes;
  if (!accepted.empty()) {
    const SolverResult s = solvePose(rig_, accepted, ekf.pose(), solver_);
    result.solver_iterations = s.iterations;
    result.solver_converged = s.converged;
    markSolve(accepted, s, result);
    if (s.ok) {
      const PoseFix fix = toFix(s, accepted);
      result.measurement = fix.pose;
      result.measurement_covariance = fix.covariance;
      if (fixDistance2(ekf, fix) <= tracking_.fix_gate_chi2) {
        fixes.agreeing = fix;
      } else {
        fixes.disagreeing = fix;
        fixes.disagreeing_landmarks = landmarksIn(accepted, s);
        result.warnings.push_back("pose fix outside the filter's gate");
      }
    } else {
      result.warnings.push_back("solver: " + s.failure);
    }
  }
  if (tentative && !fixes.disagreeing) {
    // A tentative track may rest on one misreading, and the fits that agree with it read
    // nothing: do the texts read this frame set, some of them gated away, place the
    // vehicle consistently somewhere else?
    std::vector<LandmarkObservation> reads;
    bool some_gated = false;
    for (const auto* list : {&accepted, &gated})
      for (const LandmarkObservation& o : *list)
        if (o.read) {
          reads.push_back(o);
          some_gated = some_gated || list == &gated;
        }
    if (some_gated) {
      const SolverResult s = solvePose(rig_, reads, std::nullopt, solver_);
      if (s.ok) {
        const PoseFix fix = toFix(s, reads);
        // Certain enough to start a filter with (first_fix_max_sigma_m) and outside the gate.
        const bool certain = tracking_.first_fix_max_sigma_m <= 0.0 ||
                             positionSigma(fix.covariance) <= tracking_.first_fix_max_sigma_m;
        if (certain && fixDistance2(ekf, fix) > tracking_.fix_gate_chi2) {
          fixes.disagreeing = fix;
          fixes.disagreeing_landmarks = landmarksIn(reads, s);
          result.warnings.push_back("tentative track: the texts read place the vehicle elsewhere");
          if (!result.measurement) {
            result.measurement = fix.pose;
            result.measurement_covariance = fix.covariance;
          }
        }
      }
    }
  }
  if (!fixes.agreeing && !fixes.disagreeing && !gated.empty()) {
    // Everything seen is far from the prediction: is it a consistent other place?
    std::vector<LandmarkObservation> all = accepted;
    all.insert(all.end(), gated.begin(), gated.end());
    const SolverResult s = solvePose(rig_, all, std::nullopt, solver_);
    PoseFix fix;
    fix.pose = s.pose;
    if (s.ok) fix = toFix(s, all);
    if (s.ok && fixDistance2(ekf, fix) > tracking_.fix_gate_chi2) {
      fixes.disagreeing = fix;
      fixes.disagreeing_landmarks = landmarksIn(all, s);
      if (!result.measurement) {
        result.measurement = fix.pose;
        result.measurement_covariance = fix.covariance;
      }
    }
  }
  return fixes;
}

FrameFixes ParklocMeasurement::whileSearching(const std::vector<LandmarkObservation>& accepted,
                                              SearchWindow& window, FrameResult& result) const {
  FrameFixes fixes;
  if (accepted.empty()) return fixes;
  // This frame set's texts and those of the last few, carried by odometry.
  const SearchWindow::Combined all = window.combine(rig_, accepted);
  SolverResult s = solvePose(all.rig, all.observations, std::nullopt, solver_);
  // The window's texts count towards the landmarks the fix rests on.
  std::vector<std::string> read_landmarks = landmarkIds(all.observations, s.inlier, true);
  s.residual_px.resize(std::min(s.residual_px.size(), all.current));
  s.inlier.resize(std::min(s.inlier.size(), all.current));
  result.solver_iterations = s.iterations;
  result.solver_converged = s.converged;
  markSolve(accepted, s, result);
  if (!s.ok) {
    window.add(accepted);
    result.warnings.push_back("solver: " + s.failure);
    return fixes;
  }
  // Reported whether or not it starts the filter.
  PoseFix fix = toFix(s, accepted);
  fix.read_landmarks = std::move(read_landmarks);
  result.measurement = fix.pose;
  result.measurement_covariance = fix.covariance;
  const double sigma = positionSigma(fix.covariance);
  if (tracking_.first_fix_max_sigma_m <= 0.0 || sigma <= tracking_.first_fix_max_sigma_m) {
    window.clear();
    fixes.agreeing = fix;
  } else {
    window.add(accepted);
    result.warnings.push_back(
        fmt::format("first fix too uncertain ({:.2f} m, 1 sigma): waiting for more texts", sigma));
  }
  return fixes;
}

}  // namespace parkloc::localize
