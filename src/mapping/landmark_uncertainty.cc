// The landmarks' uncertainty from the estimation's covariance (Ceres' Covariance: the inverse
// of J^T J at the solution, the robust loss's weights included), written as the map states it
// (map::MapAccuracy): one sigma per axis of the centre (the root of the mean of the two axes'
// variances) and the heading's. It is relative to the gauge, the first pose: a landmark far
// along the drive from it is less certain, as the odometry between them says. It holds the
// corner noise as white, and the spotter's corners are not quite (their error is partly the
// same from frame set to frame set), which would make it optimistic; on the held-out drives it
// is of the size of the measured error (docs/RESULTS.md, Map building).
#include <ceres/ceres.h>

#include <algorithm>
#include <cmath>

#include "map/landmark.h"
#include "mapping/map_problem.h"

namespace parkloc::mapping {

bool MapProblem::computeUncertainty(std::string* why) {
  ceres::Covariance::Options options;
  options.num_threads = options_.threads;
  // Rank-revealing: a landmark the drive saw along one ray only is reported, not inverted.
  options.algorithm_type = ceres::DENSE_SVD;
  options.null_space_rank = -1;
  if (problem_->NumParameters() > 6000) options.algorithm_type = ceres::SPARSE_QR;
  ceres::Covariance covariance(options);
  std::vector<std::pair<const double*, const double*>> blocks;
  for (const LandmarkEstimate& l : landmarks_)
    blocks.emplace_back(l.parameters.data(), l.parameters.data());
  if (!covariance.Compute(blocks, problem_.get())) {
    if (why) *why = "the covariance of the solution is rank deficient";
    return false;
  }
  for (LandmarkEstimate& l : landmarks_) {
    double c[5 * 5];
    if (!covariance.GetCovarianceBlock(l.parameters.data(), l.parameters.data(), c)) continue;
    const double position = std::sqrt(std::max(0.0, 0.5 * (c[kX * 5 + kX] + c[kY * 5 + kY])));
    const double heading = std::sqrt(std::max(0.0, c[kHeading * 5 + kHeading]));
    l.position_sigma = std::min(position, map::kMaxPositionSigmaM);
    l.heading_sigma = std::min(heading, map::kMaxHeadingSigmaRad);
  }
  return true;
}

}  // namespace parkloc::mapping
