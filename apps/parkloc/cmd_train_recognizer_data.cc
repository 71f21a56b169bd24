// parkloc train recognizer-data DATASET --out DIR : rectified text crops of a dataset split
// with their texts, to fine-tune the CTC recognizer on what the spotter feeds it.
#include <fmt/format.h>

#include <iostream>

#include "apps/parkloc/command.h"
#include "common/error.h"
#include "eval/dataset.h"
#include "ocr/recognizer_training_data.h"

namespace {

struct RecognizerDataArgs {
  std::string dataset;
  std::string split = "train";
  parkloc::ocr::RecognizerDataOptions options;
};

void runRecognizerData(RecognizerDataArgs args) {
  using namespace parkloc;
  const auto sequences = eval::splitSequences(args.dataset, args.split);
  if (sequences.empty())
    throw InputError(fmt::format("{}: split \"{}\" has no sequences", args.dataset, args.split));
  args.options.progress = [](size_t done, size_t total) {
    std::cerr << fmt::format("\rrecognizer-data {}/{} sequences ", done, total) << std::flush;
  };
  const auto stats = ocr::writeRecognizerTrainingData(sequences, args.options);
  std::cerr << "\n";
  std::cout << fmt::format("wrote {} crops of {} texts to {}\n", stats.crops, stats.texts,
                           args.options.out_dir);
}

const bool registered = parkloc::app::registerCommand([](CLI::App& parent) {
  auto* train = parkloc::app::commandGroup(parent, "train", "Train the learned parts of parkloc");
  auto args = std::make_shared<RecognizerDataArgs>();
  auto& o = args->options;
  auto* cmd = train->add_subcommand(
      "recognizer-data", "Rectified text crops and their texts to fine-tune the recognizer");
  cmd->add_option("dataset", args->dataset, "Dataset folder (with splits.json)")->required();
  cmd->add_option("--split", args->split, "Split to export")->capture_default_str();
  cmd->add_option("--out", o.out_dir, "Output folder (crops/, index.tsv)")->required();
  cmd->add_option("--stride", o.frame_stride, "Use every n-th frame set")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--max-frames", o.max_frames_per_sequence,
                  "At most N frame sets per sequence (0: all)")
      ->capture_default_str();
  cmd->add_option("--variants", o.variants,
                  "Crops per parking number: the true box and jittered ones")
      ->check(CLI::Range(1, 20))
      ->capture_default_str();
  cmd->add_option("--other-class-variants", o.other_class_variants,
                  "Crops per pillar or other text (0: parking numbers only)")
      ->check(CLI::Range(0, 20))
      ->capture_default_str();
  cmd->add_option("--alphabet", o.alphabet, "Only texts of these characters ('' any)")
      ->capture_default_str();
  cmd->add_option("--seed", o.seed, "Seed of the box jitter")->capture_default_str();
  cmd->callback([args] { runRecognizerData(*args); });
});

}  // namespace
