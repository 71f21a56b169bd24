#include "ocr/ppocr/dedup.h"

#include <opencv2/imgproc.hpp>

#include "ocr/quad.h"

namespace parkloc::ocr {

namespace {

bool contains(const Quad& quad, const cv::Point2f& p) {
  return cv::pointPolygonTest(std::vector<cv::Point2f>(quad.begin(), quad.end()), p, false) >= 0;
}

}  // namespace

bool seenBefore(const TextInstance& inst, const std::vector<TextInstance>& found, size_t count) {
  const cv::Point2f c = quadCentre(inst.polygon);
  for (size_t i = 0; i < count; ++i)
    if (contains(found[i].polygon, c)) return true;
  return false;
}

void appendUnseen(std::vector<TextInstance>& out, std::vector<TextInstance> found) {
  const size_t found_before = out.size();
  for (TextInstance& inst : found)
    if (!seenBefore(inst, out, found_before)) out.push_back(std::move(inst));
}

}  // namespace parkloc::ocr
