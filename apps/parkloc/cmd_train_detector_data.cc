// parkloc train detector-data DATASET --out DIR : ground-view images and text polygons of a
// dataset split, to fine-tune the DB text detector on what the spotter feeds it.
#include <fmt/format.h>

#include <iostream>

#include "apps/parkloc/command.h"
#include "common/error.h"
#include "eval/dataset.h"
#include "ocr/detector_training_data.h"

namespace {

struct DetectorDataArgs {
  std::string dataset;
  std::string split = "train";
  std::string out;
  size_t stride = 1;
  size_t max_frames = 0;
  parkloc::ocr::GroundViewOptions view;
  std::vector<double> raw_band;  // empty: the floor view
};

void runDetectorData(const DetectorDataArgs& args) {
  using namespace parkloc;
  const auto sequences = eval::splitSequences(args.dataset, args.split);
  if (sequences.empty())
    throw InputError(fmt::format("{}: split \"{}\" has no sequences", args.dataset, args.split));
  ocr::DetectorDataOptions options;
  options.out_dir = args.out;
  options.view = args.view;
  if (!args.raw_band.empty()) {
    options.source = ocr::DetectorSource::kRawBand;
    options.band.top = args.raw_band[0];
    options.band.bottom = args.raw_band[1];
  }
  options.frame_stride = args.stride;
  options.max_frames_per_sequence = args.max_frames;
  options.progress = [](size_t done, size_t total) {
    std::cerr << fmt::format("\rdetector-data {}/{} sequences ", done, total) << std::flush;
  };
  const auto stats = ocr::writeDetectorTrainingData(sequences, options);
  std::cerr << "\n";
  std::cout << fmt::format("wrote {} images ({} care, {} don't-care instances) to {}\n",
                           stats.images, stats.care_instances, stats.dont_care_instances, args.out);
}

const bool registered = parkloc::app::registerCommand([](CLI::App& parent) {
  auto* train = parkloc::app::commandGroup(parent, "train", "Train the learned parts of parkloc");
  auto args = std::make_shared<DetectorDataArgs>();
  auto* cmd = train->add_subcommand(
      "detector-data", "Ground-view images and text polygons to fine-tune the text detector");
  cmd->add_option("dataset", args->dataset, "Dataset folder (with splits.json)")->required();
  cmd->add_option("--split", args->split, "Split to export")->capture_default_str();
  cmd->add_option("--out", args->out, "Output folder (images/, labels/, index.txt)")->required();
  cmd->add_option("--stride", args->stride, "Use every n-th frame set")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--max-frames", args->max_frames, "At most N frame sets per sequence (0: all)")
      ->capture_default_str();
  cmd->add_option("--resolution", args->view.resolution, "Ground view metres per pixel")
      ->capture_default_str();
  cmd->add_option("--near", args->view.near, "View starts this far ahead of the camera (m)")
      ->capture_default_str();
  cmd->add_option("--far", args->view.far, "View ends this far ahead of the camera (m)")
      ->capture_default_str();
  cmd->add_option("--half-width", args->view.half_width, "View extent to each side (m)")
      ->capture_default_str();
  cmd->add_option("--raw-band", args->raw_band,
                  "Export the raw image's horizon band instead of the floor view: its top and "
                  "bottom edges as radians from the optical axis, negative above it (e.g. "
                  "-0.9095 0.3078, the spotter's band)")
      ->expected(2);
  cmd->callback([args] { runDetectorData(*args); });
});

}  // namespace
