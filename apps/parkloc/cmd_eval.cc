// parkloc eval DATASET      : the paper's tables 3, 5, 8 and 10 and the report.
// parkloc eval ocr DATASET  : table 3 only (text spotting), printed and as JSON.
// parkloc eval birdseye DATASET : table 3 on the stitched top-down images, four orientations.
// parkloc eval map, parkloc eval photos: cmd_eval_map.cc, cmd_eval_photos.cc.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <filesystem>
#include <fstream>
#include <iostream>

#include "apps/parkloc/command.h"
#include "apps/parkloc/config_args.h"
#include "apps/parkloc/map_commands.h"
#include "apps/parkloc/progress_line.h"
#include "common/error.h"
#include "eval/birds_eye_evaluation.h"
#include "eval/dataset.h"
#include "eval/evaluation.h"
#include "eval/report.h"
#include "eval/tables.h"
#include "eval/text_outcomes.h"
#include "io/tum.h"
#include "map/landmark.h"
#include "ocr/ppocr/pp_ocr_spotter.h"

namespace {

using namespace parkloc;

struct EvalArgs {
  std::string dataset;
  std::string split = "test";
  std::string out = "parkloc-eval";
  std::string json;
  std::string outcomes;
  std::string poses;
  double placement_radius = ocr::SpotRequest{}.placement_radius_m;
  int max_frames = 0;
  bool no_paper = false;
  bool no_oracle = false;
  bool give_level = false;
  bool no_lexicon = false;
  bool whole_polygons = false;
  bool quiet = false;
  std::vector<double> map_noise{0.0};
  std::vector<uint64_t> map_noise_seeds{0};
  app::ConfigArgs config;
  std::string command_line;
};

// The options `eval ocr` and `eval birdseye` share, from their arguments.
eval::OcrRunOptions ocrRunOptions(const EvalArgs& a, app::ProgressLine& progress) {
  eval::OcrRunOptions options;
  options.max_frames_per_sequence = static_cast<size_t>(a.max_frames);
  options.use_lexicon = !a.no_lexicon;
  options.metrics.inside_image_only = !a.whole_polygons;
  options.progress = [&progress](const eval::Progress& p) { progress(p); };
  return options;
}

void runEvalOcr(const EvalArgs& a) {
  const std::vector<std::string> sequences = eval::splitSequences(a.dataset, a.split);
  const config::Config config = a.config.load();
  auto spotter = app::makeSpotter(config);
  app::ProgressLine progress(a.quiet);
  eval::OcrRunOptions options = ocrRunOptions(a, progress);
  options.placement_radius_m = a.placement_radius;
  if (!a.poses.empty())  // DIR/<drive>/trajectory.tum, as `parkloc run --out DIR/<drive>` writes
    for (const std::string& sequence : sequences) {
      const std::string name = std::filesystem::path(sequence).filename().string();
      options.estimated_poses[name] = io::loadTum(a.poses + "/" + name + "/trajectory.tum");
    }
  std::ofstream outcomes;
  if (!a.outcomes.empty()) {
    outcomes.open(a.outcomes);
    if (!outcomes) throw IoError(a.outcomes + ": cannot open for writing");
    options.on_image = [&](const std::string& sequence, const io::ImageLabels& labels,
                           const std::vector<ocr::TextInstance>& found) {
      for (const eval::TextOutcome& o : eval::textOutcomes(labels, found, options.metrics)) {
        nlohmann::json j = eval::outcomeJson(o, labels, found);
        j["sequence"] = sequence;
        outcomes << j.dump() << "\n";
      }
    };
  }
  const eval::OcrEvaluation result = eval::evaluateOcr(sequences, *spotter, options);
  progress.finish();
  std::cout << fmt::format("{} images from {} sequences ({} split of {}), engine {}\n\n",
                           result.images, sequences.size(), a.split, a.dataset, spotter->name());
  for (const eval::Table& t : eval::table3All(result, std::nullopt))
    std::cout << eval::tableMarkdown(t);
  const eval::OcrCounts numbers = result.by_class.count("parking_number")
                                      ? result.by_class.at("parking_number")
                                      : eval::OcrCounts{};
  std::cout << fmt::format(
      "parking numbers: detection F {:.4f}, recognition {:.4f} (raw {:.4f}), classification "
      "{:.4f}; {:.2f} images/s ({:.1f} ms per image)\n",
      numbers.fMeasure(), numbers.recognitionAccuracy(), numbers.recognitionRawAccuracy(),
      numbers.classificationAccuracy(), result.imagesPerSecond(),
      result.images ? 1000.0 * result.spotting_seconds / result.images : 0.0);
  if (!a.json.empty()) {
    nlohmann::json j = eval::ocrEvaluationJson(result);
    j["dataset"] = a.dataset;
    j["split"] = a.split;
    j["engine"] = spotter->name();
    std::ofstream out(a.json);
    if (!out) throw IoError(a.json + ": cannot open for writing");
    out << j.dump(2) << "\n";
    std::cout << "wrote " << a.json << "\n";
  }
  if (!a.outcomes.empty()) std::cout << "wrote " << a.outcomes << "\n";
}

// parkloc eval birdseye DATASET: Table 3 on the dataset's stitched top-down images in four
// orientations.
void runEvalBirdsEye(const EvalArgs& a, double metres_per_pixel) {
  const std::vector<std::string> sequences = eval::splitSequences(a.dataset, a.split);
  const config::Config config = a.config.load();
  ocr::PpOcrSpotter spotter(config::spotterOptions(config));
  app::ProgressLine progress(a.quiet);
  eval::OcrRunOptions options = ocrRunOptions(a, progress);
  const eval::OcrEvaluation result = eval::evaluateBirdsEye(
      sequences,
      [&](const cv::Mat& image, const ocr::SpotRequest& request) {
        return spotter.spotBirdsEye(image, request, metres_per_pixel);
      },
      options);
  progress.finish();
  std::cout << fmt::format(
      "{} bird's-eye images (4 orientations each) from {} sequences ({} split "
      "of {}), engine {}\n\n",
      result.images, sequences.size(), a.split, a.dataset, spotter.name());
  std::cout << eval::tableMarkdown(eval::table3(result, std::nullopt));
  std::cout << eval::tableMarkdown(eval::table3BirdsEye(result));
  const eval::Table looks = eval::table3Appearance(result);
  if (!looks.rows.empty()) std::cout << eval::tableMarkdown(looks);
  for (const std::string& o : eval::birdsEyeOrientations()) {
    eval::OcrCounts n;
    if (const auto it = result.parking_numbers_by_condition.find(o);
        it != result.parking_numbers_by_condition.end())
      n = it->second;
    std::cout << fmt::format(
        "{} parking numbers: detection P {:.4f} R {:.4f} F {:.4f}, reading with lexicon "
        "{:.4f}\n",
        o, n.precision(), n.recall(), n.fMeasure(), n.recognitionAccuracy());
  }
  if (!a.json.empty()) {
    nlohmann::json j = eval::ocrEvaluationJson(result);
    j["dataset"] = a.dataset;
    j["split"] = a.split;
    j["engine"] = spotter.name();
    std::ofstream out(a.json);
    if (!out) throw IoError(a.json + ": cannot open for writing");
    out << j.dump(2) << "\n";
    std::cout << "wrote " << a.json << "\n";
  }
}

void runEval(const EvalArgs& a) {
  const std::vector<std::string> sequences = eval::splitSequences(a.dataset, a.split);
  const config::Config config = a.config.load();
  auto spotter = app::makeSpotter(config);
  app::ProgressLine progress(a.quiet);
  eval::EvaluationOptions options;
  options.parkloc_options = config.pipeline;
  options.paper_ablation = !a.no_paper;
  options.oracle = !a.no_oracle;
  options.give_level = a.give_level;
  options.max_frames_per_sequence = static_cast<size_t>(a.max_frames);
  options.map_noise_levels = a.map_noise;
  options.map_noise_seeds = a.map_noise_seeds;
  options.progress = [&](const eval::Progress& p) { progress(p); };
  options.title = "parkloc evaluation: " + a.split + " split";
  options.dataset =
      a.dataset + " (" + a.split + ", " + std::to_string(sequences.size()) + " sequences)";
  options.command = a.command_line;
  const auto workers = app::makeWorkerSpotters(config);
  const eval::EvaluationReport report =
      eval::evaluateSequences(sequences, spotter.get(), options, workers.pointers());
  progress.finish();
  eval::writeReport(report, a.out);
  for (const eval::Table& t : report.tables) std::cout << eval::tableMarkdown(t);
  const eval::VariantResult& m = report.main;
  std::cout << fmt::format(
      "{}: {} frame sets, {} with a pose; position error mean {:.1f} cm, p95 {:.1f} cm; yaw "
      "error mean {:.2f} deg; latency median {:.1f} ms, p99 {:.1f} ms\n",
      m.title, m.frames, m.frames_with_pose, m.error.position_m.mean * 100.0,
      m.error.position_m.p95 * 100.0, m.error.abs_yaw_deg.mean, m.latency.total_ms.median,
      m.latency.total_ms.p99);
  std::cout << "wrote " << a.out << "/report.html, results.json, results.md\n";
}

const bool registered = app::registerCommand([](CLI::App& parent) {
  auto args = std::make_shared<EvalArgs>();
  auto* cmd = parent.add_subcommand(
      "eval", "Evaluate on a dataset split: the paper's tables 3, 5, 8, 10 and a report");
  cmd->add_option("dataset", args->dataset, "Dataset folder (with splits.json) or one sequence");
  cmd->add_option("--split", args->split, "train | val | test")->capture_default_str();
  cmd->add_option("--out", args->out, "Report folder")->capture_default_str();
  cmd->add_option("--max-frames", args->max_frames, "At most N frame sets per sequence (0: all)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--no-paper", args->no_paper, "Skip the paper pipeline and its ablation");
  cmd->add_flag("--no-oracle", args->no_oracle, "Skip the oracle-OCR variant");
  cmd->add_flag("--give-level", args->give_level,
                "For comparison: hint each drive's starting level (meta.json) to the pipelines");
  cmd->add_option("--map-noise", args->map_noise,
                  "Survey error of the map the pipeline gets (metres, 1 sigma per axis; a list, "
                  "e.g. 0,0.03,0.10, gives one configuration and one report row each)")
      ->delimiter(',')
      ->check(CLI::Range(0.0, map::kMaxPositionSigmaM));
  cmd->add_option("--map-noise-seed", args->map_noise_seeds,
                  "Seed of the map perturbation (a list, e.g. 1,2,3, runs each perturbed level "
                  "once per seed: one row each and one of them pooled)")
      ->delimiter(',')
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--quiet", args->quiet, "No progress on stderr");
  args->config.addTo(cmd);

  auto ocr_args = std::make_shared<EvalArgs>();
  auto* ocr_cmd =
      cmd->add_subcommand("ocr", "Text spotting metrics (the paper's Table 3) on a dataset split");
  ocr_cmd->add_option("dataset", ocr_args->dataset, "Dataset folder (with splits.json)")
      ->required();
  ocr_cmd->add_option("--split", ocr_args->split, "train | val | test")->capture_default_str();
  ocr_cmd->add_option("--json", ocr_args->json, "Write every metric as JSON");
  ocr_cmd->add_option("--outcomes", ocr_args->outcomes,
                      "Write what became of each cared-for label (found, missed) and each false "
                      "detection, one JSON object a line");
  ocr_cmd->add_option("--max-frames", ocr_args->max_frames, "At most N frame sets per sequence")
      ->check(CLI::NonNegativeNumber);
  ocr_cmd->add_flag("--no-lexicon", ocr_args->no_lexicon, "Free reading only");
  ocr_cmd->add_option("--poses", ocr_args->poses,
                      "Folder of localization runs (DIR/<drive>/trajectory.tum, as parkloc run "
                      "writes): floor boxes decode against the texts placed near them under the "
                      "pose predicted from the estimate before each frame set");
  ocr_cmd
      ->add_option("--placement-radius", ocr_args->placement_radius,
                   "With --poses: metres from a box's centre within which a map text may be it")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  ocr_cmd->add_flag("--whole-polygons", ocr_args->whole_polygons,
                    "Match whole label polygons, not only their parts inside the image");
  ocr_cmd->add_flag("--quiet", ocr_args->quiet, "No progress on stderr");
  ocr_args->config.addTo(ocr_cmd);
  ocr_cmd->callback([ocr_args] { runEvalOcr(*ocr_args); });

  auto avm_args = std::make_shared<EvalArgs>();
  auto avm_scale = std::make_shared<double>(0.02);
  auto* avm_cmd = cmd->add_subcommand(
      "birdseye",
      "Text spotting metrics (Table 3) on the stitched top-down images of a dataset split "
      "(parkloc simulate --birdseye), in four orientations");
  avm_cmd->add_option("dataset", avm_args->dataset, "Dataset folder (with splits.json)")
      ->required();
  avm_cmd->add_option("--split", avm_args->split, "train | val | test")->capture_default_str();
  avm_cmd->add_option("--metres-per-pixel", *avm_scale, "Scale of the top-down images")
      ->check(CLI::Range(0.001, 0.5))
      ->capture_default_str();
  avm_cmd->add_option("--json", avm_args->json, "Write every metric as JSON");
  avm_cmd->add_option("--max-frames", avm_args->max_frames, "At most N images per sequence")
      ->check(CLI::NonNegativeNumber);
  avm_cmd->add_flag("--no-lexicon", avm_args->no_lexicon, "Free reading only");
  avm_cmd->add_flag("--quiet", avm_args->quiet, "No progress on stderr");
  avm_args->config.addTo(avm_cmd);
  avm_cmd->callback([avm_args, avm_scale] { runEvalBirdsEye(*avm_args, *avm_scale); });

  CLI::App* map_cmd = app::addEvalMap(*cmd);
  CLI::App* photos_cmd = app::addEvalPhotos(*cmd);
  cmd->callback([args, ocr_cmd, avm_cmd, map_cmd, photos_cmd] {
    if (ocr_cmd->parsed() || avm_cmd->parsed() || map_cmd->parsed() || photos_cmd->parsed()) return;
    if (args->dataset.empty()) throw CLI::RequiredError("dataset");
    args->command_line = fmt::format(
        "parkloc eval {} --split {}{}{}{}{}{}", args->dataset, args->split,
        args->out.empty() ? "" : " --out " + args->out,
        args->max_frames ? fmt::format(" --max-frames {}", args->max_frames) : "",
        args->no_paper ? " --no-paper" : "", args->no_oracle ? " --no-oracle" : "",
        args->map_noise == std::vector<double>{0.0}
            ? ""
            : fmt::format(" --map-noise {} --map-noise-seed {}", fmt::join(args->map_noise, ","),
                          fmt::join(args->map_noise_seeds, ",")));
    runEval(*args);
  });
});

}  // namespace
