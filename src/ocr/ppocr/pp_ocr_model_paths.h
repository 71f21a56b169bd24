#pragma once
// Which network files make a PP-OCRv4 spotter: PaddleOCR's own models, parkloc's fine-tuned
// ones (written into the model folder by scripts/setup.sh) and the classifier heads, and the
// set that parkloc ships. Names files only; nothing here loads a model.
#include <string>

namespace parkloc::ocr {

// The floor-view detector: PP-OCRv4's with its neck and head fine-tuned on floor views
// (tools/detector_tuning).
inline constexpr const char* kFloorDetectorFile = "parkloc_floor_det.onnx";
inline std::string floorDetectorIn(const std::string& dir) {
  return dir + "/" + kFloorDetectorFile;
}
// The detector fine-tuned on the raw image's horizon band (ocr/raw_band.h).
inline constexpr const char* kBandDetectorFile = "parkloc_band_det.onnx";
inline std::string bandDetectorIn(const std::string& dir) { return dir + "/" + kBandDetectorFile; }
// The recognizer with its head fine-tuned on the simulator's text crops
// (tools/recognizer_tuning).
inline constexpr const char* kTunedRecognizerFile = "parkloc_rec.onnx";
inline std::string tunedRecognizerIn(const std::string& dir) {
  return dir + "/" + kTunedRecognizerFile;
}
// The class heads (`parkloc train classifier`), in the classifier folder.
inline constexpr const char* kClassifierFile = "text_classifier.yml";
inline constexpr const char* kUnreadClassifierFile = "text_classifier_unread.yml";

struct PpOcrModelPaths {
  std::string detection;
  // The detector run on the floor view; empty: `detection`. floorDetectorIn() names
  // parkloc's, which finds more floor numbers than PaddleOCR's (docs/OCR.md).
  std::string floor_detection;
  // With a camera and a ground view: a detector run at full resolution on the raw image's
  // horizon band (DetectionOptions::band), for what the floor view cannot show: distant floor
  // numbers and text on pillars and walls. Empty: no band detection. bandDetectorIn() names
  // PP-OCRv4's with its neck and head fine-tuned by parkloc on such bands.
  std::string band_detection;
  std::string recognition;
  // A second recognizer for the crops whose reading matches no lexicon entry (full-frame
  // spotting, SpotRequest::second_opinions); only its lexicon matches are taken, marked
  // TextInstance::second_opinion. Empty: none. parkloc's tuned recognizer (tunedRecognizerIn)
  // finds and reads more numbers; some of its matches are wrong entries, so the localization
  // never starts a fix from one (docs/OCR.md).
  std::string fallback_recognition;
  std::string direction;  // empty: decide the direction by decoding both
  std::string dictionary;
  std::string classifier;  // empty: every instance is TextClass::kOther with score 0
  // The head for unread boxes (text empty: DetectionOptions::confident_box_score), trained on
  // the pixels and the box alone (`parkloc train classifier --text unread`): the reading's
  // features that the other head leans on are missing. Empty: `classifier` serves them too.
  std::string unread_classifier;

  // The PaddleOCR file names inside `dir` (and no classifier, no floor detector).
  static PpOcrModelPaths inDirectory(const std::string& dir);
};

// A model named on the command line: kTunedModel for parkloc's fine-tuned file in the model
// folder, "" for the stock choice (PaddleOCR's recognizer; no model for the other roles, which
// leaves the floor view to PaddleOCR's detector), otherwise a file.
inline constexpr const char* kTunedModel = "tuned";
struct ModelChoices {
  std::string floor_detector = kTunedModel;
  std::string recognizer;
  std::string band_detector;
  std::string fallback_recognizer = kTunedModel;
};

// The paths `choices` name in `model_dir`, with the given class heads.
PpOcrModelPaths modelPathsFor(const ModelChoices& choices, const std::string& model_dir,
                              const std::string& classifier, const std::string& unread_classifier);

// The spotter parkloc ships: PaddleOCR's detector, recognizer and direction classifier, parkloc's
// floor detector, parkloc's tuned recognizer as the fallback (ModelChoices' defaults), and the
// two class heads in `classifier_dir`.
PpOcrModelPaths shippedModelPaths(const std::string& model_dir, const std::string& classifier_dir);

}  // namespace parkloc::ocr
