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

// The mean of the projected corners (what a box centre measures) and its Jacobian.
std::optional<CornerProjection> projectCentre(const geometry::RigCamera& camera,
                                              const geometry::Pose2& pose,
                                              const LandmarkObservation& o) {
  CornerProjection c{Eigen::Vector2d::Zero(), Eigen::Matrix<double, 2, 3>::Zero()};
  for (int i = 0; i < 4; ++i) {
    const auto p = projectMapCorner(camera, pose, o.map_corners[i]);
    if (!p) return std::nullopt;
    c.pixel += 0.25 * p->pixel;
    c.J_pixel_pose += 0.25 * p->J_pixel_pose;
  }
  return c;
}

struct NormalEquations {
  Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
  Eigen::Vector3d g = Eigen::Vector3d::Zero();
  double cost = 0.0;
  double squared_error = 0.0;
  int corners = 0;
};

NormalEquations accumulate(const geometry::Rig& rig, const std::vector<LandmarkObservation>& obs,
                           const std::vector<bool>& use, const geometry::Pose2& pose,
                           double huber) {
  NormalEquations n;
  // One Huber-weighted (IRLS) residual, for a corner or a centre alike.
  const auto add = [&](const Eigen::Vector2d& r, const Eigen::Matrix<double, 2, 3>& J) {
    const double e = r.norm();
    const double w = e <= huber ? 1.0 : huber / e;
    n.H += w * J.transpose() * J;
    n.g += w * J.transpose() * r;
    n.cost += huberCost(e, huber);
    n.squared_error += e * e;
    ++n.corners;
  };
  for (size_t o = 0; o < obs.size(); ++o) {
    if (!use[o]) continue;
    const auto& camera = rig.cameras[obs[o].camera];
    if (!obs[o].use_corners) {
      const auto c = projectCentre(camera, pose, obs[o]);
      if (!c) continue;
      add(c->pixel - observedCentre(obs[o]), c->J_pixel_pose);
      continue;
    }
    for (int i = 0; i < 4; ++i) {
      const auto p = projectMapCorner(camera, pose, obs[o].map_corners[i]);
      if (!p) continue;
      add(p->pixel - obs[o].pixels[i], p->J_pixel_pose);
    }
  }
  return n;
}

double meanCornerError(const geometry::RigCamera& camera, const LandmarkObservation& o,
                       const geometry::Pose2& pose) {
  if (!o.use_corners) {
    const auto c = projectCentre(camera, pose, o);
    return c ? (c->pixel - observedCentre(o)).norm() : kInfinity;
  }
  double sum = 0.0;
  for (int i = 0; i < 4; ++i) {
    const auto p = projectMapCorner(camera, pose, o.map_corners[i]);
    if (!p) return kInfinity;
    sum += (p->pixel - o.pixels[i]).norm();
  }
  return sum / 4.0;
}

geometry::Pose2 applyStep(const geometry::Pose2& pose, const Eigen::Vector3d& step) {
  return {pose.x + step.x(), pose.y + step.y(), pose.yaw + step.z()};
}

}  // namespace

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
  return CornerProjection{projected->pixel,
                          projected->J_pixel_point * R_camera_vehicle * J_vehicle_pose};
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
  NormalEquations current = accumulate(rig, obs, use, result.pose, options.huber_threshold_px);
  for (int iter = 0; iter < options.max_iterations; ++iter) {
    result.iterations = iter + 1;
    if (current.corners < 2) break;
    Eigen::Matrix3d A = current.H;
    A.diagonal() += lambda * current.H.diagonal().cwiseMax(1e-9);
    const Eigen::Vector3d step = A.ldlt().solve(-current.g);
    if (!step.allFinite()) break;
    const geometry::Pose2 candidate = applyStep(result.pose, step);
    const NormalEquations next = accumulate(rig, obs, use, candidate, options.huber_threshold_px);
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

  result.residual_px.resize(obs.size());
  result.inlier = use;
  for (size_t o = 0; o < obs.size(); ++o)
    result.residual_px[o] = meanCornerError(rig.cameras[obs[o].camera], obs[o], result.pose);
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
  result.covariance = options.pixel_sigma * options.pixel_sigma * current.H.inverse();
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
      const double e = meanCornerError(rig.cameras[obs[o].camera], obs[o], h);
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
    if (meanCornerError(rig.cameras[obs[o].camera], mixed[o], result.pose) <
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
