#pragma once
// Shared by `parkloc eval`, `demo` and `bench`: the PP-OCRv4 spotter with the shipped models
// and a progress line on stderr.
#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "apps/parkloc/command.h"
#include "eval/evaluation.h"
#include "ocr/ppocr/pp_ocr_spotter.h"

namespace parkloc::app {

// --floor-detector: '' for PaddleOCR's own, 'tuned' for parkloc's in the model folder, or a file.
inline std::string floorDetectorPath(const std::string& value, const std::string& models) {
  return value == "tuned" ? ocr::floorDetectorIn(models) : value;
}

// --band-detector: '' for none, 'tuned' for parkloc's in the model folder, or a file.
inline std::string bandDetectorPath(const std::string& value, const std::string& models) {
  return value == "tuned" ? ocr::bandDetectorIn(models) : value;
}

// --recognizer: '' for PaddleOCR's own, 'tuned' for parkloc's in the model folder, or a file.
inline std::string recognizerPath(const std::string& value, const std::string& models) {
  if (value.empty()) return ocr::PpOcrModelPaths::inDirectory(models).recognition;
  return value == "tuned" ? ocr::tunedRecognizerIn(models) : value;
}

struct SpotterArgs {
  std::string models = PARKLOC_MODEL_DIR;
  std::string classifier = std::string(PARKLOC_SOURCE_DIR) + "/models/text_classifier.yml";
  std::string unread_classifier =
      std::string(PARKLOC_SOURCE_DIR) + "/models/text_classifier_unread.yml";
  std::string floor_detector = "tuned";       // '', 'tuned' or a path (floorDetectorPath)
  std::string recognizer;                     // '', 'tuned' or a path (recognizerPath)
  std::string band_detector;                  // '', 'tuned' or a path (bandDetectorPath)
  std::string fallback_recognizer = "tuned";  // '', 'tuned' or a path (recognizerPath)
  ocr::GroundViewOptions floor_view;
  ocr::GroundViewOptions placed_reach = ocr::PpOcrOptions{}.placed_reach;
  double placed_window = ocr::PpOcrOptions{}.placed_windows.side_m;
  double placed_window_min_height = ocr::PpOcrOptions{}.placed_windows.min_height_px;
  int placed_windows_max = ocr::PpOcrOptions{}.placed_windows.max_texts;
  double floor_unclip_ratio = ocr::PpOcrOptions{}.floor_db.unclip_ratio;
  float floor_box_threshold = ocr::PpOcrOptions{}.floor_db.box_threshold;
  float floor_binary_threshold = ocr::PpOcrOptions{}.floor_db.binary_threshold;
  std::string reading_alphabet = ocr::PpOcrOptions{}.reading_alphabet;
  float min_text_confidence = ocr::PpOcrOptions{}.min_text_confidence;
  float unplaced_class_weight = ocr::PpOcrOptions{}.unplaced_class_weight;
  double placed_open_world_weight = ocr::PpOcrOptions{}.placed_lexicon.open_world_weight;
  double on_text_open_world_weight = ocr::PpOcrOptions{}.on_placed_text_lexicon.open_world_weight;
  double on_text_margin = ocr::PpOcrOptions{}.on_placed_text_margin_m;
  bool reread_unmatched = !ocr::PpOcrOptions{}.reread_margins.empty();
  bool placed_size = ocr::PpOcrOptions{}.placed_size.has_value();
  bool reread_by_both_recognizers = !ocr::PpOcrOptions{}.reread_by_fallback_only;
  std::vector<float> floor_read_expand = {ocr::PpOcrOptions{}.floor_read_expand_x,
                                          ocr::PpOcrOptions{}.floor_read_expand_y};

