#include "eval/text_outcomes.h"

#include "geometry/text_polygon.h"
#include "io/polygon_points.h"

namespace parkloc::eval {
namespace {

nlohmann::json pointsJson(const Quad& quad) {
  nlohmann::json out = nlohmann::json::array();
  for (const cv::Point2f& p : quad) out.push_back({p.x, p.y});
  return out;
}

}  // namespace

std::string toString(OutcomeKind kind) {
  switch (kind) {
    case OutcomeKind::kFound:
      return "found";
    case OutcomeKind::kMissed:
      return "missed";
    case OutcomeKind::kFalseDetection:
      return "false_detection";
  }
  return "?";
}

std::vector<TextOutcome> textOutcomes(const io::ImageLabels& truth,
                                      const std::vector<ocr::TextInstance>& detections,
                                      const OcrEvaluationOptions& options) {
  const ImageMatching m = matchLabels(truth, detections, options);

  std::vector<TextOutcome> out;
  for (const MatchedPair& p : m.matches)
    out.push_back(
        {OutcomeKind::kFound, static_cast<int>(p.truth), static_cast<int>(p.detection), p.iou});
  for (size_t t : m.missed_truths) {
    TextOutcome miss{OutcomeKind::kMissed, static_cast<int>(t), -1, 0.0};
    for (const MatchedPair& n : m.nearest_to_missed)
      if (n.truth == t) miss.detection = static_cast<int>(n.detection), miss.iou = n.iou;
    out.push_back(miss);
  }
  for (size_t d : m.false_detections)
    out.push_back({OutcomeKind::kFalseDetection, -1, static_cast<int>(d), 0.0});
  return out;
}

nlohmann::json outcomeJson(const TextOutcome& outcome, const io::ImageLabels& truth,
                           const std::vector<ocr::TextInstance>& detections) {
  nlohmann::json j = {{"outcome", toString(outcome.kind)},
                      {"camera", truth.camera},
                      {"timestamp", truth.timestamp}};
  if (outcome.truth >= 0) {
    const io::LabelInstance& l = truth.instances.at(static_cast<size_t>(outcome.truth));
    j["text"] = l.text;
    j["class"] = map::toString(l.cls);
    j["landmark_id"] = l.landmark_id;
    j["height_px"] = geometry::apparentHeightPx(l.polygon);
    j["occluded_fraction"] = l.occluded_fraction;
    j["truncated"] = l.truncated;
    j["rotation_deg"] = l.rotation_deg;
    j["paint_wear"] = l.paint_wear;
    if (l.ink_snr) j["ink_snr"] = *l.ink_snr;
    j["polygon"] = pointsJson(io::pointQuad(l.polygon));
  }
  if (outcome.detection >= 0) {
    const ocr::TextInstance& d = detections.at(static_cast<size_t>(outcome.detection));
    j["iou"] = outcome.iou;
    j["detected"] = {{"text", d.text},
                     {"raw_text", d.raw_text},
                     {"lexicon_match", d.lexicon_match},
                     {"second_opinion", d.second_opinion},
                     {"partial", d.partial},
                     {"sized_by_map", d.sized_by_map},
                     {"class", map::toString(d.cls)},
                     {"detection_score", d.detection_score},
                     {"polygon", pointsJson(d.polygon)}};
  }
  return j;
}

}  // namespace parkloc::eval
