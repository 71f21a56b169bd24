#include "eval/text_matching.h"

#include <algorithm>
#include <cassert>

namespace parkloc::eval {
namespace {

std::vector<cv::Point2f> toVector(const Quad& q) { return {q.begin(), q.end()}; }

}  // namespace

ImageMatching matchDetections(const std::vector<Quad>& truths, const std::vector<bool>& dont_care,
                              const std::vector<Quad>& detections, const MatchingOptions& options) {
  assert(dont_care.size() == truths.size());
  std::vector<MatchedPair> candidates;
  for (size_t t = 0; t < truths.size(); ++t) {
    if (dont_care[t]) continue;
    for (size_t d = 0; d < detections.size(); ++d) {
      const double iou = polygonIoU(truths[t], detections[d]);
      if (iou >= options.min_iou) candidates.push_back({t, d, iou});
    }
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const MatchedPair& a, const MatchedPair& b) { return a.iou > b.iou; });

  ImageMatching out;
  std::vector<bool> truth_used(truths.size(), false), detection_used(detections.size(), false);
  for (const MatchedPair& pair : candidates) {
    if (truth_used[pair.truth] || detection_used[pair.detection]) continue;
    truth_used[pair.truth] = detection_used[pair.detection] = true;
    out.matches.push_back(pair);
  }
  for (size_t t = 0; t < truths.size(); ++t) {
    if (!dont_care[t] && !truth_used[t]) out.missed_truths.push_back(t);
  }
  for (size_t d = 0; d < detections.size(); ++d) {
    if (detection_used[d]) continue;
    const std::vector<cv::Point2f> detection = toVector(detections[d]);
    const double own_area = polygonArea(detection);
    bool on_dont_care = false;
    for (size_t t = 0; t < truths.size() && !on_dont_care; ++t) {
      if (!dont_care[t]) continue;
      const double overlap = intersectionArea(detection, toVector(truths[t]));
      on_dont_care = (own_area > 0.0 && overlap / own_area > options.dont_care_min_coverage) ||
                     polygonIoU(detections[d], truths[t]) >= options.min_iou;
    }
    (on_dont_care ? out.ignored_detections : out.false_detections).push_back(d);
  }
  return out;
}

}  // namespace parkloc::eval
