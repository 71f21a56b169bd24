#include "run/sequence_runner.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <thread>
#include <fstream>
#include <opencv2/videoio.hpp>

#include "common/error.h"
#include "io/tum.h"
#include "run/frame_log.h"
#include "run/oracle_source.h"
#include "run/percentile.h"
#include "run/run_visualization.h"

namespace parkloc::run {
namespace fs = std::filesystem;

std::optional<geometry::Pose2> truthAt(const std::vector<io::StampedPose>& truth, double t) {
  if (truth.empty() || t < truth.front().timestamp - 1e-6 || t > truth.back().timestamp + 1e-6)
    return std::nullopt;
  const auto after =
      std::lower_bound(truth.begin(), truth.end(), t,
                       [](const io::StampedPose& p, double v) { return p.timestamp < v; });
  if (after == truth.end()) return geometry::Pose2::fromRigid3(truth.back().pose);
  if (after == truth.begin() || std::abs(after->timestamp - t) < 1e-9)
    return geometry::Pose2::fromRigid3(after->pose);
  const auto before = after - 1;
  const double w = (t - before->timestamp) / (after->timestamp - before->timestamp);
  const auto a = geometry::Pose2::fromRigid3(before->pose);
  const auto b = geometry::Pose2::fromRigid3(after->pose);
  return geometry::Pose2(a.x + w * (b.x - a.x), a.y + w * (b.y - a.y),
                         a.yaw + w * geometry::wrapAngle(b.yaw - a.yaw));
}

std::vector<OdometrySample> odometryBetween(const std::vector<OdometrySample>& all, double after,
                                            double until) {
  std::vector<OdometrySample> out;
  auto it = std::upper_bound(all.begin(), all.end(), after,
                             [](double t, const OdometrySample& s) { return t < s.timestamp; });
  for (; it != all.end() && it->timestamp <= until; ++it) out.push_back(*it);
  return out;
}

RunSummary runSequence(const io::Sequence& sequence, ocr::TextSpotter* spotter,
                       const RunOptions& options, localize::WorkerSpotters workers) {
  if (!options.oracle && !spotter)
    throw InputError("run: no text spotter given and --oracle not set");
  RunSummary summary;
  summary.sequence_warnings = sequence.warnings();
  if (options.out_dir.empty()) throw InputError("run: --out is empty");
  std::error_code ec;
  fs::create_directories(options.out_dir, ec);
  if (ec) throw IoError(fmt::format("run: cannot create {}: {}", options.out_dir, ec.message()));
  const std::string frames_path = (fs::path(options.out_dir) / "frames.jsonl").string();
  std::ofstream frames_log(frames_path);
  if (!frames_log) throw IoError(fmt::format("run: cannot write {}", frames_path));

  checkFaultCameras(options.faults, sequence.rig());
  FaultInjector injector(options.faults, sequence.timestamps(), sequence.groundTruth(),
                         sequence.odometry());
  localize::PipelineOptions pipeline_options = options.pipeline;
  if (options.realtime) {
    pipeline_options.realtime.wait_for_worker = false;
    pipeline_options.realtime.warm_up = true;  // a vehicle starts its engines before it drives
  }
  ocr::TextSpotter* const wrapped = injector.wrapSpotter(spotter);
  localize::Pipeline pipeline(sequence.rig(),
                              options.map_noise.position_sigma_m > 0.0
                                  ? map::perturbedMap(sequence.map(), options.map_noise)
                                  : sequence.map(),
                              pipeline_options, wrapped,
                              // A spoofing spotter is shared, so the worker is spoofed too.
                              wrapped == spotter ? workers : localize::WorkerSpotters{});
  const auto& timestamps = sequence.timestamps();
  size_t count = timestamps.size();
  if (options.max_frames > 0) count = std::min(count, options.max_frames);
  if (count == 0) throw InputError(fmt::format("run: sequence {} has no frames", sequence.dir()));
  const bool need_images = !options.oracle || !options.video_path.empty();

  // Video set-up.
  cv::VideoWriter video;
  BirdsEyeView bev;
  std::vector<geometry::Pose2> truth_poses;
  for (const auto& p : sequence.groundTruth())
    truth_poses.push_back(geometry::Pose2::fromRigid3(p.pose));
  if (!options.video_path.empty()) {
    std::vector<double> intervals;
    for (size_t i = 1; i < count; ++i) intervals.push_back(timestamps[i] - timestamps[i - 1]);
    const double interval = percentile(intervals, 0.5);
    const double fps = interval > 1e-3 ? std::clamp(1.0 / interval, 1.0, 60.0) : 10.0;
    bev = BirdsEyeView::fitting(sequence.map(), truth_poses);
    const cv::Size size(2 * 640 + bev.size_px, 800);
    if (!video.open(options.video_path, cv::VideoWriter::fourcc('m', 'p', '4', 'v'), fps, size))
      throw IoError(fmt::format("run: cannot open video {} for writing", options.video_path));
  }

  std::vector<io::StampedPose> trajectory;
  std::vector<double> latencies, errors, yaw_errors;
  std::vector<geometry::Pose2> estimated, truth_so_far;
  double previous_time = -std::numeric_limits<double>::infinity();
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  Clock::time_point previous_done = start;
  for (size_t i = 0; i < count; ++i) {
    const double t = timestamps[i];
    const Clock::time_point release =
        start + std::chrono::duration_cast<Clock::duration>(
                    std::chrono::duration<double>(t - timestamps.front()));
    if (options.realtime && i > 0 && previous_done > release) {
      // The previous frame set was still running when this one came: dropped.
      ++summary.frames_dropped;
      continue;
    }
    if (injector.skip(i)) {  // kidnapped: never seen, its odometry withheld
      previous_time = t;
      ++summary.frames_skipped_by_faults;
      continue;
    }
    localize::FrameInput input;
    input.timestamp = t;
    input.odometry = odometryBetween(sequence.odometry(), previous_time, t);
    previous_time = t;
    std::vector<std::string> load_warnings;
    std::vector<cv::Mat> images;
    for (const auto& camera : sequence.rig().cameras) {
      localize::CameraInput c;
      c.camera = camera.name;
      c.capture_time = sequence.captureTime(i, camera.name);
      if (need_images) {
        std::string why;
        c.image = sequence.loadImage(i, camera.name, &why);
        if (c.image.empty() && !why.empty()) load_warnings.push_back(why);
      }
      images.push_back(c.image);
      if (options.oracle) {
        const auto labels = sequence.loadLabels(i, camera.name);
        c.instances = labels ? oracleInstances(*labels) : std::vector<ocr::TextInstance>{};
        if (!labels)
          load_warnings.push_back(
              fmt::format("camera '{}': no labels at {}", camera.name, io::timestampStem(t)));
      }
      if (!c.image.empty() || c.instances) input.cameras.push_back(std::move(c));
    }
    injector.apply(i, input, load_warnings);
    if (options.realtime) std::this_thread::sleep_until(release);
    localize::FrameResult result = pipeline.process(input);
    previous_done = Clock::now();
    const double age_ms =
        std::chrono::duration<double, std::milli>(previous_done - release).count();
    result.warnings.insert(result.warnings.begin(), load_warnings.begin(), load_warnings.end());
    for (auto& note : injector.takeSpotterNotes()) result.warnings.push_back(std::move(note));
    frames_log << frameResultToJson(result) << '\n';

    ++summary.frames;
    ++summary.status_counts[toString(result.status)];
    if (!result.warnings.empty()) ++summary.frames_with_warnings;
    latencies.push_back(result.timings.total_ms);
    if (result.has_pose && !summary.first_fix_time) {
      summary.first_fix_time = t;
      summary.first_pose_frame = i;
      summary.first_pose_output_ms = (t - timestamps.front()) * 1000.0 + age_ms;
    }
    if (options.realtime && result.has_pose) summary.pose_age_ms.push_back(age_ms);
    if (summary.first_fix_time) {
      ++summary.frames_after_first_fix;
      if (result.has_pose) ++summary.poses_after_first_fix;
    }
    const auto truth = truthAt(sequence.groundTruth(), t);
    if (truth) truth_so_far.push_back(*truth);
    if (result.has_pose) {
      ++summary.frames_with_pose;
      io::StampedPose stamped;
      stamped.timestamp = t;
      stamped.pose = result.pose.toRigid3();
      trajectory.push_back(stamped);
      estimated.push_back(result.pose);
      if (truth) {
        errors.push_back((result.pose.translation() - truth->translation()).norm());
        yaw_errors.push_back(std::abs(geometry::wrapAngle(result.pose.yaw - truth->yaw)) * 180.0 /
                             M_PI);
      }
    }
    if (video.isOpened()) {
      VisualizationInput vis;
      vis.result = &result;
      vis.images = images;
      vis.estimated_so_far = estimated;
      vis.truth_so_far = truth_so_far;
      vis.truth_now = truth;
      if (options.realtime) {
        vis.pose_age_ms = age_ms;
        vis.dropped_so_far = summary.frames_dropped;
      }
      video.write(drawRunFrame(vis, sequence.map(), bev));
    }
    if (options.progress) options.progress(i + 1, count);
  }
  io::saveTum(trajectory, (fs::path(options.out_dir) / "trajectory.tum").string());

  if (!errors.empty()) {
    summary.has_truth = true;
    double sum = 0.0, yaw_sum = 0.0;
    for (double e : errors) sum += e;
    for (double e : yaw_errors) yaw_sum += e;
    summary.mean_position_error_m = sum / errors.size();
    summary.p95_position_error_m = percentile(errors, 0.95);
    summary.max_position_error_m = *std::max_element(errors.begin(), errors.end());
    summary.mean_yaw_error_deg = yaw_sum / yaw_errors.size();
    summary.frames_over_half_metre = static_cast<size_t>(
        std::count_if(errors.begin(), errors.end(), [](double e) { return e > 0.5; }));
  }
  summary.latency_median_ms = percentile(latencies, 0.5);
  summary.latency_p99_ms = percentile(latencies, 0.99);
  summary.pose_age_median_ms = percentile(summary.pose_age_ms, 0.5);
  summary.pose_age_p95_ms = percentile(summary.pose_age_ms, 0.95);
  summary.pose_age_p99_ms = percentile(summary.pose_age_ms, 0.99);
  summary.pose_age_max_ms = percentile(summary.pose_age_ms, 1.0);
  return summary;
}

}  // namespace parkloc::run
