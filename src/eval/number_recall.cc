#include "eval/number_recall.h"

#include "eval/text_outcomes.h"

namespace parkloc::eval {

void NumberRecallTally::addImage(const io::ImageLabels& labels,
                                 const std::vector<ocr::TextInstance>& found) {
  for (const TextOutcome& o : textOutcomes(labels, found, options_)) {
    if (o.truth < 0) continue;  // a false detection
    const io::LabelInstance& truth = labels.instances[static_cast<size_t>(o.truth)];
    if (truth.cls != map::TextClass::kParkingNumber) continue;
    // Numbers repeat on each level, so the landmark id names one; the text when it has none.
    auto& [was_found, was_read] =
        current_[truth.landmark_id.empty() ? truth.text : truth.landmark_id];
    if (o.kind != OutcomeKind::kFound) continue;
    was_found = true;
    was_read = was_read || found[static_cast<size_t>(o.detection)].text == truth.text;
  }
}

void NumberRecallTally::endGroup() {
  for (const auto& [id, outcome] : current_) {
    ++result_.numbers;
    result_.found += outcome.first;
    result_.read += outcome.second;
  }
  current_.clear();
}

}  // namespace parkloc::eval
