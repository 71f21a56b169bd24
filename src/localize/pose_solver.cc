#include "localize/pose_solver.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/ground_projection.h"
#include "localize/projection_jacobian.h"

namespace parkloc::localize {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

double huberCost(double e, double k) { return e <= k ? 0.5 * e * e : k * (e - 0.5 * k); }

Eigen::Vector2d observedCentre(const LandmarkObservation& o) {
  return 0.25 * (o.pixels[0] + o.pixels[1] + o.pixels[2] + o.pixels[3]);
}

// The mean of the projected corners (what a box centre measures) and its Jacobians.
std::optional<CornerProjection> projectCentre(const geometry::RigCamera& camera,
                                              const geometry::Pose2& pose,
                                              const LandmarkObservation& o) {
  CornerProjection c{Eigen::Vector2d::Zero(), Eigen::Matrix<double, 2, 3>::Zero(),
                     Eigen::Matrix<double, 2, 3>::Zero()};
  for (int i = 0; i < 4; ++i) {
    const auto p = projectMapCorner(camera, pose, o.map_corners[i]);
    if (!p) return std::nullopt;
    c.pixel += 0.25 * p->pixel;
    c.J_pixel_pose += 0.25 * p->J_pixel_pose;
    c.J_pixel_corner += 0.25 * p->J_pixel_corner;
  }
  return c;
}

// The landmark's error parameters: x, y, heading, log width, log height.
using MapParameterJacobian = Eigen::Matrix<double, 3, 5>;
using MapParameterCovariance = Eigen::Matrix<double, 5, 1>;  // diagonal

// The map's sigmas of one observation's landmark as variances; zero when exact.
MapParameterCovariance mapVariances(const LandmarkObservation& o, const SolverOptions& options) {
  const double p = o.accuracy.position_sigma.value_or(options.assumed_map_position_sigma_m);
  const double h =
      o.accuracy.heading_sigma.value_or(options.assumed_map_heading_sigma_deg * M_PI / 180.0);
  const bool surveyed = o.accuracy.position_sigma || o.accuracy.heading_sigma;
  const double s = surveyed ? options.map_size_sigma : options.assumed_map_size_sigma;
  MapParameterCovariance v;
  v << p * p, p * p, h * h, s * s, s * s;
  return v;
}

// d map corner / d (x, y, heading, log width, log height) of the landmark, from its corners
// (top-left, top-right, bottom-right, bottom-left): the centre moves every corner alike, the
// heading turns them about the centre (a pillar text's vertical extent stays), a relative
// size change moves each along its half-width or half-height.
std::array<MapParameterJacobian, 4> cornerParameterJacobians(const LandmarkObservation& o) {
  const auto& c = o.map_corners;
  const Eigen::Vector3d centre = 0.25 * (c[0] + c[1] + c[2] + c[3]);
  const Eigen::Vector3d half_width = 0.25 * (c[1] - c[0] + c[2] - c[3]);
  const Eigen::Vector3d half_height = 0.25 * (c[0] - c[3] + c[1] - c[2]);
  constexpr double kWidthSign[4] = {-1.0, 1.0, 1.0, -1.0};
  constexpr double kHeightSign[4] = {1.0, 1.0, -1.0, -1.0};
  std::array<MapParameterJacobian, 4> out;
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector3d d = c[i] - centre;
    out[i].col(0) = Eigen::Vector3d::UnitX();
    out[i].col(1) = Eigen::Vector3d::UnitY();
    out[i].col(2) = Eigen::Vector3d(-d.y(), d.x(), 0.0);
    out[i].col(3) = kWidthSign[i] * half_width;
    out[i].col(4) = kHeightSign[i] * half_height;
  }
  return out;
}

// Observations of one landmark (its four corners in up to four cameras, or frame sets of the
// search window) share its map error and are whitened together: up to 32 rows, without
// allocation.
constexpr int kMaxGroupSize = 4;
constexpr int kMaxRows = 8 * kMaxGroupSize;
using Rows = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxRows, 1>;
using RowsBy3 = Eigen::Matrix<double, Eigen::Dynamic, 3, 0, kMaxRows, 3>;
using RowsBy5 = Eigen::Matrix<double, Eigen::Dynamic, 5, 0, kMaxRows, 5>;
using RowsByRows = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxRows, kMaxRows>;

