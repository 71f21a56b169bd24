#include "eval/ocr_metrics.h"

#include <cmath>

#include "eval/conditions.h"
#include "geometry/text_polygon.h"
#include "io/polygon_points.h"

namespace parkloc::eval {
double OcrCounts::fMeasure() const {
  const double p = precision(), r = recall();
  return p + r > 0.0 ? 2.0 * p * r / (p + r) : 0.0;
}

OcrCounts& OcrCounts::operator+=(const OcrCounts& o) {
  truths += o.truths;
  detections += o.detections;
  tp += o.tp;
  fp += o.fp;
  fn += o.fn;
  iou_sum += o.iou_sum;
  recognized_raw += o.recognized_raw;
  recognized += o.recognized;
  classified += o.classified;
  return *this;
}

const std::vector<std::string>& heightBins() {
  static const std::vector<std::string> kBins = {"under 8 px", "8-12 px", "12-16 px", "16-24 px",
                                                 "24 px and more"};
  return kBins;
}

const std::string& heightBin(double h) {
  const auto& bins = heightBins();
  const size_t i = h < 8.0 ? 0 : h < 12.0 ? 1 : h < 16.0 ? 2 : h < 24.0 ? 3 : 4;
  return bins[i];
}

const std::vector<std::string>& paintBins() {
  static const std::vector<std::string> kBins = {"intact paint", "worn paint"};
  return kBins;
}

const std::string& paintBin(double paint_wear) { return paintBins()[paint_wear > 0.0 ? 1 : 0]; }

const std::vector<std::string>& sightBins() {
  static const std::vector<std::string> kBins = {"in full sight", "partly hidden"};
  return kBins;
}

const std::string& sightBin(const io::LabelInstance& instance) {
  return sightBins()[instance.occluded_fraction > 0.0 || instance.truncated ? 1 : 0];
}

const std::vector<std::string>& inkBins() {
  static const std::vector<std::string> kBins = {"ink SNR under 8", "ink SNR 8-12", "ink SNR 12-20",
                                                 "ink SNR 20 and more"};
  return kBins;
}

const std::string& inkBin(double ink_snr) {
  const auto& bins = inkBins();
  return bins[ink_snr < 8.0 ? 0 : ink_snr < 12.0 ? 1 : ink_snr < 20.0 ? 2 : 3];
}

double readingAngleDeg(const Quad& polygon) {
  // Mid-point of the left edge to mid-point of the right edge: the reading direction.
  const cv::Point2d left = 0.5 * (cv::Point2d(polygon[0]) + cv::Point2d(polygon[3]));
  const cv::Point2d right = 0.5 * (cv::Point2d(polygon[1]) + cv::Point2d(polygon[2]));
  return std::atan2(right.y - left.y, right.x - left.x) * 180.0 / M_PI;
}

MatchingOptions matchingFor(const OcrEvaluationOptions& options, const io::ImageLabels& labels) {
  MatchingOptions out = options.matching;
  if (options.inside_image_only && labels.width > 0 && labels.height > 0)
    out.image_size = cv::Size(labels.width, labels.height);
  return out;
}

Quad matchedPolygon(const io::LabelInstance& instance, const OcrEvaluationOptions& options) {
  if (options.inside_image_only && instance.visible_polygon)
    return io::pointQuad(*instance.visible_polygon);
  return io::pointQuad(instance.polygon);
}

std::optional<Quad> alternativePolygon(const io::LabelInstance& instance,
                                       const OcrEvaluationOptions& options) {
  if (options.inside_image_only && instance.visible_polygon) return io::pointQuad(instance.polygon);
  return std::nullopt;
}

bool caredFor(const io::LabelInstance& instance, const OcrEvaluationOptions& options) {
  return instance.legible && instance.occluded_fraction < options.dont_care_occlusion;
}

ImageMatching matchLabels(const io::ImageLabels& labels,
                          const std::vector<ocr::TextInstance>& detections,
                          const OcrEvaluationOptions& options) {
  std::vector<Quad> truth_quads, detection_quads;
  std::vector<std::optional<Quad>> alternative_quads;
  std::vector<bool> dont_care;
  for (const io::LabelInstance& instance : labels.instances) {
    truth_quads.push_back(matchedPolygon(instance, options));
    alternative_quads.push_back(alternativePolygon(instance, options));
    dont_care.push_back(!caredFor(instance, options));
  }
  for (const ocr::TextInstance& d : detections) detection_quads.push_back(d.polygon);
  return matchDetections(truth_quads, alternative_quads, dont_care, detection_quads,
                         matchingFor(options, labels));
}

namespace {

// The counts of one image's matching: each cared-for truth, match, miss and false detection
// goes to every tally `buckets(class, polygon, label or nullptr)` names.
template <typename Buckets>
void countMatching(const io::ImageLabels& truth, const std::vector<ocr::TextInstance>& detections,
                   const std::vector<Quad>& truth_quads, const std::vector<Quad>& detection_quads,
                   const std::vector<bool>& dont_care, const ImageMatching& matching,
                   const Buckets& buckets) {
  for (size_t t = 0; t < truth.instances.size(); ++t) {
    if (dont_care[t]) continue;
    const io::LabelInstance& gt = truth.instances[t];
    for (OcrCounts* c : buckets(gt.cls, truth_quads[t], &gt)) ++c->truths;
  }
  for (const MatchedPair& m : matching.matches) {
    const io::LabelInstance& gt = truth.instances[m.truth];
    const ocr::TextInstance& d = detections[m.detection];
    const std::string& raw = d.raw_text.empty() ? d.text : d.raw_text;
    for (OcrCounts* c : buckets(gt.cls, truth_quads[m.truth], &gt)) {
      ++c->detections;
      ++c->tp;
      c->iou_sum += m.iou;
      c->recognized_raw += raw == gt.text;
      c->recognized += d.text == gt.text;
      c->classified += d.cls == gt.cls;
    }
  }
  for (size_t t : matching.missed_truths) {
    const io::LabelInstance& gt = truth.instances[t];
    for (OcrCounts* c : buckets(gt.cls, truth_quads[t], &gt)) ++c->fn;
  }
  // A false detection has no truth: its predicted class and its own reading angle place it.
  for (size_t d : matching.false_detections) {
    for (OcrCounts* c : buckets(detections[d].cls, detection_quads[d], nullptr)) {
      ++c->detections;
      ++c->fp;
    }
  }
}

}  // namespace

void OcrEvaluator::add(const io::ImageLabels& truth,
                       const std::vector<ocr::TextInstance>& detections,
                       const std::vector<std::string>& image_conditions, double spotting_seconds) {
  std::vector<Quad> truth_quads, matched_quads, detection_quads;
  std::vector<std::optional<Quad>> alternative_quads;
  std::vector<bool> dont_care, dont_care_by_height;
  for (const io::LabelInstance& instance : truth.instances) {
    truth_quads.push_back(io::pointQuad(instance.polygon));
    matched_quads.push_back(matchedPolygon(instance, options_));
    alternative_quads.push_back(alternativePolygon(instance, options_));
    const bool occluded = instance.occluded_fraction >= options_.dont_care_occlusion;
    dont_care.push_back(!caredFor(instance, options_));
    dont_care_by_height.push_back(occluded ||
                                  geometry::apparentHeightPx(instance.polygon) < kHeightRuleMinPx);
  }
  for (const ocr::TextInstance& d : detections) detection_quads.push_back(d.polygon);

  // Every count goes to the overall tally, its class and each subset it belongs to.
  auto buckets = [&](map::TextClass cls, const Quad& polygon, const io::LabelInstance* label) {
    std::vector<OcrCounts*> out = {&result_.overall, &result_.by_class[map::toString(cls)]};
    for (const std::string& c : image_conditions) out.push_back(&result_.by_condition[c]);
    const double angle = label ? label->rotation_deg : readingAngleDeg(polygon);
    if (const auto rot = rotationSubset(angle)) out.push_back(&result_.by_condition[*rot]);
    if (cls == map::TextClass::kParkingNumber) {
      for (const std::string& c : image_conditions)
        out.push_back(&result_.parking_numbers_by_condition[c]);
      out.push_back(&result_.parking_numbers_by_height[heightBin(
          geometry::apparentHeightPx(io::textPolygon(polygon)))]);
      if (label) {
        out.push_back(&result_.parking_numbers_by_paint[paintBin(label->paint_wear)]);
        out.push_back(&result_.parking_numbers_by_sight[sightBin(*label)]);
      }
      if (label && label->ink_snr)
        out.push_back(&result_.parking_numbers_by_ink[inkBin(*label->ink_snr)]);
    }
    return out;
  };
  const MatchingOptions matching = matchingFor(options_, truth);
  countMatching(
      truth, detections, truth_quads, detection_quads, dont_care,
      matchDetections(matched_quads, alternative_quads, dont_care, detection_quads, matching),
      buckets);

  auto by_class = [&](map::TextClass cls, const Quad&, const io::LabelInstance*) {
    return std::vector<OcrCounts*>{&result_.height_rule_by_class[map::toString(cls)]};
  };
  countMatching(truth, detections, truth_quads, detection_quads, dont_care_by_height,
                matchDetections(matched_quads, alternative_quads, dont_care_by_height,
                                detection_quads, matching),
                by_class);
  ++result_.images;
  result_.spotting_seconds += spotting_seconds;
}

}  // namespace parkloc::eval
