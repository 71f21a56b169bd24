#include "run/oracle_source.h"

namespace parkloc::run {

std::vector<ocr::TextInstance> oracleInstances(const io::ImageLabels& labels,
                                               const OracleOptions& options) {
  std::vector<ocr::TextInstance> out;
  for (const auto& l : labels.instances) {
    if (l.occluded_fraction >= options.max_occluded_fraction) continue;
    if (options.skip_truncated && l.truncated) continue;
    if (!l.legible) continue;  // the oracle reads what a reader could read
    ocr::TextInstance t;
    for (int i = 0; i < 4; ++i)
      t.polygon[i] =
          cv::Point2f(static_cast<float>(l.polygon[i].x()), static_cast<float>(l.polygon[i].y()));
    t.text = l.text;
    t.raw_text = l.text;
    t.lexicon_match = true;
    t.cls = l.cls;
    t.detection_score = t.recognition_score = t.class_score = 1.f;
    out.push_back(std::move(t));
  }
  return out;
}

}  // namespace parkloc::run
