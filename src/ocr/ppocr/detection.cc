#include "ocr/ppocr/detection.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace parkloc::ocr {

namespace {

// DB's input sides are multiples of its output stride.
constexpr int kDetectorStride = 32;
// A request may shrink the detector's input (SpotRequest::detection_scale) to save time, down
// to a tenth, never enlarge it.
constexpr double kMinDetectionScale = 0.1;

int roundToStride(double v) {
  return std::max(kDetectorStride,
                  static_cast<int>(std::lround(v / kDetectorStride)) * kDetectorStride);
}

}  // namespace

DetectionOptions withRawImagesReadAs(DetectorRole role, DetectionOptions options) {
  if (role == DetectorRole::kFloorView) {
    options.scene_db = options.floor_db;
    options.scene_read_expand_x = options.floor_read_expand_x;
    options.scene_read_expand_y = options.floor_read_expand_y;
  } else if (role == DetectorRole::kRawBand) {
    options.scene_db = options.band_db;
    options.scene_read_expand_x = options.scene_read_expand_y = 1.f;
  }
  return options;
}

Detections detect(const cv::Mat& image, DetectorRole role, const PpOcrModels& models,
                  const DetectionOptions& options, float detection_scale, int max_reads) {
  // A floor view's scale is its resolution, chosen for the floor detector: a view wider than
  // scene_max_side (+-8 m at 1.5 cm) is not shrunk.
  const double fit =
      role == DetectorRole::kRawBand || role == DetectorRole::kFloorView
          ? 1.0
          : std::min(1.0, options.scene_max_side / double(std::max(image.cols, image.rows)));
  const double scale =
      fit * std::clamp(static_cast<double>(detection_scale), kMinDetectionScale, 1.0);
  const int w = roundToStride(image.cols * scale), h = roundToStride(image.rows * scale);
  cv::Mat resized;
  if (w == image.cols && h == image.rows)
    resized = image;
  else
    cv::resize(image, resized, {w, h}, 0, 0, cv::INTER_AREA);
  Detections out;
  const DbDetector* detector = &models.detector;
  const DbOptions* db = &options.scene_db;
  out.read_expand_x = options.scene_read_expand_x;
  out.read_expand_y = options.scene_read_expand_y;
  if (role == DetectorRole::kFloorView && models.floor_detector) {
    detector = &*models.floor_detector;
    db = &options.floor_db;
    out.read_expand_x = options.floor_read_expand_x;
    out.read_expand_y = options.floor_read_expand_y;
  } else if (role == DetectorRole::kRawBand && models.band_detector) {
    detector = &*models.band_detector;
    db = &options.band_db;
    out.read_expand_x = out.read_expand_y = 1.f;
  }
  const cv::Mat probability = detector->probability({resized})[0];
  const float sx = float(image.cols) / probability.cols, sy = float(image.rows) / probability.rows;

  out.boxes = dbBoxesFromProbability(probability, *db);
  for (DbBox& box : out.boxes)  // map pixels -> image pixels (integer coordinates at centres)
    for (auto& p : box.quad) p = {(p.x + 0.5f) * sx - 0.5f, (p.y + 0.5f) * sy - 0.5f};
  if (max_reads > 0 && out.boxes.size() > static_cast<size_t>(max_reads)) {
    // Under a read budget the confident boxes go first: the weaker ones that a low box
    // threshold lets through are read only when the budget has room left.
    std::vector<DbBox> first;
    for (size_t i : readingPriority(out.boxes, options.confident_box_score)) {
      if (first.size() == static_cast<size_t>(max_reads)) break;
      first.push_back(out.boxes[i]);
    }
    out.boxes = std::move(first);
  }
  return out;
}

}  // namespace parkloc::ocr
