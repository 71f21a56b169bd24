#include "localize/search_window.h"

#include <cmath>

namespace parkloc::localize {
namespace {

// Constant speed and yaw rate over dt: the exact arc.
geometry::Pose2 arc(double speed, double yaw_rate, double dt) {
  const double dyaw = yaw_rate * dt, distance = speed * dt;
  // Chord of the arc, at half the turn (exact for a constant yaw rate).
  const double chord =
      std::abs(dyaw) < 1e-9 ? distance : distance * std::sin(0.5 * dyaw) / (0.5 * dyaw);
  return geometry::Pose2(chord * std::cos(0.5 * dyaw), chord * std::sin(0.5 * dyaw), dyaw);
}

}  // namespace

std::optional<geometry::Pose2> integrateOdometry(const std::optional<OdometrySample>& held,
                                                 const std::vector<OdometrySample>& samples,
                                                 double t0, double t1) {
  if (!held || !(t1 >= t0)) return std::nullopt;
  geometry::Pose2 pose;
  OdometrySample current = *held;
  double t = t0;
  for (const auto& s : samples) {
    if (s.timestamp <= t) {
      current = s;
      continue;
    }
    const double until = std::min(s.timestamp, t1);
    pose = pose * arc(current.speed, current.yaw_rate, until - t);
    t = until;
    current = s;
    if (t >= t1) break;
  }
  if (t < t1) pose = pose * arc(current.speed, current.yaw_rate, t1 - t);
  return pose;
}

size_t searchWindowFrames(int cameras_per_frame_set, size_t rig_cameras) {
  const int per = cameras_per_frame_set;
  if (per <= 0 || static_cast<size_t>(per) >= rig_cameras) return 0;
  return (rig_cameras + static_cast<size_t>(per) - 1) / static_cast<size_t>(per) - 1;
}

void SearchWindow::advance(const std::optional<geometry::Pose2>& motion) {
  if (!motion) {
    frames_.clear();
    return;
  }
  const geometry::Pose2 now_from_before = motion->inverse();
  for (auto& f : frames_) f.now_from_then = now_from_before * f.now_from_then;
}

void SearchWindow::add(const std::vector<LandmarkObservation>& observations) {
  if (max_frames_ == 0 || observations.empty()) return;
  frames_.push_back({geometry::Pose2(), observations});
  while (frames_.size() > max_frames_) frames_.pop_front();
}

SearchWindow::Combined SearchWindow::combine(
    const geometry::Rig& rig, const std::vector<LandmarkObservation>& current) const {
  Combined out;
  out.rig = rig;
  out.observations = current;
  out.current = current.size();
  const size_t n = rig.cameras.size();
  for (const auto& f : frames_) {
    const size_t first = out.rig.cameras.size();
    const geometry::Rigid3 now_from_then = f.now_from_then.toRigid3();
    for (const auto& camera : rig.cameras) {
      geometry::RigCamera moved = camera;
      moved.vehicle_from_camera = now_from_then * camera.vehicle_from_camera;
      out.rig.cameras.push_back(std::move(moved));
    }
    for (LandmarkObservation o : f.observations) {
      if (o.camera < 0 || static_cast<size_t>(o.camera) >= n) continue;
      o.camera = static_cast<int>(first + static_cast<size_t>(o.camera));
      o.tag = -1;  // not an association of this frame set
      out.observations.push_back(std::move(o));
    }
  }
  return out;
}

}  // namespace parkloc::localize
