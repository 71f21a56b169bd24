#include "eval/drive_smoother.h"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <map>
#include <string>

namespace parkloc::eval {
namespace {

constexpr int kFrameStates = 5;  // x, y, yaw, yaw-rate bias, speed scale
constexpr int kLandmarkStates = 5;

// Accumulates J^T W J and J^T W r of residual blocks over the state.
struct NormalEquations {
  explicit NormalEquations(Eigen::Index n) : g(Eigen::VectorXd::Zero(n)) {}
  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::VectorXd g;
  double cost = 0.0;
  // A residual r with Jacobian blocks J[k] on the states starting at index[k], weight W.
  void add(const Eigen::VectorXd& r, const std::vector<Eigen::MatrixXd>& J,
           const std::vector<Eigen::Index>& index, const Eigen::MatrixXd& W) {
    cost += r.dot(W * r);
    for (size_t a = 0; a < J.size(); ++a) {
      g.segment(index[a], J[a].cols()) += J[a].transpose() * W * r;
      for (size_t b = 0; b < J.size(); ++b) {
        const Eigen::MatrixXd block = J[a].transpose() * W * J[b];
        for (Eigen::Index i = 0; i < block.rows(); ++i)
          for (Eigen::Index j = 0; j < block.cols(); ++j)
            if (block(i, j) != 0.0) triplets.emplace_back(index[a] + i, index[b] + j, block(i, j));
      }
    }
  }
};

// The sample held at time t (the last one at or before it), if any.
const OdometrySample* heldAt(const std::vector<OdometrySample>& odometry, double t) {
  const auto it =
      std::upper_bound(odometry.begin(), odometry.end(), t,
                       [](double time, const OdometrySample& s) { return time < s.timestamp; });
  if (it == odometry.begin()) return nullptr;
  return &*(it - 1);
}

Eigen::Vector3d relative(const Eigen::Matrix<double, kFrameStates, 1>& a,
                         const Eigen::Matrix<double, kFrameStates, 1>& b) {
  const double c = std::cos(a(2)), s = std::sin(a(2));
  const double dx = b(0) - a(0), dy = b(1) - a(1);
  return {c * dx + s * dy, -s * dx + c * dy, std::remainder(b(2) - a(2), 2.0 * M_PI)};
}

}  // namespace

OdometryMotion integrateHeldOdometry(const std::vector<OdometrySample>& odometry, double t0,
                                     double t1, double bias, double scale,
                                     const localize::EkfOptions& noise) {
  OdometryMotion m;
  double t = t0;
  while (t < t1) {
    const OdometrySample* held = heldAt(odometry, t);
    const auto next =
        std::upper_bound(odometry.begin(), odometry.end(), t,
                         [](double time, const OdometrySample& s) { return time < s.timestamp; });
    const double end = next == odometry.end() ? t1 : std::min(t1, next->timestamp);
    const double dt = end - t;
    t = end;
    if (!held || !(dt > 0.0)) continue;
    // The filter's arc (PoseEkf::predictWithOdometry) and its input noise over this piece.
    const localize::OdometryArc arc =
        localize::odometryArc(m.delta(2), held->speed, held->yaw_rate, bias, scale, dt);
    const Eigen::Matrix3d F = arc.J_state.leftCols<3>();
    const Eigen::Vector2d input(noise.speed_sigma * noise.speed_sigma,
                                noise.yaw_rate_sigma * noise.yaw_rate_sigma);
    m.covariance = F * m.covariance * F.transpose() +
                   arc.J_input * input.asDiagonal() * arc.J_input.transpose();
    m.delta += arc.delta;
  }
  return m;
}

std::optional<SmootherResult> smoothDrive(const std::vector<SmootherFrame>& frames,
                                          const std::vector<OdometrySample>& odometry,
                                          const localize::EkfOptions& noise,
                                          const SmootherOptions& options) {
  if (frames.empty()) return std::nullopt;
  // The landmarks, one block of states each.
  std::map<std::string, Eigen::Index> landmark;
  Eigen::Index n = kFrameStates * static_cast<Eigen::Index>(frames.size());
  size_t fixes = 0;
  for (const SmootherFrame& f : frames)
    for (const localize::FusedFix& fix : f.fixes) {
      ++fixes;
      for (const localize::MapErrorTerm& t : fix.map_terms)
        if (landmark.emplace(t.landmark_id, n).second) n += kLandmarkStates;
    }
  if (fixes == 0) return std::nullopt;

  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  for (size_t k = 0; k < frames.size(); ++k) {
    const auto i = static_cast<Eigen::Index>(kFrameStates * k);
    x.segment<3>(i) << frames[k].initial.x, frames[k].initial.y, frames[k].initial.yaw;
    x(i + 4) = 1.0;
  }
  std::map<std::string, Eigen::Matrix<double, 5, 1>> landmark_variance;
  for (const SmootherFrame& f : frames)
    for (const localize::FusedFix& fix : f.fixes)
      for (const localize::MapErrorTerm& t : fix.map_terms)
        landmark_variance[t.landmark_id] = t.variance;

  SmootherResult result;
  for (int iter = 0; iter < options.max_iterations; ++iter) {
    result.iterations = iter + 1;
    NormalEquations ne(n);
    // Priors: the odometry errors at the first frame set, each landmark's map error.
    {
      Eigen::VectorXd r(2);
      r << x(3), x(4) - 1.0;
      Eigen::MatrixXd J = Eigen::MatrixXd::Identity(2, 2);
      Eigen::MatrixXd W =
          Eigen::Vector2d(1.0 / (noise.yaw_rate_bias_sigma * noise.yaw_rate_bias_sigma),
                          1.0 / (noise.speed_scale_sigma * noise.speed_scale_sigma))
              .asDiagonal();
      ne.add(r, {J}, {3}, W);
    }
    for (const auto& [id, at] : landmark) {
      const Eigen::Matrix<double, 5, 1> v = landmark_variance[id].cwiseMax(1e-12);
      ne.add(x.segment<kLandmarkStates>(at), {Eigen::MatrixXd::Identity(5, 5)}, {at},
             v.cwiseInverse().asDiagonal().toDenseMatrix());
    }
    // Odometry between consecutive frame sets; the bias and scale walk.
    for (size_t k = 0; k + 1 < frames.size(); ++k) {
      const auto a = static_cast<Eigen::Index>(kFrameStates * k), b = a + kFrameStates;
      const double t0 = frames[k].timestamp, t1 = frames[k + 1].timestamp;
      const auto motion = [&](const Eigen::VectorXd& s) {
        return integrateHeldOdometry(odometry, t0, t1, s(a + 3), s(a + 4), noise);
      };
      const OdometryMotion m = motion(x);
      const auto residual = [&](const Eigen::VectorXd& s, const Eigen::Vector3d& delta) {
        Eigen::Vector3d r =
            relative(s.segment<kFrameStates>(a), s.segment<kFrameStates>(b)) - delta;
        r(2) = std::remainder(r(2), 2.0 * M_PI);
        return r;
      };
      const Eigen::Vector3d r = residual(x, m.delta);
      // Central differences over the 10 states the factor touches.
      Eigen::MatrixXd Ja(3, kFrameStates), Jb(3, kFrameStates);
      for (int j = 0; j < 2 * kFrameStates; ++j) {
        const Eigen::Index at = (j < kFrameStates ? a : b) + j % kFrameStates;
        const double h = j % kFrameStates == 4 ? 1e-6 : (j % kFrameStates == 3 ? 1e-7 : 1e-6);
        Eigen::VectorXd plus = x, minus = x;
        plus(at) += h;
        minus(at) -= h;
        const bool odometry_state = at == a + 3 || at == a + 4;
        const Eigen::Vector3d rp = residual(plus, odometry_state ? motion(plus).delta : m.delta);
        const Eigen::Vector3d rm = residual(minus, odometry_state ? motion(minus).delta : m.delta);
        Eigen::Vector3d d = rp - rm;
        d(2) = std::remainder(d(2), 2.0 * M_PI);
        (j < kFrameStates ? Ja : Jb).col(j % kFrameStates) = d / (2.0 * h);
      }
      Eigen::Matrix3d Q = m.covariance;
      Q.diagonal() += Eigen::Vector3d(1e-8, 1e-8, 1e-10);
      ne.add(r, {Ja, Jb}, {a, b}, Q.inverse());
      const double dt = std::max(t1 - t0, 1e-6);
      Eigen::VectorXd rw = x.segment<2>(b + 3) - x.segment<2>(a + 3);
      Eigen::MatrixXd Jwa = -Eigen::MatrixXd::Identity(2, 2), Jwb = Eigen::MatrixXd::Identity(2, 2);
      Eigen::MatrixXd Ww =
          Eigen::Vector2d(1.0 / (noise.yaw_rate_bias_walk * noise.yaw_rate_bias_walk * dt + 1e-12),
                          1.0 / (noise.speed_scale_walk * noise.speed_scale_walk * dt + 1e-12))
              .asDiagonal();
      ne.add(rw, {Jwa, Jwb}, {a + 3, b + 3}, Ww);
    }
    // Each fix: z - pose - sum J e.
    for (size_t k = 0; k < frames.size(); ++k) {
      const auto a = static_cast<Eigen::Index>(kFrameStates * k);
      for (const localize::FusedFix& fix : frames[k].fixes) {
        Eigen::Vector3d r(x(a) - fix.pose.x, x(a + 1) - fix.pose.y, x(a + 2) - fix.pose.yaw);
        std::vector<Eigen::MatrixXd> J{Eigen::MatrixXd::Identity(3, 3)};
        std::vector<Eigen::Index> index{a};
        for (const localize::MapErrorTerm& t : fix.map_terms) {
          const Eigen::Index l = landmark.at(t.landmark_id);
          r += t.J_fix_map * x.segment<kLandmarkStates>(l);
          J.push_back(t.J_fix_map);
          index.push_back(l);
        }
        r(2) = std::remainder(r(2), 2.0 * M_PI);
        ne.add(r, J, index, fix.pixel_covariance.inverse());
      }
    }
    Eigen::SparseMatrix<double> H(n, n);
    H.setFromTriplets(ne.triplets.begin(), ne.triplets.end());
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(H);
    if (solver.info() != Eigen::Success) return std::nullopt;
    const Eigen::VectorXd step = solver.solve(-ne.g);
    if (!step.allFinite()) return std::nullopt;
    x += step;
    if (step.cwiseAbs().maxCoeff() < options.step_tolerance) {
      result.converged = true;
      break;
    }
  }
  result.poses.reserve(frames.size());
  for (size_t k = 0; k < frames.size(); ++k) {
    const auto i = static_cast<Eigen::Index>(kFrameStates * k);
    result.poses.emplace_back(x(i), x(i + 1), geometry::wrapAngle(x(i + 2)));
  }
  return result;
}

}  // namespace parkloc::eval
