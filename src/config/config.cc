#include "config/config.h"

#include <yaml-cpp/yaml.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/error.h"
#include "config/localize_options.h"
#include "config/mapping_options.h"
#include "config/ocr_options.h"
#include "config/yaml_reader.h"
#include "config/yaml_writer.h"

#ifndef PARKLOC_DEFAULT_MODEL_DIR
#define PARKLOC_DEFAULT_MODEL_DIR ""
#endif

namespace parkloc::config {
namespace {

const char* const kHeader =
    "parkloc configuration: every option with its default and the reason for it.\n"
    "Written by `parkloc config dump`; load a changed copy with --config FILE (a file may\n"
    "hold only the keys it changes). Units are in the key's name; angles inside the code are\n"
    "radians.";

void describe(OptionVisitor& v, ModelOptions& o) {
  v.value("dir", o.dir, "model folder (\"\": $PARKLOC_MODEL_DIR, else the set-up's folder)");
  v.value("floor_detector", o.choices.floor_detector,
          "floor-view detector: tuned (parkloc's), \"\" (PaddleOCR's) or a file");
  v.value("recognizer", o.choices.recognizer,
          "recognizer: \"\" (PaddleOCR's), tuned (parkloc's) or a file");
  v.value("band_detector", o.choices.band_detector,
          "horizon-band detector: \"\" (none), tuned (parkloc's) or a file");
  v.value("fallback_recognizer", o.choices.fallback_recognizer,
          "second recognizer for unmatched crops: tuned, \"\" (none) or a file");
  v.value("classifier", o.classifier, "class head for read boxes (relative: in the model folder)");
  v.value("unread_classifier", o.unread_classifier, "class head for boxes nothing could read");
}

void describe(OptionVisitor& v, Config& c) {
  v.section("models", "the network files", [&] { describe(v, c.models); });
  v.section("spotter", "text spotting (PP-OCRv4 on ONNX Runtime), docs/OCR.md",
            [&] { describe(v, c.spotter); });
  v.section("pipeline", "the localization, one section per stage, docs/LOCALIZATION.md",
            [&] { describe(v, c.pipeline); });
  v.section("map_build", "the map builder (parkloc map build), docs/MAPPING.md",
            [&] { describe(v, c.map_build); });
}

std::string inModelDir(const std::string& file, const std::string& dir) {
  if (file.empty() || std::filesystem::path(file).is_absolute()) return file;
  return (std::filesystem::path(dir) / file).string();
}

}  // namespace

Config parseConfig(const std::string& yaml, const std::string& where) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml);
  } catch (const YAML::Exception& e) {
    throw InputError(where + ": not YAML: " + e.msg + " at line " +
                     std::to_string(e.mark.line + 1));
  }
  Config config;
  YamlReader reader(root, where);
  describe(reader, config);
  reader.requireAllKnown();
  return config;
}

Config loadConfig(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw IoError(path + ": cannot open the configuration");
  std::stringstream text;
  text << in.rdbuf();
  return parseConfig(text.str(), path);
}

std::string dumpConfig(const Config& config) {
  Config copy = config;
  YamlWriter writer;
  writer.comment(kHeader);
  writer.comment("");
  describe(writer, copy);
  return writer.text();
}

std::string modelDirectory(const ModelOptions& models) {
  if (!models.dir.empty()) return models.dir;
  if (const char* env = std::getenv("PARKLOC_MODEL_DIR"); env != nullptr && *env != '\0')
    return env;
  return PARKLOC_DEFAULT_MODEL_DIR;
}

ocr::PpOcrOptions spotterOptions(const Config& config) {
  const std::string dir = modelDirectory(config.models);
  ocr::PpOcrOptions options = config.spotter;
  options.models =
      ocr::modelPathsFor(config.models.choices, dir, inModelDir(config.models.classifier, dir),
                         inModelDir(config.models.unread_classifier, dir));
  return options;
}

}  // namespace parkloc::config
