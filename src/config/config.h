#pragma once
// parkloc's configuration: every option of the spotter and the localization pipeline, and
// the model files, in one structure that mirrors the one YAML file (data/config/default.yaml,
// `parkloc config dump`). A file loaded with --config overlays the defaults: it holds only
// what it changes.
#include <string>

#include "localize/pipeline.h"
#include "mapping/map_builder.h"
#include "ocr/ppocr/pp_ocr_model_paths.h"
#include "ocr/ppocr/pp_ocr_spotter.h"

namespace parkloc::config {

// Which network files the spotter loads, and from where.
struct ModelOptions {
  // The model folder: "" for the environment variable PARKLOC_MODEL_DIR, else the folder
  // scripts/setup.sh fills (the build's default, modelDirectory()).
  std::string dir;
  ocr::ModelChoices choices;
  // The class heads; a relative name is looked for in the model folder. "": none.
  std::string classifier = ocr::kClassifierFile;
  std::string unread_classifier = ocr::kUnreadClassifierFile;
};

struct Config {
  ModelOptions models;
  ocr::PpOcrOptions spotter;  // its `models` paths come from `models` above (spotterOptions)
  localize::PipelineOptions pipeline;
  mapping::MapBuildOptions map_build;
};

// The defaults overlaid with the YAML file at `path`; throws InputError naming the file and
// the key for an unknown key or a bad value, IoError for a file that cannot be read.
Config loadConfig(const std::string& path);
// The same from YAML text (`where` names it in errors).
Config parseConfig(const std::string& yaml, const std::string& where);
// `config` as the YAML file, every key with its reason.
std::string dumpConfig(const Config& config);

// The model folder `models` resolves to: its `dir`, else $PARKLOC_MODEL_DIR, else the
// folder this build's set-up filled.
std::string modelDirectory(const ModelOptions& models);
// The spotter's options with every model path resolved; the spotter reports a file that
// does not exist when it loads it.
ocr::PpOcrOptions spotterOptions(const Config& config);

}  // namespace parkloc::config
