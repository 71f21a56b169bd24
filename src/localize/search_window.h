#pragma once
// Searching for the vehicle one camera at a time (before the first fix, or when lost): a
// single camera often sees one text, and one small text rarely fixes a pose. The window
// keeps the texts matched in the last few frame sets, carries them into the current vehicle
// frame by wheel odometry, and hands them to the solver as if extra cameras had seen them
// now: the vehicle is searched for all around, at the cost of one camera per frame set.
#include <cstddef>
#include <deque>
#include <optional>
#include <vector>

#include "common/odometry_sample.h"
#include "geometry/pose.h"
#include "geometry/rig.h"
#include "localize/landmark_observation.h"

namespace parkloc::localize {

// The vehicle's motion from t0 to t1 (the pose at t1 in the vehicle frame at t0), from
// wheel odometry held piecewise constant: `held` applies from t0 until the first of
// `samples` (ascending, finite), each sample from its timestamp on. nullopt without
// odometry (no `held` sample), or when t1 < t0.
std::optional<geometry::Pose2> integrateOdometry(const std::optional<OdometrySample>& held,
                                                 const std::vector<OdometrySample>& samples,
                                                 double t0, double t1);

// The frame sets a search window spans when `cameras_per_frame_set` of the rig's cameras are
// spotted per frame set in turn: one turn of the others (0 when every camera is spotted every
// frame set, or when cameras_per_frame_set <= 0, which means all of them).
size_t searchWindowFrames(int cameras_per_frame_set, size_t rig_cameras);

class SearchWindow {
 public:
  explicit SearchWindow(size_t max_frames = 3) : max_frames_(max_frames) {}

  void clear() { frames_.clear(); }
  bool empty() const { return frames_.empty(); }
  size_t frames() const { return frames_.size(); }

  // The vehicle moved by `motion` since the last frame set (see integrateOdometry); nullopt
  // when the motion is unknown: the stored texts can no longer be placed and are dropped.
  void advance(const std::optional<geometry::Pose2>& motion);

  // Stores this frame set's observations (camera indices into `rig`); the oldest frame
  // set beyond max_frames is dropped.
  void add(const std::vector<LandmarkObservation>& observations);

  // The current observations followed by the stored ones, and a rig that extends `rig`
  // with one displaced copy of each camera per stored frame set (observation camera
  // indices point into it).
  struct Combined {
    geometry::Rig rig;
    std::vector<LandmarkObservation> observations;
    size_t current = 0;  // the first `current` observations are this frame set's
  };
  Combined combine(const geometry::Rig& rig, const std::vector<LandmarkObservation>& current) const;

 private:
  struct Frame {
    geometry::Pose2 now_from_then;  // the vehicle then, in the vehicle frame now
    std::vector<LandmarkObservation> observations;
  };
  size_t max_frames_;
  std::deque<Frame> frames_;
};

}  // namespace parkloc::localize
