#include "run/frame_log.h"

#include <nlohmann/json.hpp>

namespace parkloc::run {
namespace {

nlohmann::json poseJson(const geometry::Pose2& p) {
  return {{"x", p.x}, {"y", p.y}, {"yaw", p.yaw}};
}

nlohmann::json matrixJson(const Eigen::Matrix3d& m) {
  nlohmann::json rows = nlohmann::json::array();
  for (int r = 0; r < 3; ++r) rows.push_back({m(r, 0), m(r, 1), m(r, 2)});
  return rows;
}

}  // namespace

std::string frameResultToJson(const localize::FrameResult& r) {
  nlohmann::json j;
  j["timestamp"] = r.timestamp;
  j["status"] = toString(r.status);
  j["has_pose"] = r.has_pose;
  if (r.has_pose) {
    j["pose"] = poseJson(r.pose);
    j["covariance"] = matrixJson(r.covariance);
  }
  if (r.odometry)
    j["odometry_estimate"] = {{"yaw_rate_bias", r.odometry->yaw_rate_bias},
                              {"yaw_rate_bias_sigma", r.odometry->yaw_rate_bias_sigma},
                              {"speed_scale", r.odometry->speed_scale},
                              {"speed_scale_sigma", r.odometry->speed_scale_sigma}};
  if (r.measurement) j["measurement"] = poseJson(*r.measurement);
  if (r.measurement_covariance) j["measurement_covariance"] = matrixJson(*r.measurement_covariance);
  j["solver"] = {{"converged", r.solver_converged}, {"iterations", r.solver_iterations}};
  j["reinitialised"] = r.reinitialised;
  j["tentative"] = r.tentative;
  j["level"] = {{"name", r.level}, {"probability", r.level_probability}, {"decided", r.level_decided}};
  nlohmann::json cameras = nlohmann::json::array();
  for (const auto& c : r.cameras) {
    nlohmann::json instances = nlohmann::json::array();
    for (const auto& t : c.instances) {
      nlohmann::json polygon = nlohmann::json::array();
      for (const auto& p : t.polygon) polygon.push_back({p.x, p.y});
      instances.push_back({{"text", t.text},
                           {"raw_text", t.raw_text},
                           {"lexicon_match", t.lexicon_match},
                           {"second_opinion", t.second_opinion},
                           {"partial", t.partial},
                           {"class", map::toString(t.cls)},
                           {"polygon", polygon},
                           {"detection_score", t.detection_score},
                           {"recognition_score", t.recognition_score},
                           {"class_score", t.class_score},
                           {"read", t.read}});
    }
    cameras.push_back({{"camera", c.camera},
                       {"image_ok", c.image_ok},
                       {"full_frame", c.full_frame},
                       {"regions", c.regions},
                       {"instances", instances}});
  }
  j["cameras"] = cameras;
  nlohmann::json associations = nlohmann::json::array();
  for (const auto& a : r.associations) {
    nlohmann::json e = {{"camera", a.camera},
                        {"instance", a.instance_index},
                        {"text", a.text},
                        {"verdict", toString(a.verdict)}};
    if (!a.landmark_id.empty()) e["landmark_id"] = a.landmark_id;
    if (a.mahalanobis2 >= 0.0) e["mahalanobis2"] = a.mahalanobis2;
    if (a.residual_px >= 0.0) e["residual_px"] = a.residual_px;
    associations.push_back(e);
  }
  j["associations"] = associations;
  j["timings_ms"] = {{"roi", r.timings.roi_ms},
                     {"spotting", r.timings.spotting_ms},
                     {"association", r.timings.association_ms},
                     {"solver", r.timings.solver_ms},
                     {"filter", r.timings.filter_ms},
                     {"total", r.timings.total_ms},
                     {"cpu", r.timings.cpu_ms}};
  // The workers (localize/search_worker.h): the cameras handed to them, and what they gave
  // back and was fused in this frame set, with their own time (off the critical path).
  const auto fusion = [](const localize::BackgroundFusion& b) {
    size_t instances = 0, accepted = 0;
    for (const auto& c : b.cameras) instances += c.instances.size();
    for (const auto& a : b.associations)
      accepted += a.verdict == localize::AssociationVerdict::kAccepted;
    nlohmann::json out = {{"capture_timestamp", b.capture_timestamp},
                          {"instances", instances},
                          {"accepted", accepted},
                          {"worker_ms", b.worker_ms},
                          {"worker_cpu_ms", b.worker_cpu_ms}};
    if (b.measurement) out["measurement"] = poseJson(*b.measurement);
    return out;
  };
  j["background_cameras"] = r.background_cameras;
  if (r.background) j["background"] = fusion(*r.background);
  j["deferred_read_cameras"] = r.deferred_read_cameras;
  if (r.deferred_reads) j["deferred_reads"] = fusion(*r.deferred_reads);
  j["warnings"] = r.warnings;
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace parkloc::run
