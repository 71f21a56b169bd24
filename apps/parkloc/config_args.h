#pragma once
// --config FILE and --models DIR, for every command that spots or localizes: the options come
// from the configuration (data/config/default.yaml, config/config.h), the command line keeps
// what changes per run.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <memory>
#include <string>

#include "config/config.h"
#include "ocr/ppocr/pp_ocr_spotter.h"

namespace parkloc::app {

struct ConfigArgs {
  std::string file;    // "": the defaults
  std::string models;  // "": the configuration's models.dir

  void addTo(CLI::App* cmd) {
    cmd->add_option("--config", file,
                    "Configuration YAML overlaid on the defaults (parkloc config dump prints them)")
        ->check(CLI::ExistingFile);
    cmd->add_option("--models", models,
                    "Model folder (default: the configuration's models.dir, else "
                    "$PARKLOC_MODEL_DIR, else the set-up's)");
  }

  config::Config load() const {
    config::Config c = file.empty() ? config::Config{} : config::loadConfig(file);
    if (!models.empty()) c.models.dir = models;
    return c;
  }
};

inline std::unique_ptr<ocr::TextSpotter> makeSpotter(const config::Config& config) {
  return std::make_unique<ocr::PpOcrSpotter>(config::spotterOptions(config));
}

// The search worker's own spotter (localize/search_worker.h), with the worker's inference
// threads; made after makeSpotter's, whose thread counts size ONNX Runtime's shared pool.
// Null when the configuration runs no search worker.
inline std::unique_ptr<ocr::TextSpotter> makeWorkerSpotter(const config::Config& config) {
  if (!config.pipeline.realtime.background_search || config.pipeline.paper_mode) return nullptr;
  ocr::PpOcrOptions options = config::spotterOptions(config);
  options.onnx.intra_op_threads = std::max(1, config.pipeline.realtime.worker_inference_threads);
  return std::make_unique<ocr::PpOcrSpotter>(options);
}

}  // namespace parkloc::app
