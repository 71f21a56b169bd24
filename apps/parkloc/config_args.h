#pragma once
// --config FILE and --models DIR, for every command that spots or localizes: the options come
// from the configuration (data/config/default.yaml, config/config.h), the command line keeps
// what changes per run.
#include <CLI/CLI.hpp>
#include <memory>
#include <string>

#include "config/config.h"
#include "config/spotters.h"

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

// The spotters: config/spotters.h.
using config::makeSpotter;
using config::makeWorkerSpotters;
using config::WorkerSpotterSet;

}  // namespace parkloc::app
