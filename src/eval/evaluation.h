#pragma once
// Runs the localization pipeline and the text spotter over the sequences of a dataset split
// and measures what the paper's tables report (the spotter alone: eval/ocr_evaluation.h). Every
// frame set is read once and fed to all configurations in lockstep; full-frame OCR runs once per
// image and its instances are shared by the eight paper-pipeline variants of the ablation (Table
// 10).
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "eval/ocr_evaluation.h"
#include "eval/ocr_metrics.h"
#include "eval/report.h"
#include "io/tum.h"
#include "localize/pipeline.h"
#include "map/placed_texts.h"
#include "ocr/text_spotter.h"

namespace parkloc::eval {

struct EvaluationOptions {
  bool parkloc = true;         // the full pipeline, spotting itself (map-guided); needs a spotter
  bool paper_ablation = true;  // the 8 AFM / MCRP / MCAP variants; needs a spotter
  // The paper's pipeline (every module on) spotting by itself, full frame on all cameras
  // every frame, for latency (`parkloc bench`); runs beside or instead of the ablation.
  bool paper_own_spotting = false;
  bool oracle = true;                         // the full pipeline on ground-truth text boxes
  bool odometry_only = true;                  // dead reckoning from the true first pose
  // For comparison only: tell every pipeline the level each drive starts on (meta.json) as
  // a hint, as a user who knows where the car entered would. Off: the level is estimated.
  bool give_level = false;
  size_t max_frames_per_sequence = 0;         // 0: all
  size_t trajectory_views = 2;                // drives drawn in the report
  localize::PipelineOptions parkloc_options;  // for parkloc and the oracle
  // Survey error (map/map_noise.h): the main configuration (parkloc, else the oracle) runs on
  // the map perturbed by each of these position sigmas (metres), one configuration each, the
  // first being the main one itself; errors are measured against the truth all the same. The
  // map of a garage is perturbed once per level and seed, so its drives share one survey.
  // A perturbed level runs once per seed: one map draw decides much of a drive's error
  // (which landmarks are off, and which way), so several draws tell the level's effect
  // from one draw's luck; the report gives each draw a row and, with more than one, their
  // pooled frames a row. A first level above 0 (the main configuration) takes the first seed.
  std::vector<double> map_noise_levels{0.0};
  std::vector<uint64_t> map_noise_seeds{0};
  OcrEvaluationOptions ocr_metrics;
  ProgressCallback progress;
  std::string title = "parkloc evaluation";
  std::string dataset;  // shown in the report
  std::string command;
};

// Without a spotter only the oracle and odometry-only variants run. The report's main
// variant is parkloc when it ran, else the oracle. Throws InputError for a bad sequence.
// `workers`: the workers' own spotters for parkloc's pipeline (localize::Pipeline).
EvaluationReport evaluateSequences(const std::vector<std::string>& sequences,
                                   ocr::TextSpotter* spotter, const EvaluationOptions& options,
                                   localize::WorkerSpotters workers = {});

}  // namespace parkloc::eval