// One observation's residuals at a pose, the rows of the corners that project (2 each) or the
// 2 of the centre, with d r / d pose and d r / d map parameters (x, y, heading, log width,
// log height).
struct ObservationTerms {
  Rows r;
  RowsBy3 J;
  RowsBy5 G;
  bool all_project = true;
};

// G only `with_map` (the whitening needs it; an iteration with a fixed whitening does not).
ObservationTerms observationTerms(const geometry::RigCamera& camera, const geometry::Pose2& pose,
                                  const LandmarkObservation& o, bool with_map = true) {
  ObservationTerms t;
  if (!o.use_corners) {
    const auto c = projectCentre(camera, pose, o);
    if (!c) {
      t.all_project = false;
      return t;
    }
    t.r = c->pixel - observedCentre(o);
    t.J = c->J_pixel_pose;
    // The centre stays where it is when the text turns or changes size.
    if (with_map) {
      t.G.setZero(2, 5);
      t.G.leftCols<2>() = c->J_pixel_corner.leftCols<2>();
    }
    return t;
  }
  std::array<MapParameterJacobian, 4> D;
  if (with_map) D = cornerParameterJacobians(o);
  int rows = 0;
  Eigen::Matrix<double, 8, 1> r;
  Eigen::Matrix<double, 8, 3> J;
  Eigen::Matrix<double, 8, 5> G;
  for (int i = 0; i < 4; ++i) {
    const auto p = projectMapCorner(camera, pose, o.map_corners[i]);
    if (!p) {
      t.all_project = false;
      continue;
    }
    r.segment<2>(rows) = p->pixel - o.pixels[i];
    J.middleRows<2>(rows) = p->J_pixel_pose;
    if (with_map) G.middleRows<2>(rows) = p->J_pixel_corner * D[i];
    rows += 2;
  }
  t.r = r.head(rows);
  t.J = J.topRows(rows);
  if (with_map) t.G = G.topRows(rows);
  return t;
}

using Group = std::vector<size_t>;  // indices of observations of one landmark

// The used observations grouped by landmark, in order of first appearance; a landmark seen
// more often than kMaxGroupSize times makes several groups.
std::vector<Group> landmarkGroups(const std::vector<LandmarkObservation>& obs,
                                  const std::vector<bool>& use) {
  std::vector<Group> groups;
  for (size_t o = 0; o < obs.size(); ++o) {
    if (!use[o]) continue;
    const auto same = std::find_if(groups.begin(), groups.end(), [&](const Group& g) {
      return g.size() < kMaxGroupSize && obs[g.front()].landmark_id == obs[o].landmark_id;
    });
    if (same == groups.end())
      groups.push_back({o});
    else
      same->push_back(o);
  }
  return groups;
}

// The observations' terms stacked.
ObservationTerms groupTerms(const geometry::Rig& rig, const geometry::Pose2& pose,
                            const std::vector<LandmarkObservation>& obs, const Group& group,
                            bool with_map = true) {
  if (group.size() == 1)
    return observationTerms(rig.cameras[obs[group[0]].camera], pose, obs[group[0]], with_map);
  ObservationTerms all;
  Eigen::Index rows = 0;
  std::array<ObservationTerms, kMaxGroupSize> parts;
  for (size_t k = 0; k < group.size(); ++k) {
    parts[k] = observationTerms(rig.cameras[obs[group[k]].camera], pose, obs[group[k]], with_map);
    rows += parts[k].r.size();
    all.all_project = all.all_project && parts[k].all_project;
  }
  all.r.resize(rows);
  all.J.resize(rows, 3);
  if (with_map) all.G.resize(rows, 5);
  rows = 0;
  for (size_t k = 0; k < group.size(); ++k) {
    const Eigen::Index n = parts[k].r.size();
    all.r.segment(rows, n) = parts[k].r;
    all.J.middleRows(rows, n) = parts[k].J;
    if (with_map) all.G.middleRows(rows, n) = parts[k].G;
    rows += n;
  }
  return all;
}

