#pragma once
// The paper's tables, filled from measured results: Table 3 (text spotting and the anomaly
// filter), Table 5 (accuracy and latency against other positioning), Table 8 (position error
// per condition) and Table 10 (ablation of AFM / MCRP / MCAP).
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "eval/ocr_metrics.h"
#include "eval/report.h"

namespace parkloc::eval {

// What the paper's anomaly filter did to the parking numbers read on full frames: a reading
// is an anomaly when it is not the labelled text of a real instance (a misreading or a
// false detection). Table 3's "Filter Accuracy" is the share of anomalies removed, its
// "Overall Recognition Accuracy" the share of correct readings among those kept.
struct AnomalyFilterCounts {
  size_t readings = 0;            // parking-number readings offered to the filter
  size_t anomalies = 0;           // of which wrong
  size_t anomalies_rejected = 0;  // wrong and rejected (not in map, box-plot outlier)
  size_t kept = 0;                // accepted by the filter
  size_t kept_correct = 0;        // accepted and right
  double filterAccuracy() const { return ratio(anomalies_rejected, anomalies); }
  double overallRecognitionAccuracy() const { return ratio(kept_correct, kept); }

 private:
  static double ratio(size_t a, size_t b) {
    return b ? static_cast<double>(a) / static_cast<double>(b) : 0.0;
  }
};

Table table3(const OcrEvaluation& ocr, const std::optional<AnomalyFilterCounts>& afm);
// OCR metrics per condition subset (the conditions of Table 8 applied to Table 3).
Table table3Conditions(const OcrEvaluation& ocr);
// Parking numbers per apparent height bin (OcrEvaluation::parking_numbers_by_height).
// OCR metrics per rendered look (meta.json's appearance subset); table3All adds it when a
// drive has one.
Table table3Appearance(const OcrEvaluation& ocr);
// OCR metrics of bird's-eye images per orientation (eval/birds_eye_evaluation.h).
Table table3BirdsEye(const OcrEvaluation& ocr);
Table table3Heights(const OcrEvaluation& ocr);
// Parking numbers with intact and worn paint (OcrEvaluation::parking_numbers_by_paint).
Table table3Paint(const OcrEvaluation& ocr);
// Parking numbers in full sight and partly hidden (OcrEvaluation::parking_numbers_by_sight).
Table table3Sight(const OcrEvaluation& ocr);
// Parking numbers by their ink's SNR (OcrEvaluation::parking_numbers_by_ink); table3All adds
// it when the labels carry one.
Table table3Ink(const OcrEvaluation& ocr);
// Per class under the height-only legibility rule (OcrEvaluation::height_rule_by_class).
Table table3HeightRule(const OcrEvaluation& ocr);
// Parking numbers per frame set (OcrEvaluation::parking_numbers_per_frame_set).
Table table3FrameSets(const OcrEvaluation& ocr);
// Parking numbers per drive (OcrEvaluation::parking_numbers_per_drive).
Table table3Drives(const OcrEvaluation& ocr);
// All of the above, in that order (the ink table only when the labels carry ink SNRs, the
// frame-set and drive tables only when they have numbers).
std::vector<Table> table3All(const OcrEvaluation& ocr,
                             const std::optional<AnomalyFilterCounts>& afm);

struct AblationRow {
  bool afm = false, mcrp = false, mcap = false;
  VariantResult result;
};
// The 8 paper combinations, then extra rows (parkloc, oracle OCR) given as plain variants.
Table table10(const std::vector<AblationRow>& paper_rows, const std::vector<VariantResult>& extra);

// Position error per condition for each variant: variant -> condition -> error.
Table table8(
    const std::vector<std::pair<std::string, std::map<std::string, TrajectoryError>>>& per_variant);

Table table5(const std::vector<VariantResult>& variants);

// One row per map-noise level (eval/evaluation.h): the survey error the pipeline's map was
// given, its position and yaw errors, and how often its covariance was honest.
struct MapNoiseRow {
  double noise_m = 0.0;
  std::string seed;  // the draw's seed, "all N" for N draws pooled, "-" for the exact map
  VariantResult result;
  size_t nees_frames = 0, nees_inside = 0;
  // The drives smoothed from the same fixes and odometry (eval/drive_smoother.h).
  std::optional<TrajectoryError> smoothed;
};
Table mapNoiseTable(const std::vector<MapNoiseRow>& rows);

// Latency per stage (median / p95 / p99 / max, ms) of each variant, and the whole frame set.
Table latencyTable(const std::vector<VariantResult>& variants);

// The level estimate of each pipeline against the true level: frame sets with a pose and with
// the level decided, right where decided, and the time to decide after the first text that
// tells the level, on the first level of a drive and after a level change.
Table levelTable(const std::vector<VariantResult>& variants);

}  // namespace parkloc::eval
