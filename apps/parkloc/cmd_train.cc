// parkloc train classifier DATASET --out FILE : the classification head (pillar / parking
// number / other) from the dataset's train split, scored on the val split.
#include <fmt/format.h>

#include <iostream>

#include "apps/parkloc/command.h"
#include "common/error.h"
#include "eval/dataset.h"
#include "ocr/classifier_training.h"

namespace {

struct TrainArgs {
  std::string dataset;
  std::string out = "models/text_classifier.yml";
  float ratio = 2.f;
  std::vector<float> compare_ratios;
  size_t stride = 1;
  size_t max_frames = 0;
  int hidden = 8;
  std::string text = "read";
  std::string eval_split = "val";
};

void printScore(const std::string& what, const parkloc::ocr::ClassifierScore& s) {
  using parkloc::map::TextClass;
  std::cout << fmt::format(
      "{}: accuracy {:.4f} on {} instances (pillar {:.4f}, parking number {:.4f}, other {:.4f})\n",
      what, s.accuracy(), s.samples, s.classAccuracy(TextClass::kPillar),
      s.classAccuracy(TextClass::kParkingNumber), s.classAccuracy(TextClass::kOther));
}

parkloc::ocr::TextClassifier trainAndScore(const TrainArgs& args, float ratio, bool save) {
  using namespace parkloc;
  ocr::SampleOptions options;
  options.features.expand_ratio = ratio;
  options.frame_stride = args.stride;
  options.max_frames_per_sequence = args.max_frames;
  options.text = args.text == "unread" ? ocr::SampleText::kUnread
                 : args.text == "both" ? ocr::SampleText::kBoth
                                       : ocr::SampleText::kRead;
  const auto train =
      ocr::collectClassifierSamples(eval::splitSequences(args.dataset, "train"), options);
  if (train.labels.empty())
    throw InputError("no labelled instances in the train split of " + args.dataset);
  ocr::ClassifierTrainOptions train_options;
  train_options.hidden_units = args.hidden;
  auto classifier =
      ocr::TextClassifier::train(train.features, train.labels, options.features, train_options);
  printScore(fmt::format("ratio {} train", ratio), ocr::scoreClassifier(classifier, train));
  const auto held_out =
      ocr::collectClassifierSamples(eval::splitSequences(args.dataset, args.eval_split), options);
  for (const bool unread : {false, true})
    if (ocr::givesSample(options.text, unread))
      printScore(fmt::format("ratio {} {}, {}", ratio, args.eval_split, unread ? "unread" : "read"),
                 ocr::scoreClassifier(classifier, held_out, unread));
  if (save) {
    classifier.save(args.out);
    std::cout << "wrote " << args.out << "\n";
  }
  return classifier;
}

const bool registered = parkloc::app::registerCommand([](CLI::App& parent) {
  auto* train = parkloc::app::commandGroup(parent, "train", "Train the learned parts of parkloc");
  auto args = std::make_shared<TrainArgs>();
  auto* cmd = train->add_subcommand(
      "classifier", "Text class head (pillar / parking number / other) from a dataset");
  cmd->add_option("dataset", args->dataset, "Dataset folder (with splits.json)")->required();
  cmd->add_option("--out", args->out, "Classifier file to write (YAML)")->capture_default_str();
  cmd->add_option("--ratio", args->ratio, "Box expansion ratio (the paper's 2)")
      ->capture_default_str();
  cmd->add_option("--compare-ratio", args->compare_ratios,
                  "Also train and score these ratios (ablation; not saved)");
  cmd->add_option("--stride", args->stride, "Use every n-th frame set")->capture_default_str();
  cmd->add_option("--max-frames", args->max_frames, "At most N frame sets per sequence (0: all)")
      ->capture_default_str();
  cmd->add_option("--hidden", args->hidden, "Hidden units of the MLP")->capture_default_str();
  cmd->add_option("--text", args->text,
                  "Samples: 'read' (the labelled text), 'unread' (no text: the head for boxes "
                  "nothing could read) or 'both'")
      ->check(CLI::IsMember({"read", "unread", "both"}))
      ->capture_default_str();
  cmd->add_option("--eval-split", args->eval_split, "Split to score on")->capture_default_str();
  cmd->callback([args] {
    trainAndScore(*args, args->ratio, true);
    for (float r : args->compare_ratios) trainAndScore(*args, r, false);
  });
});

}  // namespace
