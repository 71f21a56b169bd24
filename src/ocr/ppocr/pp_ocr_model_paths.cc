#include "ocr/ppocr/pp_ocr_model_paths.h"

namespace parkloc::ocr {

PpOcrModelPaths PpOcrModelPaths::inDirectory(const std::string& dir) {
  PpOcrModelPaths paths;
  paths.detection = dir + "/ch_PP-OCRv4_det_infer.onnx";
  paths.recognition = dir + "/ch_PP-OCRv4_rec_infer.onnx";
  paths.direction = dir + "/ch_ppocr_mobile_v2.0_cls_infer.onnx";
  paths.dictionary = dir + "/ppocr_keys_v1.txt";
  return paths;
}

namespace {

// `choice` resolved: the tuned file, `stock` for "", else the file named.
std::string resolve(const std::string& choice, const std::string& stock, const std::string& tuned) {
  if (choice.empty()) return stock;
  return choice == kTunedModel ? tuned : choice;
}

}  // namespace

PpOcrModelPaths modelPathsFor(const ModelChoices& choices, const std::string& model_dir,
                              const std::string& classifier, const std::string& unread_classifier) {
  PpOcrModelPaths paths = PpOcrModelPaths::inDirectory(model_dir);
  paths.floor_detection = resolve(choices.floor_detector, "", floorDetectorIn(model_dir));
  paths.recognition = resolve(choices.recognizer, paths.recognition, tunedRecognizerIn(model_dir));
  paths.band_detection = resolve(choices.band_detector, "", bandDetectorIn(model_dir));
  paths.fallback_recognition =
      resolve(choices.fallback_recognizer, "", tunedRecognizerIn(model_dir));
  paths.classifier = classifier;
  paths.unread_classifier = unread_classifier;
  return paths;
}

PpOcrModelPaths shippedModelPaths(const std::string& model_dir, const std::string& classifier_dir) {
  return modelPathsFor(ModelChoices{}, model_dir, classifier_dir + "/" + kClassifierFile,
                       classifier_dir + "/" + kUnreadClassifierFile);
}

}  // namespace parkloc::ocr
