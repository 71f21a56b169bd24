#include "localize/pipeline.h"

#include "localize/capture_time.h"
#include "localize/floor_heights.h"
#include "localize/search_window.h"
#include "localize/spotting.h"
#include "localize/stage_clock.h"

namespace parkloc::localize {

PipelineOptions PipelineOptions::paper(PipelineOptions o) {
  o.paper_mode = true;
  o.motion.use_odometry = false;
  o.reading.map_guided = false;
  o.reading.full_frame_interval = 1;
  o.association.use_pillar_text = false;
  return o;
}

struct Pipeline::Impl {
  geometry::Rig nominal_rig;  // as calibrated
  geometry::Rig rig;          // this frame set's: each camera moved to its capture time
  map::HdMap map;
  PipelineOptions options;
  ocr::TextSpotter* spotter = nullptr;
  FloorHeights floors;

  // The stages (each holds its own state) and the track they share.
  PoseEkf ekf;
  MotionPrediction motion;
  ReadPlanner reading;
  LevelEstimate level;
  Associator associator;
  ParklocMeasurement measurement;
  TrackLifecycle lifecycle;
  PaperPipeline paper;

  Impl(geometry::Rig r, map::HdMap m, const PipelineOptions& o, ocr::TextSpotter* s)
      : nominal_rig(r),
        rig(std::move(r)),
        map(std::move(m)),
        options(o),
        spotter(s),
        floors(map),
        ekf(o.ekf),
        motion(o.motion, o.paper_mode && o.paper_pipeline.heading == PaperHeadingSource::kOdometry),
        reading(rig, nominal_rig, map, floors, o.reading, o.reading.map_guided && !o.paper_mode),
        level(map, o.levels, o.level),
        associator(rig, map, floors, o.association, o.paper_modules, o.measurement.polygon_model,
                   o.paper_mode),
        measurement(rig, o.solver, o.measurement, o.tracking),
        lifecycle(o.tracking,
                  searchWindowFrames(o.reading.search_cameras_per_frame, rig.cameras.size())),
        paper(rig, map, o.paper_pipeline, o.paper_modules) {
    reset();
  }

  void reset() {
    ekf.reset();
    motion.reset();
    reading.reset();
    level.reset();
    associator.reset();
    lifecycle.reset();
    paper.reset(options.initial_pose);
    if (options.initial_pose && !options.paper_mode) lifecycle.startAt(*options.initial_pose, ekf);
  }

  FrameResult process(const FrameInput& frame) {
    const Stopwatch total_time;
    const double cpu_start = processCpuMs();
    FrameResult result;
    result.timestamp = frame.timestamp;

    // 1. Motion prediction: odometry up to this frame set, the filter predicted to it; the
    //    search window's texts follow the vehicle.
    const Stopwatch motion_time;
    const FrameMotion moved = motion.advance(frame, ekf, result.warnings);
    if (options.motion.use_capture_times)
      rig = rigAtFrameTime(nominal_rig, frame, motion.heldOdometry());
    level.predict(frame.timestamp);
    if (options.paper_mode) paper.integrateOdometryYaw(moved);
    if (!lifecycle.searchWindow().empty())
      lifecycle.searchWindow().advance(moved.sincePreviousFrame());
    result.timings.filter_ms += motion_time.elapsedMs();
    const bool tracking = !options.paper_mode && isTracking(ekf, options.tracking);

    // 2. Read planning: map-guided regions while tracking, the full frame now and then.
    const Stopwatch planning_time;
    ReadPlan plan = reading.plan(tracking, ekf, level);
    result.timings.roi_ms += planning_time.elapsedMs();

    // 3. Spotting, camera by camera in rig order.
    const std::vector<bool> supplied = spotCameras(
        frame, nominal_rig, spotter, plan.choice.full_frame,
        [&](size_t c) { return reading.request(c, plan, ekf.pose()); }, result);

    // 4. Association: class, score, AFM (paper 3.3), exact matching (3.3) on the level
    //    driven on, pose gate; then what the readings say of the level; MCRP / MCAP choose
    //    what the measurement fuses (3.5).
    const Stopwatch association_time;
    AssociatedObservations seen = associator.associate(result.cameras, supplied, tracking, level,
                                                       ekf, result.associations);
    level.update(result.cameras, result.associations, result.warnings);
    result.level = level.belief().level;
    result.level_probability = level.belief().probability;
    result.level_decided = level.belief().decided;
    reading.noteOutcomes(result);
    seen.accepted = selectForModules(std::move(seen.accepted), options.paper_modules);
    seen.gated = selectForModules(std::move(seen.gated), options.paper_modules);
    result.timings.association_ms += association_time.elapsedMs();

    // 5. Measurement and filter.
    if (options.paper_mode)
      paper.measure(seen.accepted, result);
    else
      measureParkloc(seen, result);

    result.timings.total_ms = total_time.elapsedMs();
    result.timings.cpu_ms = processCpuMs() - cpu_start;
    return result;
  }

  // The SE(2) solve, then the track's lifecycle.
  void measureParkloc(const AssociatedObservations& seen, FrameResult& result) {
    const Stopwatch solve_time;
    const bool was_tracking = isTracking(ekf, options.tracking);
    const FrameFixes fixes =
        was_tracking ? measurement.whileTracking(seen.accepted, seen.gated, ekf, result)
                     : measurement.whileSearching(seen.accepted, lifecycle.searchWindow(), result);
    result.timings.solver_ms += solve_time.elapsedMs();
    if (was_tracking) lifecycle.searchWindow().clear();

    const Stopwatch filter_time;
    lifecycle.apply(fixes, was_tracking, ekf, motion, result);
    result.timings.filter_ms += filter_time.elapsedMs();
    lifecycle.report(ekf, result);
  }
};

Pipeline::Pipeline(geometry::Rig rig, map::HdMap map, PipelineOptions options,
                   ocr::TextSpotter* spotter)
    : impl_(std::make_unique<Impl>(std::move(rig), std::move(map), options, spotter)) {}
Pipeline::~Pipeline() = default;
Pipeline::Pipeline(Pipeline&&) noexcept = default;
Pipeline& Pipeline::operator=(Pipeline&&) noexcept = default;

FrameResult Pipeline::process(const FrameInput& frame) { return impl_->process(frame); }
void Pipeline::reset() { impl_->reset(); }
const PipelineOptions& Pipeline::options() const { return impl_->options; }
const geometry::Rig& Pipeline::rig() const { return impl_->nominal_rig; }
const map::HdMap& Pipeline::map() const { return impl_->map; }

}  // namespace parkloc::localize
