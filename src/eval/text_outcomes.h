#pragma once
// What became of each text of one labelled image under text spotting: every cared-for label,
// found or missed, and every false detection. Table 3 counts these; the outcomes name them,
// so that a developer can look at the misses and misreadings behind a rate
// (`parkloc eval ocr --outcomes FILE`).
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "eval/ocr_metrics.h"
#include "io/labels.h"
#include "ocr/text_spotter.h"

namespace parkloc::eval {

enum class OutcomeKind { kFound, kMissed, kFalseDetection };
std::string toString(OutcomeKind kind);  // "found", "missed", "false_detection"

struct TextOutcome {
  OutcomeKind kind = OutcomeKind::kMissed;
  int truth = -1;  // index into the labels' instances; -1 for a false detection
  // Index into the detections: the match, the false detection itself, or for a miss the
  // detection that overlaps it most (-1 when none does).
  int detection = -1;
  double iou = 0.0;  // of the match, or of that nearest detection
};

// The outcomes of one image, matched as OcrEvaluator::add matches it (same cared-for rule,
// same ICDAR matching); detections on don't-care regions have none.
std::vector<TextOutcome> textOutcomes(const io::ImageLabels& truth,
                                      const std::vector<ocr::TextInstance>& detections,
                                      const OcrEvaluationOptions& options = {});

// One outcome as a JSON object: the label's text, class, apparent height, occlusion and
// polygon, and the detection's reading, class and polygon, where each exists.
nlohmann::json outcomeJson(const TextOutcome& outcome, const io::ImageLabels& truth,
                           const std::vector<ocr::TextInstance>& detections);

}  // namespace parkloc::eval
