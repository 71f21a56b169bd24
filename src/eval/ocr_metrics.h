#pragma once
// Text spotting metrics of the paper's Table 3, accumulated image by image: detection
// TP / FP / FN (ICDAR-2015 matching at IoU 0.5), mean IoU of the matches, recognition
// accuracy (exact string, raw CTC reading and after lexicon decoding) and classification
// accuracy over the matched instances; overall, per text class and per condition subset.
#include <map>
#include <string>
#include <vector>

#include "eval/text_matching.h"
#include "io/labels.h"
#include "ocr/text_spotter.h"

namespace parkloc::eval {

struct OcrCounts {
  size_t truths = 0;      // cared-for ground-truth instances
  size_t detections = 0;  // detections not ignored on don't-care regions
  size_t tp = 0, fp = 0, fn = 0;
  double iou_sum = 0.0;                                       // over the TP matches
  size_t recognized_raw = 0, recognized = 0, classified = 0;  // among the TP matches

  // Rates as Table 3 reads them: TP and FN per ground-truth instance, FP per detection.
  double tpRate() const { return ratio(tp, truths); }
  double fnRate() const { return ratio(fn, truths); }
  double fpRate() const { return ratio(fp, detections); }
  double precision() const { return ratio(tp, tp + fp); }
  double recall() const { return ratio(tp, tp + fn); }
  double fMeasure() const;
  double meanIoU() const { return tp ? iou_sum / static_cast<double>(tp) : 0.0; }
  double recognitionRawAccuracy() const { return ratio(recognized_raw, tp); }
  double recognitionAccuracy() const { return ratio(recognized, tp); }
  double classificationAccuracy() const { return ratio(classified, tp); }
  // Share of all cared-for instances both found and read correctly (end to end).
  double endToEndAccuracy() const { return ratio(recognized, truths); }

  OcrCounts& operator+=(const OcrCounts& other);

