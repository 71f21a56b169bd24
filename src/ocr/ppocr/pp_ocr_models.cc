#include "ocr/ppocr/pp_ocr_models.h"

#include "ocr/ppocr/reading_cascade.h"

namespace parkloc::ocr {

PpOcrModels::PpOcrModels(const PpOcrModelPaths& paths, const OnnxOptions& onnx,
                         const std::string& reading_alphabet, const RawBand& band)
    : detector(paths.detection, onnx),
      recognizer(paths.recognition, onnx),
      charset(Charset::fromDictionaryFile(paths.dictionary)) {
  freeReadingClasses(reading_alphabet, {}, charset);  // a foreign character throws
  if (!paths.floor_detection.empty()) floor_detector.emplace(paths.floor_detection, onnx);
  if (!paths.band_detection.empty()) {
    checkBand(band);
    band_detector.emplace(paths.band_detection, onnx);
  }
  if (!paths.direction.empty()) direction.emplace(paths.direction, onnx);
  if (!paths.fallback_recognition.empty())
    fallback_recognizer.emplace(paths.fallback_recognition, onnx);
  if (!paths.classifier.empty()) classifier = TextClassifier::load(paths.classifier);
  if (!paths.unread_classifier.empty())
    unread_classifier = TextClassifier::load(paths.unread_classifier);
}

}  // namespace parkloc::ocr
