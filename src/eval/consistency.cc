#include "eval/consistency.h"

#include <fmt/format.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>

#include "common/error.h"
#include "run/sequence_runner.h"

namespace parkloc::eval {

std::vector<ReportedFrame> loadReportedFrames(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw IoError(fmt::format("{}: cannot open", path));
  std::vector<ReportedFrame> frames;
  std::string line;
  size_t number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const auto where = [&](const std::string& why) {
      return InputError(fmt::format("{}:{}: {}", path, number, why));
    };
    nlohmann::json j;
    try {
      j = nlohmann::json::parse(line);
    } catch (const nlohmann::json::exception& e) {
      throw where(fmt::format("not JSON ({})", e.what()));
    }
    try {
      ReportedFrame f;
      f.timestamp = j.at("timestamp").get<double>();
      f.status = j.at("status").get<std::string>();
      f.has_pose = j.at("has_pose").get<bool>();
      if (f.has_pose) {
        const auto& p = j.at("pose");
        f.pose = geometry::Pose2(p.at("x").get<double>(), p.at("y").get<double>(),
                                 p.at("yaw").get<double>());
        const auto& c = j.at("covariance");
        if (!c.is_array() || c.size() != 3) throw where("field 'covariance' is not 3x3");
        for (int r = 0; r < 3; ++r) {
          if (!c[r].is_array() || c[r].size() != 3) throw where("field 'covariance' is not 3x3");
          for (int k = 0; k < 3; ++k) f.covariance(r, k) = c[r][k].get<double>();
        }
      }
      frames.push_back(f);
    } catch (const nlohmann::json::exception& e) {
      throw where(fmt::format("missing or mistyped field ({})", e.what()));
    }
  }
  return frames;
}

double nees(const Eigen::Vector3d& error, const Eigen::Matrix3d& covariance) {
  const Eigen::LLT<Eigen::Matrix3d> llt(covariance);
  if (llt.info() != Eigen::Success || !covariance.allFinite())
    return std::numeric_limits<double>::infinity();
  return error.dot(llt.solve(error));
}

double protectionLevel(const Eigen::Matrix3d& covariance, double k) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(covariance.topLeftCorner<2, 2>());
  return k * std::sqrt(std::max(0.0, eigen.eigenvalues().maxCoeff()));
}

ConsistencyResult evaluateConsistency(const std::vector<ReportedFrame>& frames,
                                      const std::vector<io::StampedPose>& truth,
                                      const ConsistencyOptions& options) {
  ConsistencyResult r;
  std::vector<double> finite_nees;
  double pl_sum = 0.0, error_sum = 0.0;
  bool in_episode = false, seen_pose = false;
  r.frames_total = frames.size();
  for (const auto& f : frames) {
    const bool alert_status =
        std::find(options.alert_statuses.begin(), options.alert_statuses.end(), f.status) !=
        options.alert_statuses.end();
    if (!f.has_pose) {
      ++r.frames_without_pose;
      if (seen_pose && !alert_status) ++r.frames_unanswered;
      in_episode = false;
      continue;
    }
    seen_pose = true;
    const auto t = run::truthAt(truth, f.timestamp);
    if (!t) {
      ++r.frames_without_truth;
      continue;
    }
    FrameConsistency c;
    c.timestamp = f.timestamp;
    c.error =
        Eigen::Vector3d(f.pose.x - t->x, f.pose.y - t->y, geometry::wrapAngle(f.pose.yaw - t->yaw));
    c.position_error_m = c.error.head<2>().norm();
    c.nees = nees(c.error, f.covariance);
    c.protection_level_m = protectionLevel(f.covariance, options.protection_k);
    c.inside_bound = c.nees <= options.nees_bound;
    c.alert = alert_status || c.protection_level_m > options.alert_limit_m;
    const bool over = c.position_error_m > options.alert_limit_m;
    c.missed = over && !c.alert;

    r.inside_bound += c.inside_bound;
    r.alerts += c.alert;
    r.over_alert_limit += over;
    r.missed_detections += c.missed;
    r.false_alerts += c.alert && !over;
    if (over && !in_episode) {
      ++r.episodes;
      if (!c.alert) ++r.late_episodes;
    }
    in_episode = over;
    if (std::isfinite(c.nees)) finite_nees.push_back(c.nees);
    r.max_position_error_m = std::max(r.max_position_error_m, c.position_error_m);
    pl_sum += c.protection_level_m;
    error_sum += c.position_error_m;
    r.frames.push_back(c);
  }
  if (!r.frames.empty()) {
    r.fraction_inside = static_cast<double>(r.inside_bound) / static_cast<double>(r.frames.size());
    r.mean_protection_level_m = pl_sum / static_cast<double>(r.frames.size());
    r.mean_position_error_m = error_sum / static_cast<double>(r.frames.size());
  }
  if (!finite_nees.empty()) {
    double sum = 0.0;
    for (double v : finite_nees) sum += v;
    r.mean_nees = sum / static_cast<double>(finite_nees.size());
    const size_t mid = finite_nees.size() / 2;
    std::nth_element(finite_nees.begin(), finite_nees.begin() + mid, finite_nees.end());
    r.median_nees = finite_nees[mid];
  }
  return r;
}

}  // namespace parkloc::eval