// The lower Cholesky factor L of the residuals' covariance in units of pixel_sigma^2,
// C = I + G Sigma_l G^T / pixel_sigma^2 = L L^T; empty when the map is exact (C = I).
RowsByRows whiteningFactor(const ObservationTerms& t, const LandmarkObservation& o,
                           const SolverOptions& options) {
  const MapParameterCovariance variances = mapVariances(o, options);
  if (t.r.size() == 0 || variances.isZero(0.0) || options.pixel_sigma <= 0.0) return {};
  RowsByRows C = (t.G * variances.asDiagonal() * t.G.transpose()) /
                 (options.pixel_sigma * options.pixel_sigma);
  C.diagonal().array() += 1.0;
  const Eigen::LLT<RowsByRows> llt(C);
  if (llt.info() != Eigen::Success) return {};
  return llt.matrixL();
}

// Whitens r and J in place by L (none when L is empty).
void whiten(const RowsByRows& L, ObservationTerms& t) {
  if (L.rows() == 0 || L.rows() != t.r.size()) return;
  const auto lower = L.triangularView<Eigen::Lower>();
  lower.solveInPlace(t.r);
  lower.solveInPlace(t.J);
}

// Each observation's whitening factor at a pose. The factor moves with the pose only through
// the projection's Jacobian; a refinement holds it fixed so that its cost is one function of
// the pose, and takes it anew at the pose it ends at.
std::vector<RowsByRows> whiteningFactors(const geometry::Rig& rig,
                                         const std::vector<LandmarkObservation>& obs,
                                         const std::vector<Group>& groups,
                                         const geometry::Pose2& pose,
                                         const SolverOptions& options) {
  std::vector<RowsByRows> factors(groups.size());
  for (size_t g = 0; g < groups.size(); ++g) {
    const LandmarkObservation& o = obs[groups[g].front()];
    if (mapVariances(o, options).isZero(0.0)) continue;  // an exact landmark: C = I
    factors[g] = whiteningFactor(groupTerms(rig, pose, obs, groups[g]), o, options);
  }
  return factors;
}

struct NormalEquations {
  Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
  // The same weights on the residuals before whitening: the information with an exact map.
  Eigen::Matrix3d H_pixel = Eigen::Matrix3d::Zero();
  Eigen::Vector3d g = Eigen::Vector3d::Zero();
  double cost = 0.0;
  double squared_error = 0.0;
  int corners = 0;
};

NormalEquations accumulate(const geometry::Rig& rig, const std::vector<LandmarkObservation>& obs,
                           const std::vector<Group>& groups, const geometry::Pose2& pose,
                           const std::vector<RowsByRows>& factors, double huber) {
  NormalEquations n;
  for (size_t g = 0; g < groups.size(); ++g) {
    ObservationTerms t = groupTerms(rig, pose, obs, groups[g], /*with_map=*/false);
    const RowsBy3 J_pixel = t.J;
    whiten(factors[g], t);
    // One Huber-weighted (IRLS) whitened corner (or centre) at a time.
    for (Eigen::Index k = 0; k + 1 < t.r.size(); k += 2) {
      const Eigen::Vector2d r = t.r.segment<2>(k);
      const double e = r.norm();
      const double w = e <= huber ? 1.0 : huber / e;
      const auto J = t.J.middleRows<2>(k);
      const auto J_raw = J_pixel.middleRows<2>(k);
      n.H += w * J.transpose() * J;
      n.H_pixel += w * J_raw.transpose() * J_raw;
      n.g += w * J.transpose() * r;
      n.cost += huberCost(e, huber);
      n.squared_error += e * e;
      ++n.corners;
    }
  }
  return n;
}

