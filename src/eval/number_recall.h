#pragma once
// Table 3 scores each camera image alone, but a localization works on the frame set, where
// a number that one camera misses another may find, and on the drive, where a number missed
// in one frame may be found in the next. Per group of images (a frame set, or a whole drive),
// each cared-for parking number counts once: found when some image of the group found it,
// read when some image found it and read it right.
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "eval/ocr_metrics.h"
#include "io/labels.h"
#include "ocr/text_spotter.h"

namespace parkloc::eval {

class NumberRecallTally {
 public:
  explicit NumberRecallTally(OcrEvaluationOptions options = {}) : options_(options) {}
  // One camera image of the group being tallied: its labels and what was spotted there.
  void addImage(const io::ImageLabels& labels, const std::vector<ocr::TextInstance>& found);
  // Closes the group: its numbers go into the result.
  void endGroup();
  const NumberRecall& result() const { return result_; }

 private:
  OcrEvaluationOptions options_;
  std::map<std::string, std::pair<bool, bool>> current_;  // landmark id -> found, read
  NumberRecall result_;
};

}  // namespace parkloc::eval
