#include <fmt/format.h>

#include <chrono>
#include <iostream>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include "apps/parkloc/command.h"

#include "common/error.h"
#include "io/calibration_yaml.h"
#include "io/sequence.h"
#include "sim/contact_sheet.h"
#include "sim/dataset_writer.h"
#include "sim/scenario.h"

namespace {

struct SimulateArgs {
  std::string scenario;
  std::string calib;
  std::string out;
  long long seed = -1;
  int max_sequences = -1;
  std::vector<std::string> splits;
  int max_frames = -1;
  int jobs = 1;
  bool birdseye = false;
  double birdseye_scale = parkloc::sim::DatasetOptions{}.birdseye_metres_per_pixel;
  bool quiet = false;
};

void runSimulate(const SimulateArgs& a) {
  using namespace parkloc;
  const sim::Scenario scenario =
      a.scenario.empty() ? sim::defaultScenario() : sim::loadScenario(a.scenario);
  sim::DatasetOptions options;
  options.out_dir = a.out;
  if (!a.calib.empty()) options.rig = io::loadCalibration(a.calib);
  if (a.seed >= 0) options.seed = static_cast<uint64_t>(a.seed);
  options.max_sequences = a.max_sequences;
  options.splits = a.splits;
  options.max_frames = a.max_frames;
  options.jobs = a.jobs;
  options.birdseye = a.birdseye;
  options.birdseye_metres_per_pixel = a.birdseye_scale;
  const auto start = std::chrono::steady_clock::now();
  auto bar = [&](size_t done, size_t total) {
    if (a.quiet) return;
    const double frac = total ? static_cast<double>(done) / total : 1.0;
    const int width = 40;
    const int filled = static_cast<int>(frac * width);
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double eta = frac > 0 ? elapsed / frac - elapsed : 0.0;
    std::cerr << fmt::format("\rsimulate [{}{}] {}/{} frame sets, {:.0f} s, eta {:.0f} s ",
                             std::string(filled, '#'), std::string(width - filled, '.'), done,
                             total, elapsed, eta)
              << std::flush;
  };
  const sim::DatasetStats s = sim::writeDataset(scenario, options, bar);
  if (!a.quiet) std::cerr << "\n";
  std::cout << fmt::format("wrote {} sequences, {} frame sets, {} images to {}\n", s.sequences,
                           s.frame_sets, s.images, a.out);
  std::cout << fmt::format(
      "instances: pillar {}, parking_number {}, other {} (occluded >= 0.5: {}, truncated: {}; "
      "labelled too thin to read: {})\n",
      s.instances_per_class[0], s.instances_per_class[1], s.instances_per_class[2],
      s.occluded_instances, s.truncated_instances, s.illegible_instances);
  for (const auto& [k, v] : s.images_per_split)
    std::cout << fmt::format("split {}: {} images\n", k, v);
  for (const auto& [k, v] : s.images_per_condition)
    std::cout << fmt::format(
        "condition {}: {} images, {} instances\n", k, v,
        s.instances_per_condition.count(k) ? s.instances_per_condition.at(k) : 0);
  for (const auto& [k, v] : s.instances_per_rotation)
    std::cout << fmt::format("rotation {}: {} instances\n", k, v);
  std::cout << fmt::format("time: {:.1f} s wall, {:.1f} ms per frame set per job\n", s.wall_seconds,
                           s.frame_sets ? 1000.0 * s.render_seconds / s.frame_sets : 0.0);
}

struct SheetArgs {
  std::string dataset;
  std::string out;
  int per_sequence = 1;
  int max_rows = 12;
  int tile_width = 480;
  bool labels = false;
  std::vector<std::string> sequences;
};

// Picks frames spread over each sequence (or the listed ones) and writes one PNG.
void runSheet(const SheetArgs& a) {
  namespace fs = std::filesystem;
  using namespace parkloc;
  const fs::path root = fs::path(a.dataset) / "sequences";
  if (!fs::is_directory(root)) throw InputError("sheet: " + root.string() + " is not a folder");
  std::vector<std::string> names = a.sequences;
  if (names.empty()) {
    for (const auto& e : fs::directory_iterator(root))
      if (e.is_directory()) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
  }
  std::vector<sim::ContactSheetRow> rows;
  for (const auto& name : names) {
    const fs::path dir = root / name;
    std::vector<double> stamps;
    const std::string first_camera =
        io::loadCalibration((dir / "calib.yaml").string()).cameras.front().name;
    for (const auto& e : fs::directory_iterator(dir / "images" / first_camera))
      stamps.push_back(std::stod(e.path().stem().string()));
    std::sort(stamps.begin(), stamps.end());
    if (stamps.empty()) continue;
    std::string condition;
    std::ifstream meta(dir / "meta.json");
    if (meta) {
      const nlohmann::json j = nlohmann::json::parse(meta, nullptr, false);
      condition = j.value("condition", "");
      // The drive's look, where the dataset names one (sim/appearance.h).
      if (j.is_object() && j.contains("appearance") && j["appearance"].is_object())
        condition += "  " + j["appearance"].value("subset", "");
    }
    for (int k = 0; k < a.per_sequence; ++k) {
      const size_t i = (stamps.size() - 1) * (2 * k + 1) / (2 * a.per_sequence);
      rows.push_back(
          {dir.string(), stamps[i], fmt::format("{}  t={:.1f} s  {}", name, stamps[i], condition)});
    }
  }
  if (static_cast<int>(rows.size()) > a.max_rows) rows.resize(a.max_rows);
  if (rows.empty()) throw InputError("sheet: no frames under " + root.string());
  // The cameras of the first row's rig, in its calibration's order.
  std::vector<std::string> cameras;
  for (const auto& camera :
       io::loadCalibration((fs::path(rows.front().sequence_dir) / "calib.yaml").string()).cameras)
    cameras.push_back(camera.name);
  const cv::Mat sheet = sim::makeContactSheet(rows, cameras, a.tile_width, a.labels);
  // JPEG at 85: small enough for the docs, no visible loss at the sheet's scale.
  if (!cv::imwrite(a.out, sheet, {cv::IMWRITE_JPEG_QUALITY, 85}))
    throw IoError("sheet: cannot write " + a.out);
  std::cout << fmt::format("wrote {} ({} rows)\n", a.out, rows.size());
}

const bool registered_sheet = parkloc::app::registerCommand([](CLI::App& parent) {
  auto args = std::make_shared<SheetArgs>();
  auto* cmd = parent.add_subcommand("sheet",
                                    "Contact sheet (PNG or JPEG) of frames of a simulated dataset");
  cmd->add_option("--dataset", args->dataset, "Dataset folder (holds sequences/)")->required();
  cmd->add_option("--out", args->out, "Output image (.png or .jpg)")->required();
  cmd->add_option("--per-sequence", args->per_sequence, "Frame sets per sequence")
      ->check(CLI::Range(1, 50));
  cmd->add_option("--max-rows", args->max_rows, "At most this many rows")
      ->check(CLI::Range(1, 200));
  cmd->add_option("--sequence", args->sequences, "Only these sequences (repeatable)");
  cmd->add_flag("--labels", args->labels, "Draw the label polygons");
  cmd->add_option("--tile-width", args->tile_width, "Width of each camera's image in pixels")
      ->check(CLI::Range(64, 1280))
      ->capture_default_str();
  cmd->callback([args] { runSheet(*args); });
});

const bool registered = parkloc::app::registerCommand([](CLI::App& parent) {
  auto args = std::make_shared<SimulateArgs>();
  auto* cmd = parent.add_subcommand(
      "simulate", "Generate the synthetic garage dataset (images, labels, maps, poses, odometry)");
  cmd->add_option("--scenario", args->scenario,
                  "Scenario YAML (default: the built-in default scenario)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--calib", args->calib,
                  "Rig calibration YAML to record with (2 to 6 cameras, any model and image "
                  "size), in place of the scenario's rig")
      ->check(CLI::ExistingFile);
  cmd->add_option("--out", args->out, "Output folder")->required();
  cmd->add_option("--seed", args->seed,
                  "Seed replacing the scenario's (every random choice changes)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--max-sequences", args->max_sequences, "Write at most N sequences");
  cmd->add_option("--split", args->splits,
                  "Only the sequences of this split (train, val, test; repeatable), with the "
                  "same garages as in the whole dataset");
  cmd->add_option("--max-frames", args->max_frames, "Write at most N frame sets per sequence");
  cmd->add_option("--jobs", args->jobs, "Sequences rendered in parallel")->check(CLI::Range(1, 64));
  cmd->add_flag("--birdseye", args->birdseye,
                "Also write each frame set's stitched top-down (AVM) image and its labels "
                "(<sequence>/birdseye/)");
  cmd->add_option("--birdseye-scale", args->birdseye_scale,
                  "Metres per pixel of the top-down images");
  cmd->add_flag("--quiet", args->quiet, "No progress bar");
  cmd->callback([args] { runSimulate(*args); });
});

}  // namespace
