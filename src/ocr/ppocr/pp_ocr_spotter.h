#pragma once
// The PaddleOCR PP-OCRv4 engine on ONNX Runtime (paper section 3.2, with PP-OCRv4 mobile in
// place of ABCNet): DB detection on the raw fisheye image, perspective-rectified crops,
// CTC recognition in both reading directions, lexicon decoding and the classification head.
// With SpotRequest::regions, only those regions are processed (map-guided spotting).
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ocr/corner_refinement.h"
#include "ocr/db_postprocess.h"
#include "ocr/ground_view.h"
#include "ocr/lexicon.h"
#include "ocr/onnx_model.h"
#include "ocr/placed_size.h"
#include "ocr/placed_windows.h"
#include "ocr/ppocr/pp_ocr_networks.h"
#include "ocr/raw_band.h"
#include "ocr/text_classifier.h"
#include "ocr/text_spotter.h"
#include "ocr/tracked_text_fit.h"

namespace parkloc::ocr {

// The fine-tuned floor-view detector's file name in the model folder (scripts/setup.sh).
inline constexpr const char* kFloorDetectorFile = "parkloc_floor_det.onnx";
inline std::string floorDetectorIn(const std::string& dir) {
  return dir + "/" + kFloorDetectorFile;
}
// The detector fine-tuned on the raw image's horizon band (ocr/raw_band.h).
inline constexpr const char* kBandDetectorFile = "parkloc_band_det.onnx";
inline std::string bandDetectorIn(const std::string& dir) { return dir + "/" + kBandDetectorFile; }
// The recognizer with its head fine-tuned on the simulator's text crops
// (tools/recognizer_tuning, written at set-up); an experiment, not the default
// (--recognizer tuned; docs/OCR.md).
inline constexpr const char* kTunedRecognizerFile = "parkloc_rec.onnx";
inline std::string tunedRecognizerIn(const std::string& dir) {
  return dir + "/" + kTunedRecognizerFile;
}

struct PpOcrModelPaths {
  std::string detection;
  // The detector run on the floor view; empty: `detection`. floorDetectorIn() names
  // PP-OCRv4's with its neck and head fine-tuned by parkloc on floor views
  // (tools/detector_tuning, written at set-up), which the parkloc commands use by default
  // (--floor-detector): it finds more floor numbers (docs/OCR.md).
  std::string floor_detection;
  // With a camera and a ground view: a detector run at full resolution on the raw image's
  // horizon band (PpOcrOptions::band), for what the floor view cannot show: distant floor
  // numbers and text on pillars and walls. Empty: no band detection. bandDetectorIn() names
  // PP-OCRv4's with its neck and head fine-tuned by parkloc on such bands.
  std::string band_detection;
  std::string recognition;
  // A second recognizer for the crops whose reading matches no lexicon entry (full-frame
  // spotting, SpotRequest::second_opinions); only its lexicon matches are taken, marked
  // TextInstance::second_opinion. Empty: none. The command line gives parkloc's tuned
  // recognizer (tunedRecognizerIn), which finds and reads more numbers; some of its matches
  // are wrong entries, so the localization never starts a fix from one (docs/OCR.md,
  // sessions 8 and 10).
  std::string fallback_recognition;
  std::string direction;  // empty: decide the direction by decoding both
  std::string dictionary;
  std::string classifier;  // empty: every instance is TextClass::kOther with score 0
  // The head for unread boxes (text empty: PpOcrOptions::confident_box_score), trained on
  // the pixels and the box alone (`parkloc train classifier --text unread`): the reading's
  // features that the other head leans on are missing. Empty: `classifier` serves them too.
  std::string unread_classifier;