  void addTo(CLI::App* cmd) {
    cmd->add_option("--models", models, "Folder with the PP-OCRv4 ONNX models")
        ->capture_default_str();
    cmd->add_option("--classifier", classifier, "Text classifier (YAML); '' for none")
        ->capture_default_str();
    cmd->add_option("--unread-classifier", unread_classifier,
                    "Text classifier for boxes nothing could read (YAML); '' for --classifier")
        ->capture_default_str();
    cmd->add_option(
           "--floor-detector", floor_detector,
           "Detector for the floor view: 'tuned' the one parkloc fine-tuned (in --models), "
           "'' PaddleOCR's own, or an ONNX file")
        ->capture_default_str();
    cmd->add_option("--band-detector", band_detector,
                    "Detector for the raw image's horizon band (distant floor numbers, pillar "
                    "text): '' none (default), 'tuned' the one parkloc fine-tuned (in --models), "
                    "or an ONNX file");
    cmd->add_option("--recognizer", recognizer,
                    "Recognizer: '' PaddleOCR's own (default), 'tuned' the one parkloc "
                    "fine-tuned (in --models), or an ONNX file");
    cmd->add_option("--fallback-recognizer", fallback_recognizer,
                    "Second recognizer for the full-frame crops the first matches to no lexicon "
                    "entry (its matches are second opinions): 'tuned' the one parkloc "
                    "fine-tuned (in --models), '' none, or an ONNX file")
        ->capture_default_str();
    cmd->add_option("--floor-view-near", floor_view.near,
                    "Floor view: where it starts, metres ahead of a camera (negative: behind)")
        ->check(CLI::Range(-5.0, 5.0))
        ->capture_default_str();
    cmd->add_option("--floor-view-far", floor_view.far, "Floor view: metres ahead of a camera")
        ->check(CLI::Range(1.0, 30.0))
        ->capture_default_str();
    cmd->add_option("--floor-view-half-width", floor_view.half_width,
                    "Floor view: metres to each side of a camera")
        ->check(CLI::Range(1.0, 30.0))
        ->capture_default_str();
    cmd->add_option("--floor-unclip-ratio", floor_unclip_ratio,
                    "Box growth of the fine-tuned floor detector (DB unclip ratio)")
        ->check(CLI::Range(1.0, 4.0))
        ->capture_default_str();
    cmd->add_option("--floor-box-threshold", floor_box_threshold,
                    "Floor detector: keep a box whose mean probability reaches this (DB box "
                    "threshold)")
        ->check(CLI::Range(0.05, 0.95))
        ->capture_default_str();
    cmd->add_option("--floor-binary-threshold", floor_binary_threshold,
                    "Floor detector: a map pixel is text above this probability (DB threshold)")
        ->check(CLI::Range(0.05, 0.95))
        ->capture_default_str();
    cmd->add_option("--reading-alphabet", reading_alphabet,
                    "Characters of a free reading besides the lexicon's ('' for all 6625)")
        ->capture_default_str();
    cmd->add_option("--min-text-confidence", min_text_confidence,
                    "A box whose reading matches no lexicon entry is kept when its free "
                    "reading is at least this confident")
        ->check(CLI::Range(0.0, 1.0))
        ->capture_default_str();
    cmd->add_option("--unplaced-class-weight", unplaced_class_weight,
                    "Under a predicted pose, the prior weight of other floor text for a box "
                    "beside a parking number that the map places there (1: the classifier "
                    "decides, 0: a parking number)")
        ->check(CLI::Range(0.0, 1.0))
        ->capture_default_str();
    cmd->add_option("--placed-open-world-weight", placed_open_world_weight,
                    "Under a predicted pose, the prior weight of \"not a text placed here\" "
                    "against the texts the map places near a floor box")
        ->check(CLI::Range(0.0, 1.0))
        ->capture_default_str();
    cmd->add_option("--on-text-open-world-weight", on_text_open_world_weight,
                    "... for a floor box that lies on a text placed there")
        ->check(CLI::Range(0.0, 1.0))
        ->capture_default_str();
    cmd->add_option("--on-text-margin", on_text_margin,
                    "Metres around a placed text's footprint within which a box lies on it "
                    "(negative: no box does)")
        ->capture_default_str();
    cmd->add_flag("--reread-unmatched,!--no-reread-unmatched", reread_unmatched,
                  "Under a predicted pose, read a floor box that matched no placed text again "
                  "with a larger margin, by the fallback recognizer (default: on)");
    cmd->add_flag("--placed-size,!--no-placed-size", placed_size,
                  "Under a predicted pose, hold a floor box read as a text placed near it to "
                  "that text's size on the floor: tightened when too tall or long, refused as "
                  "that text when far too short (default: on)");
    cmd->add_flag("--reread-by-both-recognizers", reread_by_both_recognizers,
                  "... by the first recognizer too (more time an image; measured with two "
                  "re-read margins, it read 0.1 points more numbers)");
    cmd->add_option("--floor-read-expand", floor_read_expand,
                    "Floor detector: its boxes are read from a crop grown by these factors "
                    "(along, across the text)")
        ->expected(2)
        ->check(CLI::Range(1.0, 3.0))
        ->capture_default_str();
    cmd->add_option("--floor-view-resolution", floor_view.resolution,
                    "Floor view: metres per pixel")
        ->check(CLI::Range(0.005, 0.1))
        ->capture_default_str();
    cmd->add_option("--placed-reach-half-width", placed_reach.half_width,
                    "Under a predicted pose, look for the floor texts the map places beyond "
                    "the floor view, out to this many metres to each side of a camera, in "
                    "windows around them (0: never)")
        ->check(CLI::Range(0.0, 30.0))
        ->capture_default_str();
    cmd->add_option("--placed-reach-far", placed_reach.far,
                    "... and out to this many metres ahead of a camera")
        ->check(CLI::Range(1.0, 30.0))
        ->capture_default_str();
    cmd->add_option("--placed-window", placed_window,
                    "... each window a square of this side, in metres, around a placed text")
        ->check(CLI::Range(0.5, 10.0))
        ->capture_default_str();
    cmd->add_option("--placed-window-min-height", placed_window_min_height,
                    "... for the texts that would show at least this many pixels tall")
        ->check(CLI::Range(0.0, 100.0))
        ->capture_default_str();
    cmd->add_option("--placed-windows-max", placed_windows_max,
                    "... for at most this many texts an image, the tallest first (0: all)")
        ->check(CLI::Range(0, 100))
        ->capture_default_str();
  }
};

// The engine's options from the shared flags (the classifier only when its file exists).
inline ocr::PpOcrOptions spotterOptions(const SpotterArgs& args) {
  ocr::PpOcrOptions options;
  options.models = ocr::PpOcrModelPaths::inDirectory(args.models);
  options.models.floor_detection = floorDetectorPath(args.floor_detector, args.models);
  options.models.recognition = recognizerPath(args.recognizer, args.models);
  options.models.band_detection = bandDetectorPath(args.band_detector, args.models);
  if (!args.fallback_recognizer.empty())
    options.models.fallback_recognition = recognizerPath(args.fallback_recognizer, args.models);
  options.ground_view = args.floor_view;
  options.placed_reach = args.placed_reach;
  options.placed_windows.side_m = args.placed_window;
  options.placed_windows.min_height_px = args.placed_window_min_height;
  options.placed_windows.max_texts = args.placed_windows_max;
  options.floor_db.unclip_ratio = args.floor_unclip_ratio;
  options.floor_db.box_threshold = args.floor_box_threshold;
  options.floor_db.binary_threshold = args.floor_binary_threshold;
  options.reading_alphabet = args.reading_alphabet;
  options.min_text_confidence = args.min_text_confidence;
  options.unplaced_class_weight = args.unplaced_class_weight;
  options.placed_lexicon.open_world_weight = args.placed_open_world_weight;
  options.on_placed_text_lexicon.open_world_weight = args.on_text_open_world_weight;
  options.on_placed_text_margin_m = args.on_text_margin;
  if (!args.reread_unmatched) options.reread_margins.clear();
  if (!args.placed_size) options.placed_size.reset();
  options.reread_by_fallback_only = !args.reread_by_both_recognizers;
  options.floor_read_expand_x = args.floor_read_expand.at(0);
  options.floor_read_expand_y = args.floor_read_expand.at(1);
  if (!args.classifier.empty() && std::filesystem::exists(args.classifier)) {
    options.models.classifier = args.classifier;
  }
  if (!args.unread_classifier.empty() && std::filesystem::exists(args.unread_classifier))
    options.models.unread_classifier = args.unread_classifier;
  return options;
}

inline std::unique_ptr<ocr::TextSpotter> makeSpotter(const SpotterArgs& args) {
  return std::make_unique<ocr::PpOcrSpotter>(spotterOptions(args));
}

// "\r<stage> [#####.....] 12/40 frame sets, 3 s, eta 7 s" on stderr, a new line per stage.
class ProgressLine {
 public:
  explicit ProgressLine(bool quiet = false) : quiet_(quiet) {}
  ~ProgressLine() { finish(); }

  void operator()(const eval::Progress& p) {
    if (quiet_) return;
    const auto now = std::chrono::steady_clock::now();
    if (p.stage != stage_) {
      finish();
      stage_ = p.stage;
      start_ = now;
    }
    const double fraction = p.total ? static_cast<double>(p.done) / p.total : 1.0;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double eta = fraction > 0 ? elapsed / fraction - elapsed : 0.0;
    const int width = 30, filled = static_cast<int>(fraction * width);
    std::cerr << fmt::format("\r{} [{}{}] {}/{} frame sets, {:.0f} s, eta {:.0f} s   ", stage_,
                             std::string(filled, '#'), std::string(width - filled, '.'), p.done,
                             p.total, elapsed, eta)
              << std::flush;
    open_ = true;
  }
  void finish() {
    if (open_) std::cerr << "\n";
    open_ = false;
  }

 private:
  bool quiet_ = false;
  bool open_ = false;
  std::string stage_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace parkloc::app
