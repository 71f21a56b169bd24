// `parkloc eval photos FOLDER`: word recall on real photographs of scene text
// (eval/photo_recall.h), once per model parkloc ships that finds or reads text, each in the
// role that reads a photo: the spotter as configured (PaddleOCR's detector and recognizer
// reading first), then with parkloc's floor detector, its band detector and its tuned
// recognizer in their place, each detector with its own post-processing. A model trained on renders
// alone could forget real text; this is the check that it has not. With --min-recall, a row below
// it makes the command fail.
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>

#include "apps/parkloc/command.h"
#include "apps/parkloc/config_args.h"
#include "common/error.h"
#include "eval/photo_recall.h"
#include "ocr/ocr_io.h"
#include "ocr/ppocr/detection.h"
#include "ocr/ppocr/pp_ocr_spotter.h"

namespace parkloc::app {
namespace {

namespace fs = std::filesystem;

struct EvalPhotosArgs {
  std::string folder;
  std::vector<std::string> models;  // row keys; empty: every row
  std::string json;
  double min_recall = 0.0;  // 0: report only
  bool quiet = false;
  ConfigArgs config;
};

struct ModelRow {
  std::string key;   // as --model names it
  std::string name;  // as the table prints it
  ocr::PpOcrOptions options;
};
const std::vector<std::string> kRowKeys{"configured", "floor_detector", "band_detector",
                                        "second_recognizer"};

// The spotter as configured, then each of parkloc's own networks in the role a photo uses.
std::vector<ModelRow> modelRows(const config::Config& config) {
  const ocr::PpOcrOptions configured = config::spotterOptions(config);
  const std::string dir = config::modelDirectory(config.models);
  // The configured file of a role, else parkloc's shipped one (a role the configuration leaves
  // empty, as the band detector by default).
  const auto chosen = [](const std::string& configured_file, const std::string& shipped) {
    return configured_file.empty() ? shipped : configured_file;
  };
  // A detector comes with the post-processing it was trained for (ocr::withRawImagesReadAs).
  ModelRow floor{"floor_detector", "floor detector as the detector", configured};
  floor.options.models.detection =
      chosen(configured.models.floor_detection, ocr::floorDetectorIn(dir));
  floor.options.detection =
      ocr::withRawImagesReadAs(ocr::DetectorRole::kFloorView, configured.detection);
  ModelRow band{"band_detector", "band detector as the detector", configured};
  band.options.models.detection =
      chosen(configured.models.band_detection, ocr::bandDetectorIn(dir));
  band.options.detection =
      ocr::withRawImagesReadAs(ocr::DetectorRole::kRawBand, configured.detection);
  ModelRow tuned{"second_recognizer", "second recognizer reading first", configured};
  tuned.options.models.recognition =
      chosen(configured.models.fallback_recognition, ocr::tunedRecognizerIn(dir));
  return {{"configured", "as configured (detector and first recognizer)", configured},
          floor,
          band,
          tuned};
}

void run(const EvalPhotosArgs& a) {
  const std::vector<eval::PhotoLabels> photos = eval::loadPhotoLabels(a.folder);
  // Every photo decoded before a model loads: a bad file is reported at once.
  std::vector<cv::Mat> images;
  for (const eval::PhotoLabels& p : photos) {
    // The photos sit beside labels.tsv or in its images/ folder.
    fs::path path = fs::path(a.folder) / p.file;
    if (!fs::exists(path) && fs::exists(fs::path(a.folder) / "images" / p.file))
      path = fs::path(a.folder) / "images" / p.file;
    images.push_back(ocr::readImage(path.string()));
  }

  nlohmann::json out = {{"folder", a.folder}, {"rows", nlohmann::json::array()}};
  std::vector<std::string> below;
  fmt::print("{:<48} {:>7} {:>7} {:>7}  files\n", "model", "tokens", "read", "recall");
  for (const ModelRow& row : modelRows(a.config.load())) {
    if (!a.models.empty() && std::find(a.models.begin(), a.models.end(), row.key) == a.models.end())
      continue;
    ocr::PpOcrSpotter spotter(row.options);
    eval::PhotoRecall recall;
    nlohmann::json per_photo = nlohmann::json::array();
    for (size_t i = 0; i < photos.size(); ++i) {
      if (!a.quiet) fmt::print(stderr, "\r{}: {}/{}", row.name, i + 1, photos.size());
      std::vector<std::string> readings;
      for (const ocr::TextInstance& inst : spotter.spot(images[i], ocr::SpotRequest{}))
        if (!inst.text.empty()) readings.push_back(inst.text);
      const std::vector<std::string> tokens = eval::scoredTokens(photos[i]);
      const int read = eval::tokensRead(tokens, readings);
      recall.add(static_cast<int>(tokens.size()), read);
      per_photo.push_back({{"file", photos[i].file},
                           {"tokens", tokens.size()},
                           {"read", read},
                           {"readings", readings}});
    }
    if (!a.quiet) fmt::print(stderr, "\r\033[K");
    fmt::print("{:<48} {:>7} {:>7} {:>7.3f}  {} / {}\n", row.name, recall.tokens, recall.read,
               recall.recall(), fs::path(row.options.models.detection).filename().string(),
               fs::path(row.options.models.recognition).filename().string());
    out["rows"].push_back({{"model", row.name},
                           {"detector", row.options.models.detection},
                           {"recognizer", row.options.models.recognition},
                           {"photos", recall.photos},
                           {"tokens", recall.tokens},
                           {"read", recall.read},
                           {"recall", recall.recall()},
                           {"per_photo", per_photo}});
    if (recall.recall() < a.min_recall) below.push_back(row.name);
  }
  if (!a.json.empty()) {
    std::ofstream f(a.json);
    if (!(f << out.dump(2) << "\n")) throw IoError("cannot write " + a.json);
  }
  if (!below.empty())
    throw InputError(
        fmt::format("word recall below {:.2f}: {}", a.min_recall, fmt::join(below, ", ")));
}

}  // namespace

CLI::App* addEvalPhotos(CLI::App& eval) {
  auto args = std::make_shared<EvalPhotosArgs>();
  auto* cmd = eval.add_subcommand(
      "photos", "Word recall on real photographs of scene text, once per shipped model");
  cmd->add_option("folder", args->folder,
                  "Folder with labels.tsv and the photos (beside it or in images/)")
      ->required();
  cmd->add_option("--model", args->models,
                  "Only these rows (repeatable): configured, floor_detector, band_detector, "
                  "second_recognizer")
      ->check(CLI::IsMember(kRowKeys));
  cmd->add_option("--json", args->json, "Write the figures and each photo's readings as JSON");
  cmd->add_option("--min-recall", args->min_recall,
                  "Fail when a model's word recall falls below this (0: report only)")
      ->check(CLI::Range(0.0, 1.0));
  cmd->add_flag("--quiet", args->quiet, "No progress on stderr");
  args->config.addTo(cmd);
  cmd->callback([args] { run(*args); });
  return cmd;
}

}  // namespace parkloc::app
