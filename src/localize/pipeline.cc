#include "localize/pipeline.h"

namespace parkloc::localize {

PipelineOptions PipelineOptions::paper() {
  PipelineOptions o;
  o.paper_mode = true;
  o.use_odometry = false;
  o.map_guided = false;
  o.full_frame_interval = 1;
  o.use_pillar_text = false;
  return o;
}

std::string toString(TrackingStatus status) {
  switch (status) {
    case TrackingStatus::kNotInitialised:
      return "not_initialised";
    case TrackingStatus::kOk:
      return "ok";
    case TrackingStatus::kDeadReckoning:
      return "dead_reckoning";
    case TrackingStatus::kLost:
      return "lost";
  }
  return "unknown";
}

std::string toString(AssociationVerdict verdict) {
  switch (verdict) {
    case AssociationVerdict::kAccepted:
      return "accepted";
    case AssociationVerdict::kWrongClass:
      return "wrong_class";
    case AssociationVerdict::kLowScore:
      return "low_score";
    case AssociationVerdict::kNotInMap:
      return "not_in_map";
    case AssociationVerdict::kAnomaly:
      return "anomaly";
    case AssociationVerdict::kGated:
      return "gated";
    case AssociationVerdict::kFlipped:
      return "flipped";
    case AssociationVerdict::kSolverOutlier:
      return "solver_outlier";
    case AssociationVerdict::kNoGeometry:
      return "no_geometry";
  }
  return "unknown";
}

struct Pipeline::Impl {
  geometry::Rig rig;
  map::HdMap map;
  PipelineOptions options;
  ocr::TextSpotter* spotter = nullptr;
};

Pipeline::Pipeline(geometry::Rig rig, map::HdMap map, PipelineOptions options,
                   ocr::TextSpotter* spotter)
    : impl_(std::make_unique<Impl>(Impl{std::move(rig), std::move(map), options, spotter})) {}
Pipeline::~Pipeline() = default;
Pipeline::Pipeline(Pipeline&&) noexcept = default;
Pipeline& Pipeline::operator=(Pipeline&&) noexcept = default;

FrameResult Pipeline::process(const FrameInput& frame) {
  FrameResult result;
  result.timestamp = frame.timestamp;
  result.warnings.push_back("pipeline not implemented yet");
  return result;
}

void Pipeline::reset() {}
const PipelineOptions& Pipeline::options() const { return impl_->options; }
const geometry::Rig& Pipeline::rig() const { return impl_->rig; }
const map::HdMap& Pipeline::map() const { return impl_->map; }

}  // namespace parkloc::localize