// The solve's sensitivity to each landmark's map error and its pixel-noise covariance, from
// its linearisation at the pose it ended at: the Gauss-Newton step is -H^-1 sum_g B_g L_g^-1 r_g
// with B_g = (L_g^-1 J_g)^T D_g (D_g the Huber weights of the whitened corners), and a landmark
// whose map entry is off by e shifts its raw residuals by G_g e, pixel noise by n ~ N(0,
// pixel_sigma^2 I). So the pose moves by -H^-1 B_g L_g^-1 G_g e, and by pixel noise with
// covariance pixel_sigma^2 H^-1 (sum_g M_g M_g^T) H^-1, M_g = B_g L_g^-1. Returns the
// unnormalised H^-1 sandwich; `H` is the whitened, weighted normal matrix (pixel units).
void splitMapError(const geometry::Rig& rig, const std::vector<LandmarkObservation>& obs,
                   const std::vector<Group>& groups, const geometry::Pose2& pose,
                   const std::vector<RowsByRows>& factors, const Eigen::Matrix3d& H,
                   const SolverOptions& options, SolverResult& result) {
  const Eigen::Matrix3d H_inv = H.inverse();
  Eigen::Matrix3d pixel_information = Eigen::Matrix3d::Zero();
  for (size_t g = 0; g < groups.size(); ++g) {
    const LandmarkObservation& o = obs[groups[g].front()];
    const MapParameterCovariance variances = mapVariances(o, options);
    ObservationTerms t = groupTerms(rig, pose, obs, groups[g], /*with_map=*/true);
    const Eigen::Index rows = t.r.size();
    if (rows == 0) continue;
    const RowsByRows& L = factors[g];
    const bool whitened = L.rows() == rows;
    if (whitened) {
      const auto lower = L.triangularView<Eigen::Lower>();
      lower.solveInPlace(t.r);
      lower.solveInPlace(t.J);
      lower.solveInPlace(t.G);
    }
    // B = J~^T D, one Huber weight per whitened corner.
    Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, kMaxRows> B = t.J.transpose();
    for (Eigen::Index k = 0; k + 1 < rows; k += 2) {
      const double e = t.r.segment<2>(k).norm();
      const double w = e <= options.huber_threshold_px ? 1.0 : options.huber_threshold_px / e;
      B.middleCols<2>(k) *= w;
    }
    // M = B L^-1 = (L^-T B^T)^T.
    Eigen::Matrix<double, Eigen::Dynamic, 3, 0, kMaxRows, 3> Mt = B.transpose();
    if (whitened) L.transpose().triangularView<Eigen::Upper>().solveInPlace(Mt);
    pixel_information += Mt.transpose() * Mt;
    if (variances.isZero(0.0)) continue;
    const Eigen::Matrix<double, 3, 5> J_fix_map = -H_inv * B * t.G;
    const auto same =
        std::find_if(result.map_terms.begin(), result.map_terms.end(),
                     [&](const MapErrorTerm& m) { return m.landmark_id == o.landmark_id; });
    if (same != result.map_terms.end()) {
      same->J_fix_map += J_fix_map;
    } else {
      result.map_terms.push_back({o.landmark_id, J_fix_map, variances});
    }
  }
  const double pixel_variance = options.pixel_sigma * options.pixel_sigma;
  result.pixel_covariance = pixel_variance * H_inv * pixel_information * H_inv.transpose();
  result.pixel_covariance =
      0.5 * (result.pixel_covariance + result.pixel_covariance.transpose()).eval();
}

// Mean whitened corner error of one observation at a pose (its whitening taken there);
// infinity when a corner does not project.
double meanCornerError(const geometry::RigCamera& camera, const LandmarkObservation& o,
                       const geometry::Pose2& pose, const SolverOptions& options) {
  const bool exact = mapVariances(o, options).isZero(0.0);
  ObservationTerms t = observationTerms(camera, pose, o, !exact);
  if (!t.all_project || t.r.size() == 0) return kInfinity;
  whiten(whiteningFactor(t, o, options), t);
  double sum = 0.0;
  for (Eigen::Index k = 0; k + 1 < t.r.size(); k += 2) sum += t.r.segment<2>(k).norm();
  return sum / static_cast<double>(t.r.size() / 2);
}

