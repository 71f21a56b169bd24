#include "localize/pipeline.h"

#include <algorithm>
#include <chrono>
#include <iterator>
#include <map>

#include <fmt/format.h>
#include <opencv2/imgproc.hpp>

#include "localize/capture_time.h"
#include "localize/floor_heights.h"
#include "localize/late_fusion.h"
#include "localize/search_window.h"
#include "localize/serialized_spotter.h"
#include "localize/spotting.h"
#include "localize/stage_clock.h"

namespace parkloc::localize {

PipelineOptions PipelineOptions::paper(PipelineOptions o) {
  o.paper_mode = true;
  o.motion.use_odometry = false;
  o.reading.map_guided = false;
  o.reading.full_frame_interval = 1;
  o.association.use_pillar_text = false;
  o.realtime.background_search = false;  // every frame set waits for its full frames
  return o;
}

struct Pipeline::Impl {
  geometry::Rig nominal_rig;  // as calibrated
  geometry::Rig rig;          // this frame set's: each camera moved to its capture time
  map::HdMap map;
  PipelineOptions options;
  ocr::TextSpotter* spotter = nullptr;
  FloorHeights floors;

  // Work off the critical path (search_worker.h): the full frames on the search worker
  // (options.realtime.background_search), the reads at predicted places on the read worker
  // (background_reads), which takes full frames too while there is no track to read for;
  // each lane remembers its job's frame set as it was when its images were taken: the
  // filter's prediction, the rig and the travel, for the late fusion.
  struct PendingJob {
    long frame = -1;
    PoseEkf ekf;  // predicted to the frame set, before its measurement
    geometry::Rig rig;
    geometry::Pose2 travelled;
    bool full_frames = false;  // its texts come from full frames (CameraResult::full_frame)
  };
  struct Lane {
    std::unique_ptr<SearchWorker> worker;
    std::optional<PendingJob> pending;
    // The job's copies of the images (the caller may reuse its buffers), one per camera,
    // kept from job to job: a free worker is done with them, and copying into buffers of the
    // right size spares the critical path a fresh allocation (and its page faults) for every
    // image handed over.
    std::map<size_t, cv::Mat> copies;
    cv::Mat copyOf(size_t camera, const cv::Mat& image) {
      cv::Mat& copy = copies[camera];
      image.copyTo(copy);
      return copy;
    }
  };
  std::unique_ptr<SerializedSpotter> shared_spotter;  // without a search spotter of its own
  Lane search_lane;
  Lane read_lane;
  long frame_index = -1;
  // The vehicle's path so far in the frame of the first frame set (odometry, through the
  // filter's prediction when it runs): the motion between two frame sets' poses on it.
  geometry::Pose2 travelled;

  // The stages (each holds its own state) and the track they share.
  PoseEkf ekf;
  MotionPrediction motion;
  ReadPlanner reading;
  LevelEstimate level;
  Associator associator;
  ParklocMeasurement measurement;
  TrackLifecycle lifecycle;
  PaperPipeline paper;

  Impl(geometry::Rig r, map::HdMap m, const PipelineOptions& o, ocr::TextSpotter* s,
       WorkerSpotters workers)
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
                   o.paper_mode, o.solver.map_size_sigma),
        measurement(rig, o.solver, o.measurement, o.tracking),
        lifecycle(o.tracking,
                  searchWindowFrames(o.reading.search_cameras_per_frame, rig.cameras.size())),
        paper(rig, map, o.paper_pipeline, o.paper_modules) {
    if (o.realtime.background_search && !o.paper_mode && (s || workers.search)) {
      if (!workers.search) {
        shared_spotter = std::make_unique<SerializedSpotter>(s);
        spotter = workers.search = shared_spotter.get();
      }
      search_lane.worker = std::make_unique<SearchWorker>(workers.search, o.realtime.worker_nice);
    }
    // The reads need a spotter of their own: sharing the critical path's would make the
    // frame set wait for a read in progress.
    if (o.realtime.background_reads && !o.paper_mode && workers.reads)
      read_lane.worker = std::make_unique<SearchWorker>(workers.reads, o.realtime.worker_nice);
    if (o.realtime.warm_up && !o.paper_mode) warmUp();
    reset();
  }

  // A grey frame with large dark text across it: the detector finds boxes, so the recognizer
  // and the classifier run their first inference too.
  static cv::Mat warmUpImage(int width, int height) {
    cv::Mat image(height, width, CV_8UC3, cv::Scalar::all(150));
    const double scale = std::max(1.0, height / 160.0);
    for (int row = 1; row <= 3; ++row)
      cv::putText(image, "A123 B456", cv::Point(width / 10, row * height / 4),
                  cv::FONT_HERSHEY_SIMPLEX, scale, cv::Scalar::all(20),
                  std::max(2, static_cast<int>(scale * 2)));
    return image;
  }

