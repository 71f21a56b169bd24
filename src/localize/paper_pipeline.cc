#include "localize/paper_pipeline.h"

#include <algorithm>
#include <cmath>

#include "localize/paper_projection.h"
#include "localize/stage_clock.h"

namespace parkloc::localize {
namespace {

// The covariance the paper's pose is reported with: nominal, since the paper states no
// uncertainty. It reports about 5 cm with all modules; here 10 cm for one landmark, shrinking
// as the square root of the landmarks averaged (MCAP), 50 cm while the pose is held without a
// fix, and a loose 5 degrees on the heading it does not estimate.
Eigen::Matrix3d nominalCovariance(const std::optional<PaperFix>& fix) {
  const double sigma = fix ? 0.1 / std::sqrt(std::max(1, fix->landmarks)) : 0.5;
  const double yaw_sigma = 5.0 * M_PI / 180.0;
  return Eigen::Vector3d(sigma * sigma, sigma * sigma, yaw_sigma * yaw_sigma).asDiagonal();
}

}  // namespace

PaperPipeline::PaperPipeline(const geometry::Rig& rig, const map::HdMap& map,
                             const PaperPipelineOptions& options, const PaperModuleOptions& modules)
    : rig_(rig), map_(map), options_(options), modules_(modules) {
  for (const auto& camera : rig.cameras)
    homographies_.push_back(geometry::GroundHomography::fromCamera(camera));
}

void PaperPipeline::reset(const std::optional<geometry::Pose2>& initial_pose) {
  has_pose_ = false;
  yaw_ = 0.0;
  if (initial_pose) {
    pose_ = *initial_pose;
    yaw_ = initial_pose->yaw;
    has_pose_ = true;
    motion_anchor_ = pose_.translation();
  }
}

void PaperPipeline::integrateOdometryYaw(const FrameMotion& motion) {
  if (options_.heading != PaperHeadingSource::kOdometry) return;
  // The held sample's yaw rate up to each new sample, then up to the frame set.
  std::optional<OdometrySample> held = motion.held_before;
  for (const auto& s : motion.accepted) {
    if (held) yaw_ += held->yaw_rate * (s.timestamp - held->timestamp);
    held = s;
  }
  if (held && motion.time_ok && motion.frame_time > held->timestamp)
    yaw_ += held->yaw_rate * (motion.frame_time - held->timestamp);
}

void PaperPipeline::measure(const std::vector<LandmarkObservation>& accepted, FrameResult& result) {
  const Stopwatch solve_time;
  std::vector<PaperObservation> observations;
  for (const auto& o : accepted) {
    const auto& camera = rig_.cameras[o.camera];
    auto p =
        paperObserve(homographies_[o.camera], camera.model, o.pixels, options_.centre_from_polygon);
    if (!p) {
      result.associations[o.tag].verdict = AssociationVerdict::kNoGeometry;
      continue;
    }
    const map::Landmark* landmark = map_.findById(o.landmark_id);
    p->camera = o.camera;
    p->landmark_id = o.landmark_id;
    p->map_position = landmark->position.head<2>();
    p->map_heading = landmark->heading;
    observations.push_back(*p);
  }
  // kOdometry takes its first heading from the texts, then integrates the yaw rate.
  if (options_.heading == PaperHeadingSource::kTextDirection ||
      (options_.heading == PaperHeadingSource::kOdometry && !has_pose_)) {
    if (const auto yaw = headingFromTextDirections(observations)) yaw_ = *yaw;
  }
  const auto fix = paperFuse(observations, yaw_, modules_.mcrp, modules_.mcap);
  if (fix) {
    if (options_.heading == PaperHeadingSource::kMotionDirection) {
      const Eigen::Vector2d moved = fix->position - motion_anchor_;
      if (has_pose_ && moved.norm() > options_.heading_min_travel_m) {
        yaw_ = std::atan2(moved.y(), moved.x());
        motion_anchor_ = fix->position;
      } else if (!has_pose_) {
        motion_anchor_ = fix->position;
      }
    }
    pose_ = geometry::Pose2(fix->position.x(), fix->position.y(), yaw_);
    has_pose_ = true;
    result.status = TrackingStatus::kOk;
    result.measurement = pose_;
    result.solver_converged = true;
  }
  result.timings.solver_ms += solve_time.elapsedMs();
  if (!has_pose_) return;
  result.has_pose = true;
  result.pose = geometry::Pose2(pose_.x, pose_.y, yaw_);
  result.covariance = nominalCovariance(fix);
  if (fix) result.measurement_covariance = result.covariance;
  if (result.status != TrackingStatus::kOk) result.status = TrackingStatus::kDeadReckoning;
}

}  // namespace parkloc::localize
