#include "ocr/ppocr/pp_ocr_model_paths.h"

#include <gtest/gtest.h>

namespace parkloc::ocr {
namespace {

TEST(ShippedModelPaths, NameParkLocsFloorDetectorFallbackRecognizerAndBothHeads) {
  const PpOcrModelPaths shipped = shippedModelPaths("/m", "/c");
  const PpOcrModelPaths stock = PpOcrModelPaths::inDirectory("/m");
  EXPECT_EQ(shipped.detection, stock.detection);
  EXPECT_EQ(shipped.recognition, stock.recognition);
  EXPECT_EQ(shipped.direction, stock.direction);
  EXPECT_EQ(shipped.dictionary, stock.dictionary);
  EXPECT_EQ(shipped.floor_detection, floorDetectorIn("/m"));
  EXPECT_EQ(shipped.fallback_recognition, tunedRecognizerIn("/m"));
  EXPECT_EQ(shipped.band_detection, "");
  EXPECT_EQ(shipped.classifier, "/c/text_classifier.yml");
  EXPECT_EQ(shipped.unread_classifier, "/c/text_classifier_unread.yml");
}

TEST(ModelPathsFor, ResolveTunedStockAndFiles) {
  ModelChoices choices;
  choices.floor_detector = "";
  choices.recognizer = kTunedModel;
  choices.band_detector = kTunedModel;
  choices.fallback_recognizer = "/x/rec.onnx";
  const PpOcrModelPaths paths = modelPathsFor(choices, "/m", "a.yml", "");
  EXPECT_EQ(paths.floor_detection, "");  // the floor view is left to `detection`
  EXPECT_EQ(paths.recognition, tunedRecognizerIn("/m"));
  EXPECT_EQ(paths.band_detection, bandDetectorIn("/m"));
  EXPECT_EQ(paths.fallback_recognition, "/x/rec.onnx");
  EXPECT_EQ(paths.classifier, "a.yml");
  EXPECT_EQ(paths.unread_classifier, "");
  choices = {};
  choices.recognizer = "";
  choices.fallback_recognizer = "";
  const PpOcrModelPaths stock = modelPathsFor(choices, "/m", "", "");
  EXPECT_EQ(stock.recognition, PpOcrModelPaths::inDirectory("/m").recognition);
  EXPECT_EQ(stock.fallback_recognition, "");  // no second recognizer
}

}  // namespace
}  // namespace parkloc::ocr
