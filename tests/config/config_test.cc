#include "config/config.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "common/error.h"

namespace parkloc::config {
namespace {

std::string shippedFile() {
  std::ifstream in(std::string(PARKLOC_SOURCE_DIR) + "/data/config/default.yaml");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The shipped file is the dump of the defaults, byte for byte: the file, the option structs'
// defaults and the reasons cannot drift apart.
TEST(Config, ShippedFileIsTheDumpOfTheDefaults) {
  const std::string shipped = shippedFile();
  ASSERT_FALSE(shipped.empty()) << "data/config/default.yaml is missing";
  EXPECT_EQ(shipped, dumpConfig(Config{}))
      << "regenerate it: parkloc config dump > data/config/default.yaml";
}

TEST(Config, EveryKeyCarriesAReason) {
  std::istringstream lines(dumpConfig(Config{}));
  std::string line, previous;
  int keys = 0;
  while (std::getline(lines, line)) {
    const bool is_key = !line.empty() && line.find(':') != std::string::npos &&
                        line.find('#') == std::string::npos;
    if (is_key) {
      ++keys;
      EXPECT_NE(previous.find('#'), std::string::npos) << "no reason above: " << line;
    }
    previous = line;
  }
  EXPECT_GT(keys, 150);
}

TEST(Config, ReadingTheDumpGivesTheSameConfiguration) {
  Config changed;
  changed.pipeline.reading.full_frame_interval = 7;
  changed.pipeline.solver.pixel_sigma = 0.1234567890123;
  changed.pipeline.measurement.polygon_model = localize::PolygonModel::kCentre;
  changed.spotter.detection.floor_db.box_threshold = 0.4375f;
  changed.spotter.reading.reread_margins = {{1.5f, 2.25f}, {1.125f, 1.0f}};
  changed.spotter.reading.alphabet = "0123: #x";
  changed.spotter.map_prior.placed_size.reset();
  changed.models.dir = "/opt/models";
  const std::string text = dumpConfig(changed);
  const Config read = parseConfig(text, "dump");
  EXPECT_EQ(dumpConfig(read), text);
  EXPECT_EQ(read.pipeline.reading.full_frame_interval, 7);
  EXPECT_DOUBLE_EQ(read.pipeline.solver.pixel_sigma, 0.1234567890123);
  EXPECT_EQ(read.pipeline.measurement.polygon_model, localize::PolygonModel::kCentre);
  EXPECT_EQ(read.spotter.detection.floor_db.box_threshold, 0.4375f);
  EXPECT_EQ(read.spotter.reading.reread_margins.size(), 2u);
  EXPECT_EQ(read.spotter.reading.alphabet, "0123: #x");
  EXPECT_FALSE(read.spotter.map_prior.placed_size.has_value());
  EXPECT_EQ(read.models.dir, "/opt/models");
}

TEST(Config, AFileHoldsOnlyWhatItChanges) {
  const Config read = parseConfig("pipeline:\n  reading:\n    max_reads_per_frame: 5\n", "f");
  EXPECT_EQ(read.pipeline.reading.max_reads_per_frame, 5);
  Config expected;
  expected.pipeline.reading.max_reads_per_frame = 5;
  EXPECT_EQ(dumpConfig(read), dumpConfig(expected));
  EXPECT_EQ(dumpConfig(parseConfig("", "empty")), dumpConfig(Config{}));
}

void expectError(const std::string& yaml, const std::string& fragment) {
  try {
    parseConfig(yaml, "my.yaml");
    ADD_FAILURE() << "accepted: " << yaml;
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("my.yaml"), std::string::npos) << what;
    EXPECT_NE(what.find(fragment), std::string::npos) << what;
  }
}

TEST(Config, BadFilesAreRejectedByKey) {
  expectError("pipeline:\n  reading:\n    max_reads_per_frme: 5\n",
              "unknown option 'pipeline.reading.max_reads_per_frme'");
  expectError("pipline: {}\n", "unknown option 'pipline'");
  expectError("pipeline:\n  solver:\n    pixel_sigma: wide\n", "pipeline.solver.pixel_sigma");
  expectError("pipeline:\n  solver:\n    pixel_sigma: .nan\n", "finite");
  expectError("pipeline:\n  reading:\n    map_guided: 3\n", "true or false");
  expectError("pipeline:\n  measurement:\n    polygon_model: edges\n",
              "must be one of auto, corners, centre");
  expectError("pipeline: 3\n", "must be a mapping");
  expectError("spotter:\n  reading:\n    reread_margins: [[1, 2, 3]]\n", "number pairs");
  expectError("[1, 2]\n", "mapping");
  expectError("a: [\n", "not YAML");
  expectError("models:\n  dir: \"a\\x01b\"\n", "printable UTF-8");
  expectError("models:\n  dir: a\xff\n", "my.yaml");  // a broken byte: not YAML, or not text
  expectError("? [a, b]\n: 1\n", "unknown option '([a, b])'");
  expectError("pipeline:\n  solver:\n    pixel_sigma: {a: 1, b: 2}\n", "not '{a: 1, b: 2}'");
}

TEST(Config, TheModelFolderResolvesFromTheConfigThenTheEnvironment) {
  ModelOptions models;
  models.dir = "/from/config";
  EXPECT_EQ(modelDirectory(models), "/from/config");
  models.dir.clear();
  setenv("PARKLOC_MODEL_DIR", "/from/env", 1);
  EXPECT_EQ(modelDirectory(models), "/from/env");
  unsetenv("PARKLOC_MODEL_DIR");
  EXPECT_FALSE(modelDirectory(models).empty());
}

TEST(Config, SpotterOptionsNameTheShippedModelsInTheModelFolder) {
  Config config;
  config.models.dir = "/m";
  const ocr::PpOcrOptions options = spotterOptions(config);
  EXPECT_EQ(options.models.floor_detection, "/m/parkloc_floor_det.onnx");
  EXPECT_EQ(options.models.fallback_recognition, "/m/parkloc_rec.onnx");
  EXPECT_EQ(options.models.classifier, "/m/text_classifier.yml");
  config.models.classifier = "/elsewhere/head.yml";
  config.models.unread_classifier = "";
  EXPECT_EQ(spotterOptions(config).models.classifier, "/elsewhere/head.yml");
  EXPECT_EQ(spotterOptions(config).models.unread_classifier, "");
}

}  // namespace
}  // namespace parkloc::config