geometry::Pose2 applyStep(const geometry::Pose2& pose, const Eigen::Vector3d& step) {
  return {pose.x + step.x(), pose.y + step.y(), pose.yaw + step.z()};
}

}  // namespace

Eigen::Matrix3d withMapPositionError(const Eigen::Matrix3d& pose_covariance,
                                     const map::MapAccuracy& accuracy) {
  const double sigma = accuracy.position_sigma.value_or(0.0);
  Eigen::Matrix3d P = pose_covariance;
  P(0, 0) += sigma * sigma;
  P(1, 1) += sigma * sigma;
  return P;
}

std::optional<CornerProjection> projectMapCorner(const geometry::RigCamera& camera,
                                                 const geometry::Pose2& map_from_vehicle,
                                                 const Eigen::Vector3d& map_corner) {
  // Map -> vehicle: p_v = R(yaw)^T (p_m - t), height unchanged.
  const double c = std::cos(map_from_vehicle.yaw), s = std::sin(map_from_vehicle.yaw);
  const double dx = map_corner.x() - map_from_vehicle.x;
  const double dy = map_corner.y() - map_from_vehicle.y;
  const Eigen::Vector3d p_vehicle(c * dx + s * dy, -s * dx + c * dy, map_corner.z());
  Eigen::Matrix<double, 3, 3> J_vehicle_pose;
  J_vehicle_pose << -c, -s, -s * dx + c * dy,  //
      s, -c, -c * dx - s * dy,                 //
      0.0, 0.0, 0.0;
  const Eigen::Matrix3d R_camera_vehicle = camera.vehicle_from_camera.linear().transpose();
  const Eigen::Vector3d p_camera =
      R_camera_vehicle * (p_vehicle - camera.vehicle_from_camera.translation());
  const auto projected = projectWithJacobian(camera.model, p_camera);
  if (!projected) return std::nullopt;
  // d p_vehicle / d map corner: the inverse rotation in x-y, the height as it is.
  Eigen::Matrix3d J_vehicle_corner;
  J_vehicle_corner << c, s, 0.0,  //
      -s, c, 0.0,                 //
      0.0, 0.0, 1.0;
  const Eigen::Matrix<double, 2, 3> J_pixel_vehicle = projected->J_pixel_point * R_camera_vehicle;
  return CornerProjection{projected->pixel, J_pixel_vehicle * J_vehicle_pose,
                          J_pixel_vehicle * J_vehicle_corner};
}

std::optional<geometry::Pose2> poseFromObservation(const geometry::RigCamera& camera,
                                                   const LandmarkObservation& observation) {
  std::array<Eigen::Vector2d, 4> in_vehicle;
  for (int i = 0; i < 4; ++i) {
    const auto plane = geometry::Plane::throughPoint(Eigen::Vector3d::UnitZ(),
                                                     {0.0, 0.0, observation.map_corners[i].z()});
    const auto p = geometry::pixelToPlane(camera, observation.pixels[i], plane);
    if (!p) return std::nullopt;
    in_vehicle[i] = p->head<2>();
  }
  // 2-D rigid alignment (Kabsch in the plane): map = R vehicle + t.
  Eigen::Vector2d mean_v = Eigen::Vector2d::Zero(), mean_m = Eigen::Vector2d::Zero();
  for (int i = 0; i < 4; ++i) {
    mean_v += in_vehicle[i] / 4.0;
    mean_m += observation.map_corners[i].head<2>() / 4.0;
  }
  double dot = 0.0, cross = 0.0;
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector2d a = in_vehicle[i] - mean_v;
    const Eigen::Vector2d b = observation.map_corners[i].head<2>() - mean_m;
    dot += a.dot(b);
    cross += a.x() * b.y() - a.y() * b.x();
  }
  if (std::abs(dot) + std::abs(cross) < 1e-12) return std::nullopt;
  const double yaw = std::atan2(cross, dot);
  const geometry::Pose2 rotation(0.0, 0.0, yaw);
  const Eigen::Vector2d t = mean_m - rotation.rotation() * mean_v;
  return geometry::Pose2(t.x(), t.y(), yaw);
}

