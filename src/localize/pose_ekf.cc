#include "localize/pose_ekf.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <optional>

namespace parkloc::localize {
namespace {

constexpr int kBias = 3, kScale = 4;

Eigen::Vector3d innovation(const geometry::Pose2& fix, const geometry::Pose2& pose) {
  return {fix.x - pose.x, fix.y - pose.y, geometry::wrapAngle(fix.yaw - pose.yaw)};
}

}  // namespace

PoseEkf::PoseEkf(EkfOptions options) : options_(options) { reset(); }

void PoseEkf::reset() {
  initialised_ = false;
  bias_ = 0.0;
  scale_ = 1.0;
  covariance_.setZero();
  covariance_(kBias, kBias) = options_.yaw_rate_bias_sigma * options_.yaw_rate_bias_sigma;
  covariance_(kScale, kScale) = options_.speed_scale_sigma * options_.speed_scale_sigma;
  clearMapErrors();
}

void PoseEkf::initialise(const geometry::Pose2& pose, const Eigen::Matrix3d& covariance,
                         double time) {
  pose_ = pose;
  const Eigen::Matrix2d odometry = covariance_.bottomRightCorner<2, 2>();
  covariance_.setZero();
  covariance_.topLeftCorner<3, 3>() = covariance;
  covariance_.bottomRightCorner<2, 2>() = odometry;
  time_ = time;
  started_ = time;
  initialised_ = true;
  clearMapErrors();
}

OdometryArc odometryArc(double yaw, double speed, double yaw_rate, double bias, double scale,
                        double dt) {
  const double dyaw = (yaw_rate - bias) * dt;
  // Arc of the unicycle; its chord for small turns (sin(x)/x -> 1).
  const double half = 0.5 * dyaw;
  const double chord = std::abs(half) < 1e-9 ? 1.0 : std::sin(half) / half;
  const double measured_distance = speed * dt * chord;
  const double distance = scale * measured_distance;
  const double heading = yaw + half;
  const double c = std::cos(heading), s = std::sin(heading);
  OdometryArc arc;
  arc.delta = Eigen::Vector3d(distance * c, distance * s, dyaw);

  // The turn changes both the heading of the chord (half of it) and its length (d chord /
  // d half); the bias enters like the yaw rate with the opposite sign, the scale like the speed.
  const double chord_slope = std::abs(half) < 1e-4
                                 ? -half / 3.0
                                 : (half * std::cos(half) - std::sin(half)) / (half * half);
  const Eigen::Vector2d d_position_d_half(scale * speed * dt * chord_slope * c - distance * s,
                                          scale * speed * dt * chord_slope * s + distance * c);
  arc.J_state.setZero();
  arc.J_state.leftCols<3>().setIdentity();
  arc.J_state(0, 2) = -distance * s;
  arc.J_state(1, 2) = distance * c;
  arc.J_state.block<2, 1>(0, kBias) = -0.5 * dt * d_position_d_half;
  arc.J_state(2, kBias) = -dt;
  arc.J_state(0, kScale) = measured_distance * c;
  arc.J_state(1, kScale) = measured_distance * s;
  arc.J_input.setZero();
  arc.J_input(0, 0) = scale * dt * chord * c;
  arc.J_input(1, 0) = scale * dt * chord * s;
  arc.J_input.block<2, 1>(0, 1) = 0.5 * dt * d_position_d_half;
  arc.J_input(2, 1) = dt;
  return arc;
}

void PoseEkf::predictWithOdometry(double speed, double yaw_rate, double dt) {
  if (!(dt > 0.0)) return;
  const OdometryArc arc = odometryArc(pose_.yaw, speed, yaw_rate, bias_, scale_, dt);
  pose_ = geometry::Pose2(pose_.x + arc.delta(0), pose_.y + arc.delta(1), pose_.yaw + arc.delta(2));
  StateMatrix F = StateMatrix::Identity();
  F.topRows<3>() = arc.J_state;
  Eigen::Matrix<double, kStateSize, 2> G = Eigen::Matrix<double, kStateSize, 2>::Zero();
  G.topRows<3>() = arc.J_input;
  const Eigen::Vector2d input_variance(options_.speed_sigma * options_.speed_sigma,
                                       options_.yaw_rate_sigma * options_.yaw_rate_sigma);
  covariance_ = F * covariance_ * F.transpose() + G * input_variance.asDiagonal() * G.transpose();
  transition_ = (F * transition_).eval();
  // The map errors stay where they are; their correlation with the state moves with it.
  if (cross_.cols() > 0) cross_ = (F * cross_).eval();
  covariance_(kBias, kBias) += options_.yaw_rate_bias_walk * options_.yaw_rate_bias_walk * dt;
  covariance_(kScale, kScale) += options_.speed_scale_walk * options_.speed_scale_walk * dt;
}

void PoseEkf::predictWithoutOdometry(double dt) {
  if (!(dt > 0.0)) return;
  const double p = options_.no_odometry_position_sigma, y = options_.no_odometry_yaw_sigma,
               b = options_.yaw_rate_bias_walk, k = options_.speed_scale_walk;
  covariance_.diagonal() += StateVector(p * p, p * p, y * y, b * b, k * k) * dt;
}

OdometrySensitivity PoseEkf::odometrySensitivitySince(const PoseEkf& then) const {
  // Transitions are [A B; 0 I] (bias and scale are carried as they are): now * then^-1 has
  // B_now - A_now A_then^-1 B_then as its top right block.
  const Eigen::Matrix3d A_then = then.transition_.topLeftCorner<3, 3>();
  return transition_.topRightCorner<3, 2>() - transition_.topLeftCorner<3, 3>() * A_then.inverse() *
                                                  then.transition_.topRightCorner<3, 2>();
}

namespace {

// H = [I -carried] on the core state (x, y, yaw, bias, scale).
Eigen::Matrix<double, 3, PoseEkf::kStateSize> directH(const OdometrySensitivity& carried) {
  Eigen::Matrix<double, 3, PoseEkf::kStateSize> H;
  H.leftCols<3>().setIdentity();
  H.rightCols<2>() = -carried;
  return H;
}

}  // namespace

double PoseEkf::mahalanobis2(const geometry::Pose2& fix, const Eigen::Matrix3d& R,
                             const OdometrySensitivity& carried) const {
  const Eigen::Vector3d nu = innovation(fix, pose_);
  const auto H = directH(carried);
  const Eigen::Matrix3d S = H * covariance_ * H.transpose() + R;
  return nu.dot(S.ldlt().solve(nu));
}

void PoseEkf::update(const geometry::Pose2& fix, const Eigen::Matrix3d& R) {
  updateDirect(fix, R, OdometrySensitivity::Zero());
}

void PoseEkf::updateDirect(const geometry::Pose2& fix, const Eigen::Matrix3d& R,
                           const OdometrySensitivity& carried) {
  if (!map_ids_.empty()) {
    Eigen::MatrixXd H = Eigen::MatrixXd::Zero(3, kStateSize + map_error_.size());
    H.leftCols<kStateSize>() = directH(carried);
    updateFull(innovation(fix, pose_), H, R);
    return;
  }
  const Eigen::Vector3d nu = innovation(fix, pose_);
  const auto H = directH(carried);
  const Eigen::Matrix<double, kStateSize, 3> PHt = covariance_ * H.transpose();
  const Eigen::Matrix3d S = H * PHt + R;
  Eigen::Matrix<double, kStateSize, 3> K = PHt * S.inverse();
  if (time_ - started_ < options_.odometry_learning_delay_s) K.bottomRows<2>().setZero();
  const StateVector dx = K * nu;
  pose_ = geometry::Pose2(pose_.x + dx(0), pose_.y + dx(1), pose_.yaw + dx(2));
  bias_ += dx(kBias);
  scale_ += dx(kScale);
  // Joseph form keeps the covariance symmetric positive definite.
  const StateMatrix I_KH = StateMatrix::Identity() - K * H;
  covariance_ = I_KH * covariance_ * I_KH.transpose() + K * R * K.transpose();
  covariance_ = 0.5 * (covariance_ + covariance_.transpose()).eval();
}

namespace {

// The generalised eigen decomposition of (B, A): with A = L L^T, L^-1 B L^-T = V diag(lambda)
// V^T. Empty when A is not positive definite.
struct GeneralisedEigen {
  Eigen::Matrix3d L, V;
  Eigen::Vector3d lambda;
};
std::optional<GeneralisedEigen> generalisedEigen(const Eigen::Matrix3d& A,
                                                 const Eigen::Matrix3d& B) {
  const Eigen::LLT<Eigen::Matrix3d> llt(A);
  if (llt.info() != Eigen::Success) return std::nullopt;
  const Eigen::Matrix3d L = llt.matrixL();
  const Eigen::Matrix3d L_inv = L.inverse();
  const Eigen::Matrix3d M = L_inv * B * L_inv.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(0.5 * (M + M.transpose()));
  return GeneralisedEigen{L, eigen.eigenvectors(), eigen.eigenvalues()};
}

// L V diag(lambda) V^T L^T: A with its generalised eigenvalues replaced by `lambda`.
Eigen::Matrix3d recompose(const GeneralisedEigen& g, const Eigen::Vector3d& lambda) {
  return g.L * g.V * lambda.asDiagonal() * g.V.transpose() * g.L.transpose();
}

}  // namespace

Eigen::Matrix3d covarianceMinimum(const Eigen::Matrix3d& A, const Eigen::Matrix3d& B) {
  const auto g = generalisedEigen(A, B);
  if (!g) return Eigen::Matrix3d::Zero();
  return recompose(*g, g->lambda.cwiseMax(0.0).cwiseMin(1.0));
}

void PoseEkf::update(const geometry::Pose2& fix, const Eigen::Matrix3d& R,
                     const Eigen::Matrix3d& map_part, const OdometrySensitivity& carried) {
  const Eigen::Matrix3d before = covariance();
  updateDirect(fix, R, carried);
  if (!map_part.allFinite() || map_part.isZero(0.0)) return;
  floorPoseCovariance(covarianceMinimum(before, map_part));
}

void PoseEkf::floorPoseCovariance(const Eigen::Matrix3d& floor) {
  if (!floor.allFinite() || floor.isZero(0.0)) return;
  // With P = L L^T: P' = L V max(Lambda, 1) V^T L^T, where V Lambda V^T = L^-1 floor L^-T.
  // Then P' >= P and P' >= floor; adding P' - P (>= 0) to the pose block keeps the whole
  // state covariance positive semi-definite.
  const Eigen::Matrix3d P = covariance();
  const auto g = generalisedEigen(P, floor);
  if (!g || g->lambda.maxCoeff() <= 1.0) return;
  const Eigen::Matrix3d raised = recompose(*g, g->lambda.cwiseMax(1.0));
  covariance_.topLeftCorner<3, 3>() += raised - P;
  covariance_ = 0.5 * (covariance_ + covariance_.transpose()).eval();
}

void PoseEkf::clearMapErrors() {
  map_ids_.clear();
  last_seen_.clear();
  map_error_.resize(0);
  cross_.resize(kStateSize, 0);
  map_covariance_.resize(0, 0);
}

void PoseEkf::removeMapState(size_t i) {
  // Dropping a state's rows and columns marginalises it: what it told the pose stays there.
  const Eigen::Index n = map_error_.size(), at = 5 * static_cast<Eigen::Index>(i);
  const Eigen::Index tail = n - at - 5;
  map_error_.segment(at, tail) = map_error_.tail(tail).eval();
  map_error_.conservativeResize(n - 5);
  cross_.middleCols(at, tail) = cross_.rightCols(tail).eval();
  cross_.conservativeResize(Eigen::NoChange, n - 5);
  map_covariance_.middleCols(at, tail) = map_covariance_.rightCols(tail).eval();
  map_covariance_.middleRows(at, tail) = map_covariance_.bottomRows(tail).eval();
  map_covariance_.conservativeResize(n - 5, n - 5);
  map_ids_.erase(map_ids_.begin() + static_cast<std::ptrdiff_t>(i));
  last_seen_.erase(last_seen_.begin() + static_cast<std::ptrdiff_t>(i));
}

std::vector<int> PoseEkf::mapStates(const std::vector<MapErrorTerm>& map_terms) {
  ++updates_;
  std::vector<int> index(map_terms.size(), -1);
  for (size_t t = 0; t < map_terms.size(); ++t) {
    const auto it = std::find(map_ids_.begin(), map_ids_.end(), map_terms[t].landmark_id);
    if (it != map_ids_.end()) {
      last_seen_[static_cast<size_t>(it - map_ids_.begin())] = updates_;
      continue;
    }
    // A new state: mean 0, the map's variances, uncorrelated with the rest.
    const Eigen::Index n = map_error_.size();
    map_error_.conservativeResize(n + 5);
    map_error_.tail<5>().setZero();
    cross_.conservativeResize(Eigen::NoChange, n + 5);
    cross_.rightCols<5>().setZero();
    map_covariance_.conservativeResize(n + 5, n + 5);
    map_covariance_.rightCols<5>().setZero();
    map_covariance_.bottomRows<5>().setZero();
    map_covariance_.bottomRightCorner<5, 5>() = map_terms[t].variance.asDiagonal();
    map_ids_.push_back(map_terms[t].landmark_id);
    last_seen_.push_back(updates_);
  }
  // Beyond the limit the landmark observed longest ago leaves (never one of this fix).
  const size_t limit = static_cast<size_t>(std::max(options_.map_error_landmarks, 0));
  while (map_ids_.size() > std::max(limit, map_terms.size())) {
    size_t oldest = 0;
    for (size_t i = 1; i < map_ids_.size(); ++i)
      if (last_seen_[i] < last_seen_[oldest]) oldest = i;
    removeMapState(oldest);
  }
  for (size_t t = 0; t < map_terms.size(); ++t)
    index[t] = static_cast<int>(
        std::find(map_ids_.begin(), map_ids_.end(), map_terms[t].landmark_id) - map_ids_.begin());
  return index;
}

Eigen::MatrixXd PoseEkf::assembled() const {
  const Eigen::Index n = kStateSize + map_error_.size();
  Eigen::MatrixXd P(n, n);
  P.topLeftCorner<kStateSize, kStateSize>() = covariance_;
  P.topRightCorner(kStateSize, map_error_.size()) = cross_;
  P.bottomLeftCorner(map_error_.size(), kStateSize) = cross_.transpose();
  P.bottomRightCorner(map_error_.size(), map_error_.size()) = map_covariance_;
  return P;
}

void PoseEkf::split(const Eigen::MatrixXd& P) {
  const Eigen::Index m = map_error_.size();
  covariance_ = P.topLeftCorner<kStateSize, kStateSize>();
  cross_ = P.topRightCorner(kStateSize, m);
  map_covariance_ = P.bottomRightCorner(m, m);
}

void PoseEkf::updateFull(const Eigen::Vector3d& nu, const Eigen::MatrixXd& H,
                         const Eigen::Matrix3d& R) {
  const Eigen::MatrixXd P = assembled();
  const Eigen::MatrixXd PHt = P * H.transpose();
  const Eigen::Matrix3d S = H * PHt + R;
  const Eigen::MatrixXd K = PHt * S.inverse();
  const Eigen::VectorXd dx = K * nu;
  pose_ = geometry::Pose2(pose_.x + dx(0), pose_.y + dx(1), pose_.yaw + dx(2));
  bias_ += dx(kBias);
  scale_ += dx(kScale);
  map_error_ += dx.tail(map_error_.size());
  // P - K S K^T: O(n^2) where the Joseph form costs O(n^3) in the map states; symmetrised.
  const Eigen::MatrixXd updated = P - K * S * K.transpose();
  split(0.5 * (updated + updated.transpose()));
}

void PoseEkf::initialise(const geometry::Pose2& pose, const Eigen::Matrix3d& R_pixel,
                         const std::vector<MapErrorTerm>& map_terms, double time) {
  Eigen::Matrix3d covariance = R_pixel;
  for (const MapErrorTerm& t : map_terms)
    covariance += t.J_fix_map * t.variance.asDiagonal() * t.J_fix_map.transpose();
  initialise(pose, covariance, time);
  if (!mapErrorStates() || map_terms.empty()) return;
  // pose - z = -sum J e - v: the pose's error is correlated with each landmark's by -J Sigma.
  const std::vector<int> index = mapStates(map_terms);
  for (size_t t = 0; t < map_terms.size(); ++t)
    if (index[t] >= 0)
      cross_.block<3, 5>(0, 5 * index[t]) =
          -map_terms[t].J_fix_map * map_terms[t].variance.asDiagonal();
}

double PoseEkf::mahalanobis2(const geometry::Pose2& fix, const Eigen::Matrix3d& R_pixel,
                             const std::vector<MapErrorTerm>& map_terms,
                             const OdometrySensitivity& carried) const {
  Eigen::Vector3d nu = innovation(fix, pose_);
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(3, kStateSize + map_error_.size());
  H.leftCols<kStateSize>() = directH(carried);
  Eigen::Matrix3d S = R_pixel;
  for (const MapErrorTerm& t : map_terms) {
    const auto it = std::find(map_ids_.begin(), map_ids_.end(), t.landmark_id);
    if (it == map_ids_.end() || !mapErrorStates()) {
      S += t.J_fix_map * t.variance.asDiagonal() * t.J_fix_map.transpose();
      continue;
    }
    const Eigen::Index at = 5 * (it - map_ids_.begin());
    H.middleCols<5>(kStateSize + at) += t.J_fix_map;
    nu -= t.J_fix_map * map_error_.segment<5>(at);
  }
  nu(2) = geometry::wrapAngle(nu(2));
  S += H * assembled() * H.transpose();
  return nu.dot(S.ldlt().solve(nu));
}

void PoseEkf::update(const geometry::Pose2& fix, const Eigen::Matrix3d& R_pixel,
                     const std::vector<MapErrorTerm>& map_terms,
                     const OdometrySensitivity& carried) {
  if (!mapErrorStates()) {
    Eigen::Matrix3d R = R_pixel;
    for (const MapErrorTerm& t : map_terms)
      R += t.J_fix_map * t.variance.asDiagonal() * t.J_fix_map.transpose();
    updateDirect(fix, R, carried);
    return;
  }
  const std::vector<int> index = mapStates(map_terms);
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(3, kStateSize + map_error_.size());
  H.leftCols<kStateSize>() = directH(carried);
  Eigen::Vector3d nu = innovation(fix, pose_);
  for (size_t t = 0; t < map_terms.size(); ++t) {
    H.middleCols<5>(kStateSize + 5 * index[t]) += map_terms[t].J_fix_map;
    nu -= map_terms[t].J_fix_map * map_error_.segment<5>(5 * index[t]);
  }
  nu(2) = geometry::wrapAngle(nu(2));
  updateFull(nu, H, R_pixel);
}

}  // namespace parkloc::localize
