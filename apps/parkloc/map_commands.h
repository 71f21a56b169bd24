#pragma once
// Subcommands that join a group another file creates: `map build` (cmd_map_build.cc) under
// `map`, `eval map` (cmd_eval_map.cc) and `eval photos` (cmd_eval_photos.cc) under `eval`.
#include <CLI/CLI.hpp>

namespace parkloc::app {

CLI::App* addMapBuild(CLI::App& map);
CLI::App* addEvalMap(CLI::App& eval);
CLI::App* addEvalPhotos(CLI::App& eval);

}  // namespace parkloc::app
