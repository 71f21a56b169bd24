#pragma once
// Extended Kalman filter on the planar pose (x, y, yaw) with wheel odometry (speed, yaw
// rate) as the motion input and absolute pose fixes as measurements. Beyond the paper, which
// has no temporal fusion: it gives a pose every frame (dead reckoning with a growing
// covariance when no text is seen) and a prediction to gate associations against.
//
// The state also holds the two systematic errors of wheel odometry, each a random walk: the
// yaw-rate bias b (the vehicle turns at measured - b; a gyro or wheel-based yaw rate is
// offset by a slowly drifting amount) and the speed scale s (the vehicle moves at s *
// measured; the wheel radius is known to about a percent). A filter that treats them as
// white noise is overconfident between fixes and lags behind them (docs/RELIABILITY.md,
// "Consistent uncertainty"). The pose fixes observe both through the heading and the
// distance they correct.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "geometry/pose.h"
#include "localize/map_error_term.h"

namespace parkloc::localize {

struct EkfOptions {
  double speed_sigma = 0.05;     // odometry speed noise, m/s (1 sigma)
  double yaw_rate_sigma = 0.01;  // odometry yaw-rate white noise, rad/s
  // Yaw-rate bias: its prior (1 sigma, rad/s, mean 0) and its random walk (rad/s/sqrt(s)).
  double yaw_rate_bias_sigma = 0.02;
  double yaw_rate_bias_walk = 0.001;
  // Speed scale (wheel radius error): its prior (1 sigma around 1) and random walk (1/sqrt(s)).
  double speed_scale_sigma = 0.02;
  double speed_scale_walk = 0.001;
  // For this long after the filter starts (s), fixes correct the pose but not the bias and
  // scale (a Schmidt "consider" update: their uncertainty still enters the prediction and the
  // gain of the pose). The first fixes of a track come a few tenths of a second apart and their
  // errors are alike (the same few texts): the yaw difference of two of them read as a bias
  // of a degree a second, which sparse fixes then took seconds to undo. 0: from the first fix.
  // (Not with map_error_landmarks, whose update needs the optimal gain.)
  double odometry_learning_delay_s = 0.0;
  // Random walk when no odometry drives the prediction.
  double no_odometry_position_sigma = 0.5;  // m / sqrt(s)
  double no_odometry_yaw_sigma = 0.1;       // rad / sqrt(s)
  // The map errors (x, y, heading, log width, log height) of up to this many landmarks are
  // states beside the pose (map_error_term.h): a landmark's error is one unknown that every
  // fix of it repeats, and odometry ties the fixes of different landmarks together, so the
  // filter averages independent landmarks' errors over the drive but never one landmark's
  // error over the frames that see it. The landmark observed longest ago leaves first (its
  // information stays in the pose, marginalised). 0: no such states; the tracking's
  // map_reuse_cap and the measurement's map_covariance_floor stand in for them.
  int map_error_landmarks = 0;
};

// One piece of odometry held for dt as the filter integrates it: the exact unicycle arc from
// heading `yaw`, moving at scale * speed and turning at yaw_rate - bias, with its Jacobians.
struct OdometryArc {
  Eigen::Vector3d delta = Eigen::Vector3d::Zero();  // x, y (map axes) and yaw change
  // d (x, y, yaw after) / d (x, y, yaw, yaw-rate bias, speed scale) and / d (speed, yaw rate).
  Eigen::Matrix<double, 3, 5> J_state = Eigen::Matrix<double, 3, 5>::Zero();
  Eigen::Matrix<double, 3, 2> J_input = Eigen::Matrix<double, 3, 2>::Zero();
};
OdometryArc odometryArc(double yaw, double speed, double yaw_rate, double bias, double scale,
                        double dt);

// The largest covariance below both A and B in the positive semi-definite order along the
// generalised eigenvectors of (B, A): with A = L L^T and L^-1 B L^-T = V Lambda V^T,
// L V min(Lambda, 1) V^T L^T. A must be positive definite; B positive semi-definite.
Eigen::Matrix3d covarianceMinimum(const Eigen::Matrix3d& A, const Eigen::Matrix3d& B);

// How a pose depends on the yaw-rate bias and the speed scale (d pose / d (bias, scale)): a
// fix measured earlier and carried to the present by the filter's motion (late_fusion.h)
// carries the filter's odometry errors over that motion with it.
using OdometrySensitivity = Eigen::Matrix<double, 3, 2>;

class PoseEkf {
 public:
  // State: x, y, yaw, yaw-rate bias, speed scale.
  static constexpr int kStateSize = 5;
  using StateVector = Eigen::Matrix<double, kStateSize, 1>;
  using StateMatrix = Eigen::Matrix<double, kStateSize, kStateSize>;