  // The PaddleOCR file names inside `dir` (and no classifier, no floor detector).
  static PpOcrModelPaths inDirectory(const std::string& dir);
};

enum class DirectionMode {
  kDecodeBoth,  // recognize the 0 and 180 degree crops, keep the better reading
  kClassifier,  // the direction classifier decides; both only when it is unsure
};

// Where full-frame detection runs on a fisheye image (docs/OCR.md has the measurements).
enum class FisheyeView {
  kRaw,           // the raw image
  kGround,        // a bird's-eye view of the floor (needs SpotRequest::camera; else raw)
  kGroundAndRaw,  // both; raw detections already found on the floor are dropped
};

// Margins for PpOcrOptions::reread_margins: larger than the floor boxes' own. Session 14 read
// a tight one (1.0 x 1.1) too; on the test split, session 17, the two read 93.8 % where this
// one reads 92.4 %, for 12 ms more an image (85.7 -> 98.0 ms, back to back), too close to the
// 100 ms budget (docs/OCR.md).
inline const std::vector<std::pair<float, float>> kRereadMargins = {{1.25f, 1.7f}};

struct PpOcrOptions {
  PpOcrModelPaths models;
  OnnxOptions onnx;
  DbOptions db;
  // Post-processing for the fine-tuned floor detector: it was trained on DB's shrunk kernels
  // (r = 0.4, tools/detector_tuning/db_targets.py), which an unclip ratio of about 2 grows
  // back to the whole text box for text 3-4 times as long as high; PaddleOCR's own 1.5
  // leaves boxes a fifth too low, and crops that cut into the glyphs read worse. Its thin
  // kernels also average less over their rectangle than PaddleOCR's (a clean upside-down
  // number in a floor view: 0.54), so the box threshold is DB's binary threshold: a box
  // under confident_box_score is kept only when the lexicon matches or the free reading is
  // confident (min_text_confidence). Val split: parking-number detection F 0.753 -> 0.787, found
  // and read 56.3 -> 57.0 % (docs/OCR.md, session 7).
  DbOptions floor_db = [] {
    DbOptions o;
    o.unclip_ratio = 2.0;
    o.box_threshold = 0.3f;
    return o;
  }();
  // Its boxes are the text's own box, with no margin (PaddleOCR's unclip of 1.5 leaves one),
  // and the recognizer reads a crop with a margin better: floor-view crops are read from the
  // box grown by these factors (along, across the text); the box itself is what is
  // reported. Chosen on the val split among 1.05 x 1.15 to 1.2 x 1.7: found and read 59.6 ->
  // 63.2 % (docs/OCR.md, session 9).
  float floor_read_expand_x = 1.1f;
  float floor_read_expand_y = 1.3f;
  FisheyeView view = FisheyeView::kGround;
  GroundViewOptions ground_view;
  // Under a predicted pose (SpotRequest::look_beyond_the_view), the floor texts placed beyond
  // `ground_view` but within this wider view are looked for in windows around them
  // (ocr/placed_windows.h), detected at `ground_view`'s resolution (this one's is not used).
  // A half width of 0: never. The side cameras see their row of numbers 6-10 m along the
  // aisle, which the +-6 m view misses and a +-8 m view costs too much to detect whole.
  GroundViewOptions placed_reach = [] {
    GroundViewOptions o;
    o.half_width = 10.0;
    return o;
  }();
  PlacedWindowOptions placed_windows;
  // Floor-view boxes scoring at least this (PaddleOCR's own box threshold) are text by the
  // detector's standard. With SpotRequest::max_reads they are read before the others (a
  // search turn's two reads go to the boxes it would have read with that threshold), and
  // they are reported even when no reading is confident, as unread text (`text` empty):
  // a number in a font the recognizer misreads is still a number found. Weaker boxes are
  // reported only when read (min_text_confidence). Val split, first 40 frame sets a drive:
  // parking-number recall 72.0 -> 76.5 % (docs/OCR.md, session 8).
  float confident_box_score = 0.6f;
  // The band detector's rows and post-processing (trained as the floor detector was; its
  // box threshold stays DB's, as measured in session 6).
  RawBand band;
  DbOptions band_db = [] {
    DbOptions o;
    o.unclip_ratio = 2.0;
    return o;
  }();
  // Full-frame detection input on a raw image: the longer side is scaled to this (multiple of
  // 32). A floor view is detected at its own resolution (GroundViewOptions::resolution).
  int detection_max_side = 960;
  int recognition_max_width = CtcRecognizer::kMaxWidth;  // crops are kHeight px tall
  int recognition_batch = 8;
  DirectionMode direction = DirectionMode::kClassifier;
  float direction_confident = 0.9f;  // classifier probability above which one crop suffices
  LexiconOptions lexicon;
  // ... and for a floor box read against the texts placed near it under a predicted pose:
  // the map paints those texts there, so "some other text" is a ten times weaker hypothesis
  // than against the whole lexicon. Val split, first 40 frame sets a drive, open-world weight
  // 0.05 / 0.005 / 0.0005 / 0: parking numbers read right 912 / 939 / 949 / 971, misread
  // 51 / 40 / 37 / 32, false detections called parking numbers 27 / 31 / 37 / 40
  // (docs/OCR.md, session 15). 0 would force every box onto the text placed there.
  LexiconOptions placed_lexicon = [] {
    LexiconOptions o;
    o.open_world_weight = 0.005;
    return o;
  }();
  // ... and for one whose centre lies on a text placed there (its footprint on the floor grown
  // by on_placed_text_margin_m; negative: never): the map paints that text under the box, so
  // "some other text" is fifty times weaker again, and a faint reading of it (down to e^-5 a
  // character) still counts. Val split, first 40 frame sets a drive, open-world weight and
  // floor 0.0005 / -3, -4, -5 and 0.0001 / -3, -5: parking numbers read with the lexicon
  // 99.08 / 99.19 / 99.19 / 99.08 / 99.31 % (98.26 % before), false detections 0.12 % each
  // (docs/OCR.md, session 21).
  LexiconOptions on_placed_text_lexicon = [] {
    LexiconOptions o;
    o.open_world_weight = 0.0001;
    o.min_log_prob_per_char = -5.0;
    return o;
  }();
  double on_placed_text_margin_m = 0.1;
  // Under a predicted pose (SpotRequest::placed_floor_texts) a floor box whose reading axis lies
  // within this angle (radians) of the way the texts placed near it read is read that way round
  // only: half the recognizer's work, and no reading of the number upside down ("600" for
  // "009") to compete with the right one.
  double placed_reading_max_angle = 30.0 * M_PI / 180.0;
  // ... and a floor box is classified under the classes' prior weights that the texts placed
  // near it give (floorClassWeightsNear): a parking number only where the map paints one, and
  // beside one, other floor text at this weight. Val split, first 40 frame sets a drive,
  // weights 0 / 0.05 / 0.2 / 0.5: parking numbers classified 99.80 / 99.39 / 99.39 / 99.28 %,
  // their false detections 4.6 / 3.9 / 3.7 / 3.7 % (3.6 % without placed classes: fragments of
  // numbers cut by the border, which the classifier calls other text).
  float unplaced_class_weight = 0.2f;
  // ... and a floor box that may run out of the image decodes against the parts of the texts
  // placed near it that a cut would leave, of at least this many characters and half the
  // text (ocr/cut_parts.h; TextInstance::partial); 0: none. Test split: parking numbers read
  // with the lexicon 80.5 -> 85.0 % of the detected, 159 cut numbers matched by their part,
  // none to a wrong text (docs/OCR.md, session 14).
  int min_cut_part_chars = 2;
  // ... and a floor box read as a text placed near it is held to that text's size on the floor
  // (ocr/placed_size.h): tightened when DB's margin left it too tall or long, refused as that
  // text when far too short; one that matched nothing, lying on a text, is tightened too, or
  // dropped as a fragment of it. Test split, session 21: parking-number detection F 0.947 ->
  // 0.950, false detections 1.13 -> 0.76 % (docs/OCR.md). Empty: never.
  std::optional<PlacedSizeOptions> placed_size = PlacedSizeOptions{};
  // ... and a floor box read against the texts placed near it, one way round, that no reading
  // matched is read again from crops grown by each of these factors (along, across the text),
  // its matches counting as the first reading's. Empty: none. Test split, session 17: parking
  // numbers read with the lexicon 89.7 -> 92.4 % of the detected, 86.1 -> 83.5 ms an image in
  // back-to-back runs (the cost is within the machine's noise; docs/OCR.md).
  std::vector<std::pair<float, float>> reread_margins = kRereadMargins;
  // ... read by the fallback recognizer alone (PpOcrModelPaths::fallback_recognition; by the
  // first when there is none), its matches second opinions. Test split, session 17, session
  // 14's two margins: read by the first recognizer they added 0.7 points of reading, by the
  // fallback 4.0, by both (false) 4.1, each at a cost of its own (docs/OCR.md).
  bool reread_by_fallback_only = true;
  // A crop read with a lexicon (the map's texts) is read freely, too, with only these
  // characters and the lexicon's (ctcGreedyDecode): the garage's script, not the 6625
  // classes of a Chinese recognizer. Empty, or a request without a lexicon: every class.
  std::string reading_alphabet = "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ";
  // Re-fit the corners to the ink (on the ground plane when SpotRequest::camera is set).
  bool refine_corners = true;
  CornerRefinementOptions refinement;
  // Free readings (no lexicon match) below this mean confidence are dropped as non-text,
  // unless the detector is sure of the box (confident_box_score).
  float min_text_confidence = 0.6f;
  // Map-guided spotting: the region is expanded to at least these multiples of its text
  // size and warped to a patch of this size (the patch keeps the text's aspect ratio).
  float region_expand_x = 1.4f;
  float region_expand_y = 2.2f;
  cv::Size region_patch{256, 64};
  // Regions with a predicted text polygon (RegionOfInterest::predicted) are read at the
  // prediction grown by these factors, without detection (the map tracks them to a few
  // pixels; the lexicon must match); false: every region goes through the detector.
  bool read_at_prediction = true;
  float prediction_expand_x = 1.1f;
  float prediction_expand_y = 1.4f;
  // Regions with RegionOfInterest::read == false: corner fit only.
  TrackedFitOptions tracked_fit;
};

class PpOcrSpotter : public TextSpotter {
 public:
  // Loads every model; throws InputError naming a missing or unreadable file.
  explicit PpOcrSpotter(const PpOcrOptions& options);
  ~PpOcrSpotter() override;

