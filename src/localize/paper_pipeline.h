#pragma once
// The paper's pipeline (OCR-RTPS section 3), kept apart from parkloc's: every camera spotted
// on the full frame every frame set, parking numbers only, the AFM before exact matching,
// then the centre of each text's box through the camera's ground homography
// (paper_projection.h), MCRP / MCAP averaging, and no filter: the pose is the last fix, held
// until the next one.
//
// The paper estimates no heading, yet needs one to turn vehicle-frame offsets into map
// offsets; PaperPipelineOptions::heading says where it comes from.
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "geometry/ground_projection.h"
#include "geometry/pose.h"
#include "geometry/rig.h"
#include "localize/frame_types.h"
#include "localize/landmark_observation.h"
#include "localize/motion_prediction.h"
#include "localize/paper_modules.h"
#include "map/hd_map.h"

namespace parkloc::localize {

enum class PaperHeadingSource {
  // The reading direction of the text (two polygon edges through the same ground
  // homography) against the landmark's map heading: ground-truth free, one text suffices.
  kTextDirection,
  // Direction of travel between successive position fixes (ground-truth free); before
  // the first two fixes, and when standing still, the last heading is kept (initially 0,
  // or PipelineOptions::initial_pose when given).
  kMotionDirection,
  // Integrated wheel-odometry yaw rate (needs odometry; not in the paper).
  kOdometry,
};

struct PaperPipelineOptions {
  // Where the heading comes from.
  PaperHeadingSource heading = PaperHeadingSource::kTextDirection;
  // The text centre: true = mean of the four polygon corners, false = centre of the
  // axis-aligned bounding box (the paper's "box").
  bool centre_from_polygon = true;
  // kMotionDirection: the heading is taken from the travel between fixes once the vehicle
  // has moved this far (metres); over a shorter travel the fixes' noise (decimetres) would
  // swing it.
  double heading_min_travel_m = 0.5;
};

class PaperPipeline {
 public:
  // The rig and map must outlive the pipeline.
  PaperPipeline(const geometry::Rig& rig, const map::HdMap& map,
                const PaperPipelineOptions& options, const PaperModuleOptions& modules);

  void reset(const std::optional<geometry::Pose2>& initial_pose);

  // kOdometry: integrates the frame set's odometry yaw rate up to the frame set.
  void integrateOdometryYaw(const FrameMotion& motion);

  // The position from the accepted texts, the pose into the result.
  void measure(const std::vector<LandmarkObservation>& accepted, FrameResult& result);

 private:
  const geometry::Rig& rig_;
  const map::HdMap& map_;
  PaperPipelineOptions options_;
  PaperModuleOptions modules_;
  std::vector<geometry::GroundHomography> homographies_;  // per rig camera
  bool has_pose_ = false;
  geometry::Pose2 pose_;
  double yaw_ = 0.0;
  // kMotionDirection: the position the travel is measured from.
  Eigen::Vector2d motion_anchor_ = Eigen::Vector2d::Zero();
};

}  // namespace parkloc::localize