SolverResult refinePose(const geometry::Rig& rig, const std::vector<LandmarkObservation>& obs,
                        const geometry::Pose2& initial, const SolverOptions& options,
                        const std::vector<bool>& use_in) {
  const std::vector<bool> use = use_in.empty() ? std::vector<bool>(obs.size(), true) : use_in;
  SolverResult result;
  result.pose = initial;
  // Levenberg-Marquardt on the Huber cost (IRLS weights re-evaluated every iteration).
  double lambda = 1e-4;
  const std::vector<Group> groups = landmarkGroups(obs, use);
  std::vector<RowsByRows> factors = whiteningFactors(rig, obs, groups, result.pose, options);
  const double huber = options.huber_threshold_px;
  NormalEquations current = accumulate(rig, obs, groups, result.pose, factors, huber);
  for (int iter = 0; iter < options.max_iterations; ++iter) {
    result.iterations = iter + 1;
    if (current.corners < 2) break;
    Eigen::Matrix3d A = current.H;
    A.diagonal() += lambda * current.H.diagonal().cwiseMax(1e-9);
    const Eigen::Vector3d step = A.ldlt().solve(-current.g);
    if (!step.allFinite()) break;
    const geometry::Pose2 candidate = applyStep(result.pose, step);
    const NormalEquations next = accumulate(rig, obs, groups, candidate, factors, huber);
    if (next.corners >= current.corners && next.cost <= current.cost) {
      const double decrease = current.cost - next.cost;
      result.pose = candidate;
      current = next;
      lambda = std::max(lambda * 0.1, 1e-10);
      if (step.cwiseAbs().sum() < options.step_tolerance ||
          decrease <= 1e-12 * std::max(current.cost, 1e-300)) {
        result.converged = true;
        break;
      }
    } else {
      lambda *= 10.0;
      if (lambda > 1e8) {
        // No descent left: at a minimum to machine precision, or stuck.
        result.converged = step.cwiseAbs().sum() < 1e3 * options.step_tolerance;
        break;
      }
    }
  }

  // The fit and the covariance with the whitening where the refinement ended.
  factors = whiteningFactors(rig, obs, groups, result.pose, options);
  current = accumulate(rig, obs, groups, result.pose, factors, huber);
  result.residual_px.resize(obs.size());
  result.inlier = use;
  for (size_t o = 0; o < obs.size(); ++o)
    result.residual_px[o] = meanCornerError(rig.cameras[obs[o].camera], obs[o], result.pose, options);
  if (current.corners < 2) {
    result.failure = "fewer than 2 points project into their cameras";
    return result;
  }
  result.rms_px = std::sqrt(current.squared_error / current.corners);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(current.H);
  if (eigen.eigenvalues().minCoeff() <= 1e-9 * std::max(1.0, eigen.eigenvalues().maxCoeff())) {
    result.failure = "degenerate geometry (normal matrix singular)";
    return result;
  }
  const double pixel_variance = options.pixel_sigma * options.pixel_sigma;
  result.covariance = pixel_variance * current.H.inverse();
  // What is left of it with an exact map (H_pixel >= H: whitening only removes information).
  const Eigen::Matrix3d exact_map = pixel_variance * current.H_pixel.inverse();
  if (exact_map.allFinite()) {
    const Eigen::Matrix3d difference = result.covariance - exact_map;
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> split(0.5 *
                                                               (difference + difference.transpose()));
    result.map_covariance = split.eigenvectors() *
                            split.eigenvalues().cwiseMax(0.0).asDiagonal() *
                            split.eigenvectors().transpose();
  }
  splitMapError(rig, obs, groups, result.pose, factors, current.H, options, result);
  if (!result.converged) {
    result.failure =
        "did not converge in " + std::to_string(options.max_iterations) + " iterations";
    return result;
  }
  result.ok = true;
  return result;
}

