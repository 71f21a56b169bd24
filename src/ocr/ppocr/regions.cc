#include "ocr/ppocr/regions.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace parkloc::ocr {

bool readAtPrediction(const RegionOfInterest& region, const RegionOptions& options) {
  return options.read_at_prediction && quadWidth(region.predicted) > 1.f &&
         quadHeight(region.predicted) > 1.f;
}

std::vector<RegionPatch> regionPatches(const cv::Mat& image,
                                       const std::vector<RegionOfInterest>& regions,
                                       const RegionOptions& options) {
  const cv::Size patch = options.patch;
  const float aspect = float(patch.width) / patch.height;
  std::vector<RegionPatch> out;
  for (size_t r = 0; r < regions.size(); ++r) {
    if (readAtPrediction(regions[r], options)) continue;
    const Quad& q = regions[r].polygon;
    const float w = std::max(quadWidth(q), 1.f), h = std::max(quadHeight(q), 1.f);
    // The expanded region keeps the patch's aspect ratio, so the text is not stretched.
    const float expanded_h = std::max(h * options.expand_y, w * options.expand_x / aspect);
    const float expanded_w = expanded_h * aspect;
    const Quad expanded = expandQuad(q, expanded_w / w, expanded_h / h);
    RegionPatch p;
    p.region = r;
    p.patch_from_image = rectifyingHomography(expanded, patch.width, patch.height);
    cv::warpPerspective(image, p.image, p.patch_from_image, patch, cv::INTER_LINEAR,
                        cv::BORDER_CONSTANT);
    p.text_width = w / expanded_w * patch.width;
    p.text_height = h / expanded_h * patch.height;
    out.push_back(std::move(p));
  }
  return out;
}

std::optional<DbBox> boxAtPrediction(const std::vector<DbBox>& boxes, const cv::Size& patch,
                                     float text_width, float text_height) {
  const cv::Point2f centre(patch.width * 0.5f, patch.height * 0.5f);
  std::optional<DbBox> chosen;
  float chosen_cost = 0.f;
  for (const DbBox& box : boxes) {
    const cv::Point2f c = quadCentre(box.quad);
    const float dx = (c.x - centre.x) / std::max(text_width, 1.f),
                dy = (c.y - centre.y) / std::max(text_height, 1.f);
    const float cost = dx * dx + dy * dy;
    if (std::abs(dx) > kMaxOffsetAlong || std::abs(dy) > kMaxOffsetAcross) continue;
    if (!chosen || cost < chosen_cost) {
      chosen = box;
      chosen_cost = cost;
    }
  }
  return chosen;
}

std::vector<ReadJob> regionJobs(const std::vector<RegionOfInterest>& regions,
                                const RegionOptions& options) {
  std::vector<ReadJob> jobs(regions.size());
  for (size_t r = 0; r < regions.size(); ++r) {
    jobs[r].lexicon = &regions[r].expected_texts;
    jobs[r].try_both_directions = false;  // the map predicts the reading direction
    jobs[r].quad = readAtPrediction(regions[r], options)
                       ? expandQuad(regions[r].predicted, options.prediction_expand_x,
                                    options.prediction_expand_y)
                       : regions[r].polygon;  // read the prediction itself; score 0
  }
  return jobs;
}

}  // namespace parkloc::ocr
