#pragma once
// The networks of a PP-OCRv4 spotter, loaded once: the detectors of each role, the
// recognizers, the direction classifier, the character set and the class heads.
#include <optional>
#include <string>

#include "ocr/ctc.h"
#include "ocr/onnx_model.h"
#include "ocr/ppocr/pp_ocr_model_paths.h"
#include "ocr/ppocr/pp_ocr_networks.h"
#include "ocr/raw_band.h"
#include "ocr/text_classifier.h"
#include "ocr/text_spotter.h"

namespace parkloc::ocr {

struct PpOcrModels {
  DbDetector detector;
  std::optional<DbDetector> floor_detector;  // empty: `detector` serves the floor view too
  std::optional<DbDetector> band_detector;   // empty: no band detection
  CtcRecognizer recognizer;
  std::optional<DirectionClassifier> direction;
  Charset charset;
  TextClassifier classifier;
  TextClassifier unread_classifier;  // empty: `classifier` classifies unread boxes too
  std::optional<CtcRecognizer> fallback_recognizer;  // empty: none

  // Loads every file `paths` names, in the order listed above. The options that must agree
  // with a model are checked as it loads: `reading_alphabet` against the dictionary (a
  // character it lacks throws), `band` before the band detector (checkBand). Throws
  // InputError naming a missing or unreadable file.
  PpOcrModels(const PpOcrModelPaths& paths, const OnnxOptions& onnx,
              const std::string& reading_alphabet, const RawBand& band);

  // The class head for an instance: the unread head when nothing was read.
  const TextClassifier& headFor(const TextInstance& instance) const {
    return instance.text.empty() && !unread_classifier.empty() ? unread_classifier : classifier;
  }
};

}  // namespace parkloc::ocr