 private:
  static double ratio(size_t a, size_t b) {
    return b ? static_cast<double>(a) / static_cast<double>(b) : 0.0;
  }
};

// Per group of images (a frame set, a drive), each cared-for parking number counted once
// (eval/number_recall.h).
struct NumberRecall {
  size_t numbers = 0;  // (group, parking number) pairs cared for in some image of the group
  size_t found = 0;    // ... found in some image of the group
  size_t read = 0;     // ... found and read right in some image of the group
  double foundShare() const { return numbers ? static_cast<double>(found) / numbers : 0.0; }
  double readShare() const { return numbers ? static_cast<double>(read) / numbers : 0.0; }
};

struct OcrEvaluation {
  OcrCounts overall;
  std::map<std::string, OcrCounts> by_class;      // "parking_number", "pillar", "other"
  std::map<std::string, OcrCounts> by_condition;  // names of conditionNames()
  // The parking numbers alone per condition subset (the looks and bird's-eye orientations
  // report these).
  std::map<std::string, OcrCounts> parking_numbers_by_condition;
  // Parking numbers by apparent height in the image (heightBin): what the size of a
  // number costs.
  std::map<std::string, OcrCounts> parking_numbers_by_height;
  // Parking numbers by their paint (paintBin of io::LabelInstance::paint_wear): intact or worn.
  // A false detection has no paint and counts in none.
  std::map<std::string, OcrCounts> parking_numbers_by_paint;
  // Parking numbers in full sight and partly hidden (sightBin): a raw reading can be exact
  // only where every character shows. A false detection counts in neither.
  std::map<std::string, OcrCounts> parking_numbers_by_sight;
  // Parking numbers by how far their ink stands out of the sensor's noise (inkBin of
  // io::LabelInstance::ink_snr); labels without it count in none.
  std::map<std::string, OcrCounts> parking_numbers_by_ink;
  // Per class, with every text at least kHeightRuleMinPx tall cared for (unless half
  // occluded), whatever its label's legibility: a height-only rule, reported beside the
  // labels' legible flag (which also weighs the pitch along the reading direction and the
  // camera's blur) to show how much the choice of rule moves the figures.
  std::map<std::string, OcrCounts> height_rule_by_class;
  // Parking numbers per frame set, found or read in some camera's image
  // (eval/number_recall.h; filled by evaluateOcr, empty from OcrEvaluator alone).
  NumberRecall parking_numbers_per_frame_set;
  // ... and per drive: the numbers a drive finds and reads in some image at all.
  NumberRecall parking_numbers_per_drive;
  size_t images = 0;
  double spotting_seconds = 0.0;  // time spent in the engine, for images per second
  double imagesPerSecond() const {
    return spotting_seconds > 0.0 ? static_cast<double>(images) / spotting_seconds : 0.0;
  }
};

// The apparent height from which the height-only rule cares for a text.
inline constexpr double kHeightRuleMinPx = 8.0;

struct OcrEvaluationOptions {
  MatchingOptions matching;
  // Instances at least this much occluded are "don't care" (the targets count instances
  // less than half occluded).
  double dont_care_occlusion = 0.5;
  // Compare polygons by their parts inside the image (MatchingOptions::image_size): a
  // number cut by the border is found when its visible part is. False: whole polygons.
  bool inside_image_only = true;
};

// The matching options for one labelled image.
MatchingOptions matchingFor(const OcrEvaluationOptions& options, const io::ImageLabels& labels);

// The polygon a detection is matched against: the part the image shows for text cut by the
// image's edge or partly hidden (io::LabelInstance::visible_polygon) when `inside_image_only`,
// else the label's.
Quad matchedPolygon(const io::LabelInstance& instance, const OcrEvaluationOptions& options);
// The other polygon a detection may match: the whole text's where matchedPolygon is the part
// that shows (a detector may box either); empty otherwise.
std::optional<Quad> alternativePolygon(const io::LabelInstance& instance,
                                       const OcrEvaluationOptions& options);

// Whether a label counts in the tables: legible and less than dont_care_occlusion occluded.
bool caredFor(const io::LabelInstance& instance, const OcrEvaluationOptions& options);

// One image's detections matched to its labels as the tables match them: each label by its
// matchedPolygon or alternativePolygon, those not caredFor as don't care.
ImageMatching matchLabels(const io::ImageLabels& labels,
                          const std::vector<ocr::TextInstance>& detections,
                          const OcrEvaluationOptions& options);

// The bins of OcrEvaluation::parking_numbers_by_height, in increasing order, and the bin of
// an apparent height (geometry::apparentHeightPx, the simulator's legibility measure).
const std::vector<std::string>& heightBins();
const std::string& heightBin(double height_px);

// The bins of OcrEvaluation::parking_numbers_by_paint and the bin of a label's paint wear.
const std::vector<std::string>& paintBins();
const std::string& paintBin(double paint_wear);

// The bins of OcrEvaluation::parking_numbers_by_sight and the bin of a label: partly hidden
// when anything occludes part of it or the image's edge cuts it.
const std::vector<std::string>& sightBins();
const std::string& sightBin(const io::LabelInstance& instance);

// The bins of OcrEvaluation::parking_numbers_by_ink, in increasing order, and the bin of a
// label's ink SNR (sim::featureSnr; 5 is the labels' legibility floor).
const std::vector<std::string>& inkBins();
const std::string& inkBin(double ink_snr);

// Reading direction of a polygon in the image, degrees in (-180, 180] (0 = left to right),
// the same convention as io::LabelInstance::rotation_deg.
double readingAngleDeg(const Quad& polygon);

class OcrEvaluator {
 public:
  explicit OcrEvaluator(OcrEvaluationOptions options = {}) : options_(options) {}

  // One image: its labels, what the engine found, the sequence's conditions (bright,
  // weak_light, blur) and the seconds the engine took.
  void add(const io::ImageLabels& truth, const std::vector<ocr::TextInstance>& detections,
           const std::vector<std::string>& image_conditions, double spotting_seconds = 0.0);
  const OcrEvaluation& result() const { return result_; }

 private:
  OcrEvaluationOptions options_;
  OcrEvaluation result_;
};

}  // namespace parkloc::eval