  explicit PoseEkf(EkfOptions options = {});

  bool initialised() const { return initialised_; }
  // Sets the pose and its covariance. The bias and scale estimates are kept (they belong to
  // the sensor, not to the pose: a re-localisation does not change them); their correlation
  // with the old pose is dropped.
  void initialise(const geometry::Pose2& pose, const Eigen::Matrix3d& covariance, double time);
  // Forgets everything, the bias and scale estimates included (back to their priors).
  void reset();

  // Motion over dt seconds with the measured speed and yaw rate (unicycle, exact arc; the
  // vehicle moves at speedScale() * speed and turns at yaw_rate - yawRateBias()).
  void predictWithOdometry(double speed, double yaw_rate, double dt);
  // No odometry: the pose stays, the covariance grows as a random walk.
  void predictWithoutOdometry(double dt);

  // How the pose now depends on the bias and the scale through the motion predicted since
  // `then`, an earlier copy of this filter, with the pose then held (the top right block of
  // the state transition from then to now).
  OdometrySensitivity odometrySensitivitySince(const PoseEkf& then) const;

  // A fix may be one measured earlier and carried here by the filter's motion, with the
  // odometry sensitivity G of that motion (zero for a fix of this time): it measures
  // pose - G (bias - estimate, scale - estimate), H = [I -G 0]. Fused as if the pose now
  // were measured, a late fix's heading would also be read as the bias's effect over the
  // delay, which it has not seen.

  // Squared Mahalanobis distance of a pose fix with covariance R from the prediction.
  double mahalanobis2(const geometry::Pose2& fix, const Eigen::Matrix3d& R,
                      const OdometrySensitivity& carried = OdometrySensitivity::Zero()) const;
  // Standard EKF update with a direct pose measurement (H = [I 0], yaw innovation wrapped).
  void update(const geometry::Pose2& fix, const Eigen::Matrix3d& R);
  // Raises the pose covariance to at least `floor` (in the positive semi-definite order; the
  // smallest such increase along the directions where it is below), leaving it where it is
  // above. Errors that fusion cannot average out (the map's, shared by consecutive fixes of
  // the same landmarks) bound what the filter may claim to know.
  void floorPoseCovariance(const Eigen::Matrix3d& floor);
  // An update with a fix whose covariance R holds a part `map_part` that the next fixes of
  // the same landmarks repeat: fused as usual, but the pose covariance is not taken below
  // the smaller of what it was and map_part (covarianceMinimum). Where the filter already
  // knew better than those landmarks' map error it keeps what it had; where it knew worse
  // it comes down to their map error and no further, however many frames see them.
  void update(const geometry::Pose2& fix, const Eigen::Matrix3d& R, const Eigen::Matrix3d& map_part,
              const OdometrySensitivity& carried = OdometrySensitivity::Zero());

