#pragma once
// Table 3 scores each camera image alone, but a localization works on the frame set, where
// a number that one camera misses another may find. Per frame set, each cared-for parking
// number counts once: found when some camera's image found it, read when some camera found
// it and read it right.
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "eval/ocr_metrics.h"
#include "io/labels.h"
#include "ocr/text_spotter.h"

namespace parkloc::eval {

class FrameSetRecallTally {
 public:
  explicit FrameSetRecallTally(OcrEvaluationOptions options = {}) : options_(options) {}
  // One camera image of the frame set being tallied: its labels and what was spotted there.
  void addImage(const io::ImageLabels& labels, const std::vector<ocr::TextInstance>& found);
  // Closes the frame set: its numbers go into the result.
  void endFrameSet();
  const FrameSetRecall& result() const { return result_; }

 private:
  OcrEvaluationOptions options_;
  std::map<std::string, std::pair<bool, bool>> current_;  // landmark id -> found, read
  FrameSetRecall result_;
};

}  // namespace parkloc::eval
