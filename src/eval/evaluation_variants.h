#pragma once
// The configurations evaluateSequences (eval/evaluation.h) runs side by side over the drives:
// what each one is, what it accumulates, and the report built from their totals. Internal to
// the eval module.
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "eval/dead_reckoning.h"
#include "eval/drive_smoother.h"
#include "eval/evaluation.h"
#include "eval/latency.h"
#include "eval/level_metrics.h"
#include "eval/ocr_metrics.h"
#include "eval/report.h"
#include "eval/tables.h"
#include "eval/trajectory_metrics.h"
#include "io/sequence.h"
#include "io/tum.h"
#include "localize/pipeline.h"

namespace parkloc::eval::detail {

// Where a configuration's text instances come from: its own spotting, the full-frame pass
// shared by the paper's ablation variants, the ground-truth labels, or none (odometry only).
enum class Source { kSpotter, kSharedFullFrame, kOracle, kOdometry };

struct VariantSpec {
  std::string key, title;
  Source source = Source::kSpotter;
  localize::PipelineOptions options;
  bool afm = false, mcrp = false, mcap = false;
  bool ablation = false;
  double map_noise_m = 0.0;  // the pipeline's map perturbed by this survey error (0: exact)
  uint64_t map_noise_seed = 0;  // ... drawn with this seed
};

// What one variant accumulates over all sequences.
struct VariantTally {
  VariantSpec spec;
  std::vector<FrameError> frames;
  std::vector<std::set<std::string>> frame_tags;
  std::vector<FrameTiming> timings;
  size_t frames_total = 0, frames_with_pose = 0, after_fix = 0, with_pose_after_fix = 0;
  LevelScore levels;
  // The reported covariance against the truth: frames with a pose and truth, and those whose
  // NEES lies inside the 95 % chi-square bound (eval/consistency.h).
  size_t nees_frames = 0, nees_inside = 0;
  size_t views = 0;  // drives drawn in the report
  // The drive smoothed from the fixes this configuration fused (eval/drive_smoother.h), at its
  // frames with a pose: what a non-causal estimator makes of the same fixes and odometry.
  std::vector<FrameError> smoothed_frames;
};

// One variant's state within a sequence.
struct VariantRun {
  VariantTally* tally = nullptr;
  std::unique_ptr<localize::Pipeline> pipeline;
  std::unique_ptr<DeadReckoning> dead_reckoning;
  std::vector<io::StampedPose> estimate;
  std::vector<Eigen::Matrix3d> covariance;  // of each estimate
  std::set<std::string> levels;  // levels of the landmarks it used (for the map plot)
  std::vector<LevelFrame> level_frames;
  bool fixed = false;
  std::vector<SmootherFrame> smoother_frames;  // frames with a pose, for the drive smoother
};

// The configurations the options ask for, in the report's order: parkloc, the paper's
// Table 10 ablation, the paper's pipeline spotting itself, the oracle, odometry only.
std::vector<VariantSpec> variantSpecs(const EvaluationOptions& o, bool have_spotter);
VariantResult toResult(const VariantTally& t);
// One tally of several configurations' frames (the draws of one map-noise level): their
// frames, counts and smoothed frames together, under the first one's spec.
VariantTally pooledTally(const std::vector<const VariantTally*>& tallies);
// The trajectory error per recording condition and rotation subset (Table 8).
std::map<std::string, TrajectoryError> conditionErrors(const VariantTally& t);
// One drive of one configuration drawn over the map, between t0 and t1.
TrajectoryView makeView(const io::Sequence& seq, const VariantRun& run, double t0, double t1);

// What the run over every drive gathered, for the report.
struct EvaluationTotals {
  const std::vector<VariantTally>& tallies;
  std::string main_key;  // the headline configuration: "parkloc" or "oracle"
  bool have_spotter = false;
  bool shared_ocr = false;              // the paper's variants shared one full-frame pass
  bool shared_second_opinions = false;  // ... which asked for second opinions
  const OcrEvaluator& shared_ocr_evaluator;
  const OcrEvaluator& own_ocr_evaluator;  // parkloc's own full-frame spotting
  const AnomalyFilterCounts& afm_counts;
  std::vector<TrajectoryView> views;
  size_t sequences = 0;
};

// The report's figures, tables (3, 5, 8, 10, latency) and notes (evaluation_report.cc).
EvaluationReport assembleReport(const EvaluationOptions& options, const EvaluationTotals& totals);

}  // namespace parkloc::eval::detail