  // Every spotter spots a full frame of each camera as the search would, the workers on their
  // threads while the critical path's spotter does the same here.
  void warmUp() {
    ReadPlan plan;
    plan.choice.full_frame.assign(nominal_rig.cameras.size(), true);
    plan.choice.searching = true;
    plan.regions.resize(nominal_rig.cameras.size());
    SearchJob job;
    for (size_t c = 0; c < nominal_rig.cameras.size(); ++c) {
      const auto& model = nominal_rig.cameras[c].model;
      if (model.width <= 0 || model.height <= 0) continue;
      job.cameras.push_back(c);
      job.images.push_back(warmUpImage(model.width, model.height));
      job.requests.push_back(reading.request(c, plan, geometry::Pose2()));
    }
    for (Lane* lane : {&search_lane, &read_lane})
      if (lane->worker) lane->worker->submit(job);
    if (spotter && !shared_spotter)
      for (size_t k = 0; k < job.cameras.size(); ++k) {
        try {
          spotter->spot(job.images[k], job.requests[k]);
        } catch (const std::exception&) {
          // A spotter that fails on the made-up frame will say so on the first real one.
        }
      }
    for (Lane* lane : {&search_lane, &read_lane})
      if (lane->worker) lane->worker->wait();
  }

  void reset() {
    for (Lane* lane : {&search_lane, &read_lane}) {
      if (lane->worker) lane->worker->wait();
      lane->pending.reset();
    }
    frame_index = -1;
    travelled = geometry::Pose2();
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
    ++frame_index;
    const Stopwatch motion_time;
    const bool predicted_before = ekf.initialised();
    const geometry::Pose2 pose_before = ekf.pose();
    const FrameMotion moved = motion.advance(frame, ekf, result.warnings);
    if (options.motion.use_capture_times)
      rig = rigAtFrameTime(nominal_rig, frame, motion.heldOdometry());
    // The path: the filter's prediction (odometry with its bias and scale estimates), else
    // the odometry alone.
    if (predicted_before && ekf.initialised())
      travelled = travelled * (pose_before.inverse() * ekf.pose());
    else if (const auto step = moved.sincePreviousFrame())
      travelled = travelled * *step;
    level.predict(frame.timestamp);
    if (options.paper_mode) paper.integrateOdometryYaw(moved);
    if (!lifecycle.searchWindow().empty())
      lifecycle.searchWindow().advance(moved.sincePreviousFrame());
    result.timings.filter_ms += motion_time.elapsedMs();

    // The workers' texts, when their turn has come (late_fusion.h).
    const auto waits_until =
        std::chrono::steady_clock::now() +
        std::chrono::microseconds(static_cast<long>(1e3 * options.realtime.first_fix_wait_ms));
    collectLate(search_lane, result, result.background, waits_until);
    collectLate(read_lane, result, result.deferred_reads, waits_until);
    const bool tracking = !options.paper_mode && isTracking(ekf, options.tracking);

    // 2. Read planning: map-guided regions while tracking, the full frame now and then.
    const Stopwatch planning_time;
    const std::vector<Lane*> full_frame_lanes = freeFullFrameLanes(tracking);
    // Reads due while the read worker is busy wait for it: the critical path only fits.
    const bool reads_wait = tracking && read_lane.worker && read_lane.worker->busy();
    ReadPlan plan = reading.plan(
        tracking, ekf, level,
        search_lane.worker ? std::optional<int>(static_cast<int>(full_frame_lanes.size()))
                           : std::nullopt,
        tracking && lifecycle.tentative(), reads_wait);
    if (search_lane.worker) handOverFullFrames(frame, full_frame_lanes, plan, result);
    if (read_lane.worker && tracking) handOverReads(frame, plan, result);
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

  // Camera c's image of the frame set, when it can be spotted (present, decoded, of its
  // calibrated size, not instances handed in); null otherwise.
  const cv::Mat* spottableImage(const FrameInput& frame, size_t c) const {
    const geometry::RigCamera& camera = nominal_rig.cameras[c];
    for (const CameraInput& input : frame.cameras)
      if (input.camera == camera.name && !input.instances && !input.image.empty() &&
          input.image.cols == camera.model.width && input.image.rows == camera.model.height)
        return &input.image;
    return nullptr;
  }

  // The lanes free to take full frames now: the search worker, and the read worker while
  // there is no track to read for (searching, lost): before the first fix the critical path
  // has nothing to spot, and two workers search twice the cameras.
  std::vector<Lane*> freeFullFrameLanes(bool tracking) {
    std::vector<Lane*> lanes;
    if (!search_lane.worker) return lanes;
    if (!search_lane.worker->busy()) lanes.push_back(&search_lane);
    if (!tracking && read_lane.worker && !read_lane.worker->busy()) lanes.push_back(&read_lane);
    return lanes;
  }

  // The full frames of the plan go to the free lanes, shared out camera by camera; either
  // way the critical path spots none of them. (The schedule chose no more than the lanes can
  // take; none when no lane is free, and its turn waits.)
  void handOverFullFrames(const FrameInput& frame, const std::vector<Lane*>& lanes,
                          ReadPlan& plan, FrameResult& result) {
    std::vector<SearchJob> jobs(lanes.size());
    size_t next = 0;
    for (size_t c = 0; c < nominal_rig.cameras.size() && !lanes.empty(); ++c) {
      if (!plan.choice.full_frame[c]) continue;
      if (const cv::Mat* image = spottableImage(frame, c)) {
        const size_t k = next++ % lanes.size();
        SearchJob& job = jobs[k];
        job.cameras.push_back(c);
        job.images.push_back(lanes[k]->copyOf(c, *image));
        job.requests.push_back(reading.request(c, plan, ekf.pose()));
        result.background_cameras.push_back(nominal_rig.cameras[c].name);
      }
    }
    std::fill(plan.choice.full_frame.begin(), plan.choice.full_frame.end(), false);
    for (size_t k = 0; k < lanes.size(); ++k)
      submit(*lanes[k], frame, std::move(jobs[k]), /*full_frames=*/true);
  }

  // The plan's reads go to the read worker (free: the plan has none while it is busy); the
  // critical path keeps the fits.
  void handOverReads(const FrameInput& frame, ReadPlan& plan, FrameResult& result) {
    if (read_lane.worker->busy()) return;
    ReadPlan reads = plan;
    SearchJob job;
    for (size_t c = 0; c < nominal_rig.cameras.size(); ++c) {
      reads.regions[c].clear();
      if (plan.choice.full_frame[c]) continue;
      auto& regions = plan.regions[c];
      const auto fits = std::stable_partition(
          regions.begin(), regions.end(), [](const RegionCandidate& r) { return !r.roi.read; });
      if (fits == regions.end()) continue;
      const cv::Mat* image = spottableImage(frame, c);
      if (!image) continue;
      std::move(fits, regions.end(), std::back_inserter(reads.regions[c]));
      regions.erase(fits, regions.end());
      job.cameras.push_back(c);
      job.images.push_back(read_lane.copyOf(c, *image));
      job.requests.push_back(reading.request(c, reads, ekf.pose()));
      result.deferred_read_cameras.push_back(nominal_rig.cameras[c].name);
    }
    submit(read_lane, frame, std::move(job), /*full_frames=*/false);
  }

  void submit(Lane& lane, const FrameInput& frame, SearchJob job, bool full_frames) {
    if (job.cameras.empty()) return;
    job.frame = frame_index;
    job.timestamp = frame.timestamp;
    lane.pending = PendingJob{frame_index, ekf, rig, travelled, full_frames};
    lane.worker->submit(std::move(job));
  }

  // A worker's result: waited for at its fixed turn (wait_for_worker), else taken when done;
  // before the first fix a full frame is waited for until `waits_until`
  // (RealtimeOptions::first_fix_wait_ms).
  void collectLate(Lane& lane, FrameResult& result, std::optional<BackgroundFusion>& fused,
                   std::chrono::steady_clock::time_point waits_until) {
    if (!lane.worker || !lane.pending) return;
    std::optional<SearchResult> done;
    const RealtimeOptions& o = options.realtime;
    if (o.wait_for_worker) {
      if (frame_index - lane.pending->frame < std::max(1, o.fuse_after_frames)) return;
      done = lane.worker->wait();
    } else {
      done = lane.worker->poll();
      if (!done && lane.pending->full_frames && !ekf.initialised() && o.first_fix_wait_ms > 0)
        done = lane.worker->waitUntil(waits_until);
    }
    if (!done) return;
    fuseLate(*lane.pending, *done, result, fused);
    lane.pending.reset();
  }

  // The worker's texts as they would have been fused at their capture time: associated
  // against the filter's prediction then, each camera where it stood then, and the fix
  // carried to the present by the motion since (late_fusion.h).
  void fuseLate(const PendingJob& then, const SearchResult& done, FrameResult& result,
                std::optional<BackgroundFusion>& fused_out) {
    const bool full_frames = then.full_frames;
    const geometry::Pose2 motion_since = then.travelled.inverse() * travelled;
    FrameResult late;
    late.timestamp = result.timestamp;
    for (const auto& camera : nominal_rig.cameras) {
      CameraResult c;
      c.camera = camera.name;
      c.full_frame = false;
      late.cameras.push_back(std::move(c));
    }
    for (size_t k = 0; k < done.cameras.size(); ++k) {
      CameraResult& c = late.cameras[done.cameras[k]];
      c.full_frame = full_frames;
      if (!done.errors[k].empty()) {
        c.image_ok = false;
        result.warnings.push_back("camera '" + c.camera + "': " + done.errors[k]);
      }
      c.instances = done.instances[k];
    }
    const bool tracking_then = isTracking(then.ekf, options.tracking);
    if (tracking_then != isTracking(ekf, options.tracking)) {
      // The track started or was lost meanwhile: the prediction the texts would have been
      // gated against is not the filter's any more.
      result.warnings.push_back(fmt::format(
          "{} of an earlier frame set dropped: the track changed state while they were spotted",
          full_frames ? "full-frame texts" : "reads"));
      return;
    }
    const geometry::Rig current_rig = rig;
    rig = then.rig;  // the stages read the rig they were built with
    const Stopwatch association_time;
    const std::vector<bool> supplied(nominal_rig.cameras.size(), false);
    AssociatedObservations seen = associator.associate(late.cameras, supplied, tracking_then,
                                                       level, then.ekf, late.associations);
    level.update(late.cameras, late.associations, late.warnings);
    reading.noteOutcomes(late);
    seen.accepted = selectForModules(std::move(seen.accepted), options.paper_modules);
    seen.gated = selectForModules(std::move(seen.gated), options.paper_modules);
    result.timings.association_ms += association_time.elapsedMs();

    const Stopwatch solve_time;
    FrameFixes fixes;
    if (tracking_then) {
      fixes = measurement.whileTracking(seen.accepted, seen.gated, then.ekf,
                                        lifecycle.tentative(), late);
      lifecycle.searchWindow().clear();
    } else {
      // The search window holds its texts in the vehicle frame now: back to then and forth.
      lifecycle.searchWindow().advance(motion_since.inverse());
      fixes = measurement.whileSearching(seen.accepted, lifecycle.searchWindow(), late);
      lifecycle.searchWindow().advance(motion_since);
    }
    rig = current_rig;
    result.timings.solver_ms += solve_time.elapsedMs();

    const Stopwatch filter_time;
    lifecycle.apply(carryFixes(fixes, motion_since, ekf.odometrySensitivitySince(then.ekf)),
                    tracking_then, ekf, motion, late);
    result.timings.filter_ms += filter_time.elapsedMs();
    if (late.status == TrackingStatus::kOk) result.status = TrackingStatus::kOk;
    result.reinitialised = result.reinitialised || late.reinitialised;
    for (auto& f : late.fused_fixes) result.fused_fixes.push_back(std::move(f));
    for (auto& w : late.warnings) result.warnings.push_back(std::move(w));

    BackgroundFusion fused;
    fused.capture_timestamp = done.timestamp;
    fused.cameras = std::move(late.cameras);
    fused.associations = std::move(late.associations);
    fused.measurement = late.measurement;
    fused.worker_ms = done.wall_ms;
    fused.worker_cpu_ms = done.cpu_ms;
    fused_out = std::move(fused);
  }

  // The SE(2) solve, then the track's lifecycle.
  void measureParkloc(const AssociatedObservations& seen, FrameResult& result) {
    const Stopwatch solve_time;
    const bool was_tracking = isTracking(ekf, options.tracking);
    const FrameFixes fixes =
        was_tracking ? measurement.whileTracking(seen.accepted, seen.gated, ekf,
                                                   lifecycle.tentative(), result)
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
                   ocr::TextSpotter* spotter, WorkerSpotters workers)
    : impl_(std::make_unique<Impl>(std::move(rig), std::move(map), options, spotter, workers)) {}
Pipeline::~Pipeline() = default;
Pipeline::Pipeline(Pipeline&&) noexcept = default;
Pipeline& Pipeline::operator=(Pipeline&&) noexcept = default;

FrameResult Pipeline::process(const FrameInput& frame) { return impl_->process(frame); }
void Pipeline::reset() { impl_->reset(); }
const PipelineOptions& Pipeline::options() const { return impl_->options; }
const geometry::Rig& Pipeline::rig() const { return impl_->nominal_rig; }
const map::HdMap& Pipeline::map() const { return impl_->map; }

}  // namespace parkloc::localize
