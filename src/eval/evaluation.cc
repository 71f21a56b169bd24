#include "eval/evaluation.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <set>

#include "eval/conditions.h"
#include "eval/consistency.h"
#include "eval/dataset.h"
#include "eval/dead_reckoning.h"
#include "eval/evaluation_variants.h"
#include "eval/latency.h"
#include "eval/number_recall.h"
#include "eval/pose_prediction.h"
#include "eval/tables.h"
#include "io/sequence.h"
#include "map/map_noise.h"
#include "run/oracle_source.h"
#include "run/sequence_runner.h"

namespace parkloc::eval {
namespace {

using Clock = std::chrono::steady_clock;
using detail::EvaluationTotals;
using detail::makeView;
using detail::Source;
using detail::VariantRun;
using detail::VariantSpec;
using detail::variantSpecs;
using detail::VariantTally;

// Per detection: +1 read correctly (matched to a label with the same text), 0 wrong
// (unmatched, or matched and misread), -1 unknown (on a don't-care region).
std::vector<int> detectionCorrectness(const io::ImageLabels& labels,
                                      const std::vector<ocr::TextInstance>& detections,
                                      const OcrEvaluationOptions& options) {
  const ImageMatching m = matchLabels(labels, detections, options);
  std::vector<int> out(detections.size(), 0);
  for (const MatchedPair& p : m.matches) {
    out[p.detection] = detections[p.detection].text == labels.instances[p.truth].text ? 1 : 0;
  }
  for (size_t d : m.ignored_detections) out[d] = -1;
  return out;
}

// Rotation subsets of the parking numbers a camera sees clearly in this frame.
void addRotationTags(const io::ImageLabels& labels, double dont_care_occlusion,
                     std::set<std::string>& tags) {
  for (const auto& l : labels.instances) {
    if (l.cls != map::TextClass::kParkingNumber || l.occluded_fraction >= dont_care_occlusion ||
        !l.legible)
      continue;
    if (const auto rot = rotationSubset(l.rotation_deg)) tags.insert(*rot);
  }
}

// One camera of a frame set, read once for every configuration.
struct CameraData {
  std::string name;
  std::optional<double> capture_time;
  cv::Mat image;
  std::optional<io::ImageLabels> labels;
  std::vector<ocr::TextInstance> full_frame;
  std::vector<int> correctness;
};

// Table 3's anomaly filter figures: each parking-number reading the filter was offered, whether
// it was read right (against the labels) and whether the filter kept it.
void countAnomalyFilter(const std::vector<localize::Association>& associations,
                        const std::vector<CameraData>& cameras, AnomalyFilterCounts& afm_counts) {
  for (const localize::Association& a : associations) {
    const auto cam = std::find_if(cameras.begin(), cameras.end(),
                                  [&](const CameraData& c) { return c.name == a.camera; });
    if (cam == cameras.end() || a.instance_index < 0 ||
        static_cast<size_t>(a.instance_index) >= cam->correctness.size())
      continue;
    using V = localize::AssociationVerdict;
    if (a.verdict != V::kAccepted && a.verdict != V::kNotInMap && a.verdict != V::kAnomaly)
      continue;
    const int correct = cam->correctness[static_cast<size_t>(a.instance_index)];
    if (correct < 0) continue;
    ++afm_counts.readings;
    if (a.verdict == V::kAccepted) {
      ++afm_counts.kept;
      afm_counts.kept_correct += correct;
    }
    if (!correct) {
      ++afm_counts.anomalies;
      afm_counts.anomalies_rejected += a.verdict != V::kAccepted;
    }
  }
}

std::optional<geometry::Pose2> truthAt(const std::vector<io::StampedPose>& truth, double t,
                                       double max_difference = 0.01) {
  const io::StampedPose* best = nullptr;
  for (const auto& p : truth) {
    if (std::fabs(p.timestamp - t) <= max_difference &&
        (!best || std::fabs(p.timestamp - t) < std::fabs(best->timestamp - t))) {
      best = &p;
    }
  }
  if (!best) return std::nullopt;
  return geometry::Pose2::fromRigid3(best->pose);
}

}  // namespace

EvaluationReport evaluateSequences(const std::vector<std::string>& sequences,
                                   ocr::TextSpotter* spotter, const EvaluationOptions& options,
                                   localize::WorkerSpotters workers) {
  std::vector<VariantTally> tallies;
  for (const VariantSpec& spec : variantSpecs(options, spotter != nullptr)) {
    VariantTally tally;
    tally.spec = spec;
    tallies.push_back(std::move(tally));
  }
  const bool shared_ocr = std::any_of(tallies.begin(), tallies.end(), [](const VariantTally& t) {
    return t.spec.source == Source::kSharedFullFrame;
  });
  // The shared pass asks for second opinions only when a pipeline it feeds would ask for
  // them spotting by itself: the paper's never does (it never tracks, so a second opinion
  // could only be unconfirmed there, and its reading time would be timed for nothing).
  const bool shared_second_opinions =
      std::any_of(tallies.begin(), tallies.end(), [](const VariantTally& t) {
        return t.spec.source == Source::kSharedFullFrame && t.spec.options.reading.second_opinions;
      });
  OcrEvaluator ocr_evaluator(options.ocr_metrics);
  // Without the shared full-frame pass, the OCR figures come from the full-frame spotting
  // the parkloc pipeline does by itself (its map-guided frames are left out).
  OcrEvaluator own_ocr_evaluator(options.ocr_metrics);
  AnomalyFilterCounts afm_counts;
  std::vector<TrajectoryView> views;
  const std::string main_key = spotter && options.parkloc ? "parkloc" : "oracle";

  for (size_t s = 0; s < sequences.size(); ++s) {
    const io::Sequence seq(sequences[s]);
    const std::string name = std::filesystem::path(seq.dir()).filename().string();
    const std::vector<std::string> conditions =
        sequenceConditions(seq.metaJson(), seq.dir() + "/meta.json");
    ocr::SpotRequest full_frame;
    full_frame.lexicon = map::distinctTexts(seq.map());
    full_frame.floor_lexicon = map::distinctTexts(seq.map(), /*floor_only=*/true);
    full_frame.second_opinions = shared_second_opinions;
    size_t frames = seq.timestamps().size();
    if (options.max_frames_per_sequence) frames = std::min(frames, options.max_frames_per_sequence);
    if (frames == 0) continue;
    const double t0 = seq.timestamps().front(), t1 = seq.timestamps()[frames - 1];

    // The level the drive starts on: the hint of --give-level, and the truth where the drive
    // has no levels.csv.
    const std::string start_level = sequenceLevel(seq.metaJson());
    std::vector<VariantRun> runs;
    for (VariantTally& tally : tallies) {
      VariantRun run;
      run.tally = &tally;
      if (tally.spec.source == Source::kOdometry) {
        const auto start = truthAt(seq.groundTruth(), t0);
        if (!start) continue;  // no ground truth to start from
        run.dead_reckoning = std::make_unique<DeadReckoning>(*start, t0);
      } else {
        localize::PipelineOptions pipeline_options = tally.spec.options;
        if (options.give_level) pipeline_options.level = start_level;
        run.pipeline = std::make_unique<localize::Pipeline>(
            seq.rig(),
            tally.spec.map_noise_m > 0.0
                ? map::perturbedMap(seq.map(), {tally.spec.map_noise_m, tally.spec.map_noise_seed})
                : seq.map(),
            pipeline_options, tally.spec.source == Source::kSpotter ? spotter : nullptr,
            tally.spec.source == Source::kSpotter ? workers : localize::WorkerSpotters{});
      }
      runs.push_back(std::move(run));
    }
    const VariantRun* paper_full = nullptr;
    for (const VariantRun& r : runs) {
      if (r.tally->spec.ablation && r.tally->spec.afm && r.tally->spec.mcrp && r.tally->spec.mcap)
        paper_full = &r;
    }

    double previous_time = -std::numeric_limits<double>::infinity();
    const std::string stage = fmt::format("sequence {}/{} {}", s + 1, sequences.size(), name);
    std::vector<std::set<std::string>> tags_by_frame;
    for (size_t i = 0; i < frames; ++i) {
      const double t = seq.timestamps()[i];
      const std::vector<OdometrySample> odometry =
          run::odometryBetween(seq.odometry(), previous_time, t);
      previous_time = t;

      // Read every camera once; spot the full frame once for all paper variants.
      std::vector<CameraData> cameras;
      std::set<std::string> tags(conditions.begin(), conditions.end());
      double shared_ocr_ms = 0.0;
      for (const std::string& camera : seq.cameras()) {
        CameraData c;
        c.name = camera;
        c.capture_time = seq.captureTime(i, camera);
        c.labels = seq.loadLabels(i, camera);
        if (c.labels) addRotationTags(*c.labels, options.ocr_metrics.dont_care_occlusion, tags);
        if (spotter) c.image = seq.loadImage(i, camera);
        if (shared_ocr && !c.image.empty()) {
          full_frame.camera = seq.rig().find(camera);  // the floor view needs the camera
          const auto start = Clock::now();
          c.full_frame = spotter->spot(c.image, full_frame);
          const double ms = msSince(start);
          shared_ocr_ms += ms;
          if (c.labels) {
            ocr_evaluator.add(*c.labels, c.full_frame, conditions, ms / 1000.0);
            c.correctness = detectionCorrectness(*c.labels, c.full_frame, options.ocr_metrics);
          }
        }
        cameras.push_back(std::move(c));
      }
      tags_by_frame.push_back(tags);
      // What scores the level estimate: the true level, and a text that tells it in view.
      std::vector<io::ImageLabels> labels;
      for (const CameraData& c : cameras)
        if (c.labels) labels.push_back(*c.labels);
      LevelFrame level_truth;
      level_truth.timestamp = t;
      // levels.csv where the drive has one (a drive that changes level), else meta.json's.
      level_truth.truth = io::levelAt(seq.levelTruth(), t).value_or(start_level);
      level_truth.telling_text_in_view = tellingTextInView(seq.map(), labels);

      for (VariantRun& run : runs) {
        VariantTally& tally = *run.tally;
        ++tally.frames_total;
        if (run.dead_reckoning) {
          const auto start = Clock::now();
          run.dead_reckoning->advance(odometry, t);
          tally.timings.push_back({msSince(start), {{"dead_reckoning", msSince(start)}}});
          run.estimate.push_back({t, run.dead_reckoning->pose().toRigid3()});
          ++tally.frames_with_pose;
          ++tally.after_fix;
          ++tally.with_pose_after_fix;
          continue;
        }
        localize::FrameInput input;
        input.timestamp = t;
        input.odometry = odometry;
        for (const CameraData& c : cameras) {
          localize::CameraInput in;
          in.camera = c.name;
          in.capture_time = c.capture_time;
          switch (tally.spec.source) {
            case Source::kSpotter:
              in.image = c.image;
              break;
            case Source::kSharedFullFrame:
              in.instances = c.full_frame;
              break;
            case Source::kOracle:
              in.instances =
                  c.labels ? run::oracleInstances(*c.labels) : std::vector<ocr::TextInstance>{};
              break;
            case Source::kOdometry:
              break;
          }
          input.cameras.push_back(std::move(in));
        }
        const auto start = Clock::now();
        const localize::FrameResult result = run.pipeline->process(input);
        double total_ms = msSince(start);
        const localize::StageTimings& st = result.timings;
        FrameTiming timing;
        timing.stage_ms = {{"roi", st.roi_ms},
                           {"spotting", st.spotting_ms},
                           {"association", st.association_ms},
                           {"solver", st.solver_ms},
                           {"filter", st.filter_ms}};
        if (tally.spec.source == Source::kSharedFullFrame) {
          // The shared OCR ran outside the pipeline; it belongs to this variant's latency.
          timing.stage_ms["spotting"] += shared_ocr_ms;
          total_ms += shared_ocr_ms;
        }
        if (tally.spec.source == Source::kOracle) timing.stage_ms.erase("spotting");
        // Off the critical path: the workers' time on the texts fused here.
        if (result.background) timing.worker_ms += result.background->worker_ms;
        if (result.deferred_reads) timing.worker_ms += result.deferred_reads->worker_ms;
        timing.total_ms = total_ms;
        tally.timings.push_back(timing);

        if (!shared_ocr && tally.spec.key == "parkloc") {
          size_t full_frames = 0;
          for (const localize::CameraResult& c : result.cameras) full_frames += c.full_frame;
          for (const localize::CameraResult& c : result.cameras) {
            const auto cam = std::find_if(cameras.begin(), cameras.end(),
                                          [&](const CameraData& d) { return d.name == c.camera; });
            if (!c.full_frame || !c.image_ok || cam == cameras.end() || !cam->labels) continue;
            own_ocr_evaluator.add(*cam->labels, c.instances, conditions,
                                  st.spotting_ms / 1000.0 / static_cast<double>(full_frames));
          }
        }
        LevelFrame level = level_truth;
        level.has_pose = result.has_pose;
        level.level = result.level;
        level.decided = result.level_decided;
        run.level_frames.push_back(level);
        if (result.has_pose) {
          run.fixed = true;
          ++tally.frames_with_pose;
          run.estimate.push_back({t, result.pose.toRigid3()});
          run.covariance.push_back(result.covariance);
          run.smoother_frames.push_back({t, result.pose, result.fused_fixes});
        }
        if (run.fixed) {
          ++tally.after_fix;
          tally.with_pose_after_fix += result.has_pose;
        }
        for (const localize::Association& a : result.associations) {
          if (a.verdict != localize::AssociationVerdict::kAccepted || a.landmark_id.empty())
            continue;
          if (const map::Landmark* l = seq.map().findById(a.landmark_id))
            run.levels.insert(l->level);
        }

        // Table 3's anomaly filter figures, from the paper pipeline with every module on.
        if (&run == paper_full) countAnomalyFilter(result.associations, cameras, afm_counts);
      }
      if (options.progress) options.progress({stage, i + 1, frames});
    }

    // Errors of this drive, each frame tagged with its conditions.
    for (VariantRun& run : runs) {
      if (run.pipeline) run.tally->levels.add(scoreLevels(run.level_frames));
      for (size_t k = 0; k < run.covariance.size(); ++k) {
        const auto truth = run::truthAt(seq.groundTruth(), run.estimate[k].timestamp);
        if (!truth) continue;
        const geometry::Pose2 estimate = geometry::Pose2::fromRigid3(run.estimate[k].pose);
        const Eigen::Vector3d error(estimate.x - truth->x, estimate.y - truth->y,
                                    std::remainder(estimate.yaw - truth->yaw, 2.0 * M_PI));
        ++run.tally->nees_frames;
        run.tally->nees_inside += nees(error, run.covariance[k]) <= ConsistencyOptions{}.nees_bound;
      }
      const TrajectoryError e = trajectoryError(run.estimate, seq.groundTruth());
      for (const FrameError& f : e.frames) {
        const auto it = std::lower_bound(seq.timestamps().begin(),
                                         seq.timestamps().begin() + static_cast<long>(frames),
                                         f.timestamp - 0.01);
        const size_t index =
            std::min(frames - 1, static_cast<size_t>(it - seq.timestamps().begin()));
        run.tally->frames.push_back(f);
        run.tally->frame_tags.push_back(tags_by_frame[index]);
      }
      // The main configuration at each map-noise level: the same fixes smoothed offline.
      const bool main_family =
          run.pipeline && (run.tally->spec.key == main_key ||
                           run.tally->spec.key.rfind(main_key + "_map_noise_", 0) == 0);
      const bool map_noise_table =
          std::any_of(options.map_noise_levels.begin(), options.map_noise_levels.end(),
                      [](double level) { return level > 0.0; });
      if (main_family && map_noise_table) {
        if (const auto smoothed =
                smoothDrive(run.smoother_frames, seq.odometry(), run.tally->spec.options.ekf)) {
          std::vector<io::StampedPose> poses;
          for (size_t k = 0; k < smoothed->poses.size(); ++k)
            poses.push_back({run.smoother_frames[k].timestamp, smoothed->poses[k].toRigid3()});
          const TrajectoryError se = trajectoryError(poses, seq.groundTruth());
          run.tally->smoothed_frames.insert(run.tally->smoothed_frames.end(), se.frames.begin(),
                                            se.frames.end());
        }
      }
      // The main configuration's first drives, and those of each map-noise level.
      const bool main_or_noisy =
          run.tally->spec.key == main_key ||
          (run.tally->spec.map_noise_m > 0.0 && run.tally->spec.key.rfind(main_key, 0) == 0);
      if (main_or_noisy && run.tally->views < options.trajectory_views) {
        views.push_back(makeView(seq, run, t0, t1));
        ++run.tally->views;
      }
    }
  }

  return detail::assembleReport(
      options,
      EvaluationTotals{tallies, main_key, spotter != nullptr, shared_ocr, shared_second_opinions,
                       ocr_evaluator, own_ocr_evaluator, afm_counts, views, sequences.size()});
}

}  // namespace parkloc::eval
