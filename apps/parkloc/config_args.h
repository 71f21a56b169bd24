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

// The workers' own spotters (localize/search_worker.h), each with the workers' inference
// threads; made after makeSpotter's, whose thread counts size ONNX Runtime's shared pool.
// A spotter is made only for a worker the configuration runs.
struct WorkerSpotterSet {
  std::unique_ptr<ocr::TextSpotter> search, reads;
  localize::WorkerSpotters pointers() const { return {search.get(), reads.get()}; }
};
inline WorkerSpotterSet makeWorkerSpotters(const config::Config& config) {
  const localize::RealtimeOptions& realtime = config.pipeline.realtime;
  WorkerSpotterSet out;
  if (config.pipeline.paper_mode) return out;
  ocr::PpOcrOptions options = config::spotterOptions(config);
  options.onnx.intra_op_threads = std::max(1, realtime.worker_inference_threads);
  if (realtime.background_search) out.search = std::make_unique<ocr::PpOcrSpotter>(options);
  if (realtime.background_reads) out.reads = std::make_unique<ocr::PpOcrSpotter>(options);
  return out;
}

}  // namespace parkloc::app