SolverResult solvePose(const geometry::Rig& rig, const std::vector<LandmarkObservation>& obs,
                       const std::optional<geometry::Pose2>& prior, const SolverOptions& options) {
  SolverResult best;
  best.failure = "no observation gives a pose";
  if (obs.empty()) {
    best.failure = "no observations";
    return best;
  }
  SolverOptions quick = options;
  quick.max_iterations = std::min(options.max_iterations, 8);

  std::vector<geometry::Pose2> hypotheses;
  if (prior) hypotheses.push_back(*prior);
  // Hypotheses from the observations that look largest (nearest: the best single-text
  // poses); a handful suffices as every one of them sees the whole pose.
  std::vector<size_t> order(obs.size());
  for (size_t o = 0; o < obs.size(); ++o) order[o] = o;
  const auto area = [&](size_t o) {
    const auto& q = obs[o].pixels;
    double a = 0.0;
    for (int i = 0; i < 4; ++i) a += q[i].x() * q[(i + 1) % 4].y() - q[i].y() * q[(i + 1) % 4].x();
    return std::abs(a);
  };
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return area(a) > area(b); });
  if (order.size() > static_cast<size_t>(options.max_hypotheses))
    order.resize(static_cast<size_t>(options.max_hypotheses));
  for (const size_t o : order) {
    const auto pose = poseFromObservation(rig.cameras[obs[o].camera], obs[o]);
    if (!pose) continue;
    // Polish on its own observation so that far texts (poor ground casting) score fairly.
    std::vector<bool> only(obs.size(), false);
    only[o] = true;
    const SolverResult polished = refinePose(rig, obs, *pose, quick, only);
    hypotheses.push_back(polished.converged || polished.ok ? polished.pose : *pose);
  }

  int best_count = -1;
  double best_error = kInfinity;
  std::optional<geometry::Pose2> best_pose;
  std::vector<bool> best_inliers;
  for (const auto& h : hypotheses) {
    int count = 0;
    double error = 0.0;
    std::vector<bool> inliers(obs.size(), false);
    for (size_t o = 0; o < obs.size(); ++o) {
      const double e = meanCornerError(rig.cameras[obs[o].camera], obs[o], h, options);
      if (e < options.inlier_threshold_px) {
        inliers[o] = true;
        ++count;
        error += e;
      }
    }
    if (count > best_count || (count == best_count && error < best_error)) {
      best_count = count;
      best_error = error;
      best_pose = h;
      best_inliers = inliers;
    }
  }
  if (!best_pose || best_count <= 0) return best;

  SolverResult result = refinePose(rig, obs, *best_pose, options, best_inliers);
  // Re-classify at the refined pose once: an observation may move in or out.
  std::vector<bool> inliers(obs.size(), false);
  for (size_t o = 0; o < obs.size(); ++o)
    inliers[o] = result.residual_px[o] < options.inlier_threshold_px;
  if (inliers != best_inliers && std::count(inliers.begin(), inliers.end(), true) > 0)
    result = refinePose(rig, obs, result.pose, options, inliers);
  if (!result.ok || options.centre_fallback_px <= 0.0) return result;

  // A text whose corners disagree but whose centre fits (a detector box around sheared
  // floor text) still measures its centre.
  std::vector<LandmarkObservation> mixed = obs;
  std::vector<bool> use = result.inlier;
  bool added = false;
  for (size_t o = 0; o < obs.size(); ++o) {
    if (result.inlier[o] || !obs[o].use_corners) continue;
    mixed[o].use_corners = false;
    if (meanCornerError(rig.cameras[obs[o].camera], mixed[o], result.pose, options) <
        options.centre_fallback_px) {
      use[o] = true;
      added = true;
    }
  }
  if (!added) return result;
  SolverResult with_centres = refinePose(rig, mixed, result.pose, options, use);
  if (!with_centres.ok) return result;
  return with_centres;
}

}  // namespace parkloc::localize
