#pragma once
// Training data for the classification head from dataset sequences (`parkloc simulate`
// folders): per labelled text instance, its features taken from the labelled polygon and
// transcription, as the spotter will see a correctly read instance, and again without the
// text, as it sees a box that nothing could read.
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "ocr/text_classifier.h"

namespace parkloc::ocr {

struct ClassifierSamples {
  cv::Mat features;  // CV_32F, one row per sample
  std::vector<map::TextClass> labels;
  std::vector<bool> unread;  // the sample's text is empty (an unread box)
};

enum class SampleText { kRead, kUnread, kBoth };

// Whether `text` gives the unread (true) or the read (false) sample of an instance.
inline bool givesSample(SampleText text, bool unread) {
  return text == SampleText::kBoth || (text == SampleText::kUnread) == unread;
}

struct SampleOptions {
  ClassifierFeatureOptions features;
  double max_occluded_fraction = 0.5;  // the targets' "less than half occluded"
  size_t frame_stride = 1;             // use every n-th frame set
  size_t max_frames_per_sequence = 0;  // 0: all
  // Which samples an instance gives: its box as read (the labelled text), as an unread box
  // (empty text: the spotter reports boxes its floor detector is sure of even when no
  // reading is, DetectionOptions::confident_box_score), or both.
  SampleText text = SampleText::kRead;
  std::function<void(size_t done, size_t total)> progress;  // per sequence
};

// Reads the sequences' images and labels; throws InputError for unreadable sequences.
ClassifierSamples collectClassifierSamples(const std::vector<std::string>& sequence_dirs,
                                           const SampleOptions& options);

struct ClassifierScore {
  size_t samples = 0;
  size_t correct = 0;
  // confusion[truth][predicted], classes in TextClass order.
  size_t confusion[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  double accuracy() const { return samples ? double(correct) / samples : 0.0; }
  double classAccuracy(map::TextClass c) const;
};

// Over every sample, or only the read (`unread` false) or unread ones.
ClassifierScore scoreClassifier(const TextClassifier& classifier, const ClassifierSamples& samples,
                                std::optional<bool> unread = std::nullopt);

}  // namespace parkloc::ocr