  std::string name() const override { return "ppocr-v4"; }
  std::vector<TextInstance> spot(const cv::Mat& image, const SpotRequest& request) override;

  const PpOcrOptions& options() const { return options_; }

 private:
  struct Networks;
  std::vector<TextInstance> spotFullFrame(const cv::Mat& image, const SpotRequest& request);
  std::vector<TextInstance> spotRegions(const cv::Mat& image, const SpotRequest& request);
  std::vector<TextInstance> readRegions(const cv::Mat& image, const SpotRequest& request);

  // Which detector looks at the image: PaddleOCR's on a raw image (scaled to
  // detection_max_side), the floor detector on a floor view (at the view's resolution), the
  // band detector on a raw image's horizon band (at full resolution).
  enum class DetectorRole { kScene, kFloorView, kRawBand };
  // Where detectAndRead's `image` lies in a floor view: the whole view, or a mosaic of its
  // windows (ocr/placed_windows.h).
  struct FloorWindow;
  std::vector<TextInstance> detectAndRead(const cv::Mat& image, const SpotRequest& request,
                                          const geometry::RigCamera* camera, DetectorRole role,
                                          const FloorWindow* floor = nullptr);
  const GroundView& groundView(const geometry::RigCamera& camera);
  const GroundView& placedReach(const geometry::RigCamera& camera);

  PpOcrOptions options_;
  std::unique_ptr<Networks> nets_;
  std::vector<std::unique_ptr<GroundView>> ground_views_;    // one per camera calibration
  std::vector<std::unique_ptr<GroundView>> placed_reaches_;  // likewise, for `placed_reach`
};

// Throws InputError unless `image` is a non-empty 8-bit 3-channel image.
void requireBgrImage(const cv::Mat& image, const std::string& what = "image");

}  // namespace parkloc::ocr