  // The map error states (EkfOptions::map_error_landmarks > 0).
  bool mapErrorStates() const { return options_.map_error_landmarks > 0; }
  // Starts the filter from a fix z = pose + sum J_fix_map e + v with pixel noise v ~ N(0,
  // R_pixel): the pose z with covariance R_pixel + sum J Sigma_e J^T, correlated with the map
  // errors of its landmarks, which become states (the fix has told nothing about them yet).
  void initialise(const geometry::Pose2& pose, const Eigen::Matrix3d& R_pixel,
                  const std::vector<MapErrorTerm>& map_terms, double time);
  // Squared Mahalanobis distance of such a fix from the prediction (the map errors of its
  // landmarks from their states, or from the map's sigmas when they are no state).
  double mahalanobis2(const geometry::Pose2& fix, const Eigen::Matrix3d& R_pixel,
                      const std::vector<MapErrorTerm>& map_terms,
                      const OdometrySensitivity& carried = OdometrySensitivity::Zero()) const;
  // Update with such a fix: H = [I 0 J_fix_map...], the landmarks' map errors added as
  // states (mean 0, the map's variances) when they are not yet.
  void update(const geometry::Pose2& fix, const Eigen::Matrix3d& R_pixel,
              const std::vector<MapErrorTerm>& map_terms,
              const OdometrySensitivity& carried = OdometrySensitivity::Zero());
  // The landmarks whose map errors are states, and the estimate of each (x, y, heading, log
  // width, log height).
  const std::vector<std::string>& mapErrorLandmarks() const { return map_ids_; }
  Eigen::Matrix<double, 5, 1> mapError(size_t i) const { return map_error_.segment<5>(5 * i); }

  const geometry::Pose2& pose() const { return pose_; }
  // Marginal covariance of (x, y, yaw).
  Eigen::Matrix3d covariance() const { return covariance_.topLeftCorner<3, 3>(); }
  // Odometry error estimates and their variances.
  double yawRateBias() const { return bias_; }  // rad/s
  double yawRateBiasVariance() const { return covariance_(3, 3); }
  double speedScale() const { return scale_; }
  double speedScaleVariance() const { return covariance_(4, 4); }
  // Covariance of the whole state (x, y, yaw, bias, scale).
  const StateMatrix& fullCovariance() const { return covariance_; }
  double time() const { return time_; }
  void setTime(double time) { time_ = time; }

 private:
  EkfOptions options_;
  bool initialised_ = false;
  geometry::Pose2 pose_;
  double bias_ = 0.0;
  double scale_ = 1.0;
  double started_ = 0.0;  // time of the last initialise()
  StateMatrix covariance_ = StateMatrix::Identity();
  double time_ = 0.0;
  // The state transition of every prediction since the filter was made (the product of their
  // Jacobians; reset() keeps it): the transition between two copies of the filter is one's
  // times the other's inverse.
  StateMatrix transition_ = StateMatrix::Identity();
  // Map error states: 5 per landmark in map_ids_, their cross-covariance with the core state
  // (5 x 5m) and their covariance (5m x 5m); last_seen_ counts updates, for eviction.
  std::vector<std::string> map_ids_;
  std::vector<long> last_seen_;
  long updates_ = 0;
  Eigen::VectorXd map_error_;
  Eigen::MatrixXd cross_;
  Eigen::MatrixXd map_covariance_;

  void clearMapErrors();
  // The update with H = [I -carried 0].
  void updateDirect(const geometry::Pose2& fix, const Eigen::Matrix3d& R,
                    const OdometrySensitivity& carried);
  // The state index of each term's landmark, adding it (and evicting the oldest beyond the
  // limit, never one of this fix's) when it is not a state.
  std::vector<int> mapStates(const std::vector<MapErrorTerm>& map_terms);
  void removeMapState(size_t i);
  // The full covariance (core, then the map errors) and back.
  Eigen::MatrixXd assembled() const;
  void split(const Eigen::MatrixXd& P);
  // The general update: innovation nu, H over the full state, noise R.
  void updateFull(const Eigen::Vector3d& nu, const Eigen::MatrixXd& H, const Eigen::Matrix3d& R);
};

}  // namespace parkloc::localize
