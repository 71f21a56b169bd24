#pragma once
// What an estimator that sees the whole drive could make of the fixes the filter fused and
// the wheel odometry: the yardstick for the filter on a map with survey error. A batch
// least-squares smoother (Gauss-Newton on sparse normal equations) over
//  - every frame set's pose (x, y, yaw), with the odometry's yaw-rate bias and speed scale
//    at each frame set (random walks, as the filter models them, localize/pose_ekf.h);
//  - the map error of every landmark the fixes rest on (x, y, heading, log width, log
//    height), one unknown per landmark however often it is seen, its prior the map's stated
//    sigmas (localize/map_error_term.h);
// with odometry factors between consecutive frame sets (the held samples integrated as the
// filter integrates them, with its noise), and each fix z = pose + sum J_fix_map e + v,
// v ~ N(0, pixel covariance). It is non-causal: every fix informs every pose. It reads no
// truth; the evaluation scores its poses against the truth.
#include <optional>
#include <vector>

#include "common/odometry_sample.h"
#include "geometry/pose.h"
#include "localize/frame_types.h"
#include "localize/pose_ekf.h"

namespace parkloc::eval {

struct SmootherFrame {
  double timestamp = 0.0;
  geometry::Pose2 initial;                // where Gauss-Newton starts (the filter's pose)
  std::vector<localize::FusedFix> fixes;  // fused at this frame set
};

struct SmootherResult {
  std::vector<geometry::Pose2> poses;  // one per frame
  int iterations = 0;
  bool converged = false;
};

struct SmootherOptions {
  int max_iterations = 10;
  double step_tolerance = 1e-6;  // converged when the largest state change falls below
};

// Empty when there is no frame or no fix. `odometry` is the drive's whole odometry in time
// order; each sample holds until the next.
std::optional<SmootherResult> smoothDrive(const std::vector<SmootherFrame>& frames,
                                          const std::vector<OdometrySample>& odometry,
                                          const localize::EkfOptions& noise,
                                          const SmootherOptions& options = {});

// The vehicle's motion between two times in the frame of the first, from the held odometry
// samples with yaw-rate bias `bias` and speed scale `scale`, and its covariance from the
// filter's input noise. Exposed for tests.
struct OdometryMotion {
  Eigen::Vector3d delta = Eigen::Vector3d::Zero();  // x, y, yaw in the first frame
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
};
OdometryMotion integrateHeldOdometry(const std::vector<OdometrySample>& odometry, double t0,
                                     double t1, double bias, double scale,
                                     const localize::EkfOptions& noise);

}  // namespace parkloc::eval
