#include "eval/text_matching.h"

#include <algorithm>
#include <cassert>
#include <optional>

namespace parkloc::eval {
namespace {

using geometry::clippedToImage;
using geometry::intersectionArea;
using geometry::polygonArea;
using geometry::polygonIoU;

// The polygons as compared: whole, or their parts inside the image.
std::vector<std::vector<cv::Point2f>> compared(const std::vector<Quad>& quads,
                                               const MatchingOptions& options) {
  std::vector<std::vector<cv::Point2f>> out;
  for (const Quad& q : quads) {
    std::vector<cv::Point2f> polygon(q.begin(), q.end());
    out.push_back(options.image_size ? clippedToImage(polygon, *options.image_size) : polygon);
  }
  return out;
}

}  // namespace

ImageMatching matchDetections(const std::vector<Quad>& truth_quads,
                              const std::vector<bool>& dont_care,
                              const std::vector<Quad>& detection_quads,
                              const MatchingOptions& options) {
  return matchDetections(truth_quads, {}, dont_care, detection_quads, options);
}

ImageMatching matchDetections(const std::vector<Quad>& truth_quads,
                              const std::vector<std::optional<Quad>>& alternative_quads,
                              const std::vector<bool>& dont_care,
                              const std::vector<Quad>& detection_quads,
                              const MatchingOptions& options) {
  assert(dont_care.size() == truth_quads.size());
  assert(alternative_quads.empty() || alternative_quads.size() == truth_quads.size());
  const auto truths = compared(truth_quads, options);
  const auto detections = compared(detection_quads, options);
  std::vector<std::optional<std::vector<cv::Point2f>>> alternatives(truths.size());
  for (size_t t = 0; t < alternative_quads.size(); ++t)
    if (alternative_quads[t]) alternatives[t] = compared({*alternative_quads[t]}, options).front();
  std::vector<MatchedPair> candidates, nearest(truths.size());
  for (size_t t = 0; t < truths.size(); ++t) {
    if (dont_care[t]) continue;
    for (size_t d = 0; d < detections.size(); ++d) {
      double iou = polygonIoU(truths[t], detections[d]);
      if (alternatives[t]) iou = std::max(iou, polygonIoU(*alternatives[t], detections[d]));
      if (iou >= options.min_iou) candidates.push_back({t, d, iou});
      if (iou > nearest[t].iou) nearest[t] = {t, d, iou};
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
    if (dont_care[t] || truth_used[t]) continue;
    out.missed_truths.push_back(t);
    if (nearest[t].iou > 0.0) out.nearest_to_missed.push_back(nearest[t]);
  }
  for (size_t d = 0; d < detections.size(); ++d) {
    if (detection_used[d]) continue;
    const std::vector<cv::Point2f>& detection = detections[d];
    const double own_area = polygonArea(detection);
    bool on_dont_care = false;
    for (size_t t = 0; t < truths.size() && !on_dont_care; ++t) {
      if (!dont_care[t]) continue;
      auto covers = [&](const std::vector<cv::Point2f>& truth) {
        const double overlap = intersectionArea(detection, truth);
        return (own_area > 0.0 && overlap / own_area > options.dont_care_min_coverage) ||
               polygonIoU(detection, truth) >= options.min_iou;
      };
      // As for a cared-for truth, the box may cover the part that shows or the whole.
      on_dont_care = covers(truths[t]) || (alternatives[t] && covers(*alternatives[t]));
    }
    (on_dont_care ? out.ignored_detections : out.false_detections).push_back(d);
  }
  return out;
}

}  // namespace parkloc::eval
