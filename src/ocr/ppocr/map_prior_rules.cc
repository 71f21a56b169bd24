#include "ocr/ppocr/map_prior_rules.h"

#include <optional>

#include "map/placed_texts.h"
#include "ocr/cut_parts.h"
#include "ocr/placed_classes.h"

namespace parkloc::ocr {

void applyOneEndRule(TextInstance& inst, const ReadJob& job, const MapPriorOptions& options) {
  // Only a box that names a text freely (a lexicon match has its own cut parts) and lies on a
  // placed text: the map says which text the end may be of.
  if (inst.lexicon_match || inst.text.empty() || !job.onPlacedText() ||
      options.min_cut_part_chars <= 0)
    return;
  const CutCandidates parts =
      withCutParts(*job.placed_near, true, true, static_cast<size_t>(options.min_cut_part_chars));
  if (const auto whole = wholeOfPart(inst.raw_text, parts)) {
    inst.text = *whole;
    inst.lexicon_match = inst.partial = true;
  }
}

bool holdToPlacedSize(TextInstance& inst, const GroundView& view, const SpotRequest& request,
                      const PlacedSizeOptions& size, float confident_box_score) {
  const std::optional<Quad> in_view = view.viewFromRaw(inst.polygon);
  if (!in_view) return true;  // a corner off the floor: no size to compare
  const Eigen::Vector2d centre = view.groundFromView(quadCentre(*in_view));
  // A box read as a text is held to the nearest text of that name, one nothing matched to the
  // text it lies on.
  const map::PlacedText* placed =
      inst.lexicon_match ? map::nearestPlaced(request.placed_floor_texts, centre,
                                              request.placement_radius_m, inst.text)
      : size.unmatched_margin_m >= 0.0
          ? map::placedTextUnder(request.placed_floor_texts, centre, size.unmatched_margin_m)
          : nullptr;
  if (placed == nullptr) return true;
  const double resolution = view.options().resolution;
  const float width = static_cast<float>(placed->width / resolution),
              height = static_cast<float>(placed->height / resolution);
  const PlacedSizeFit fit =
      inst.lexicon_match
          ? fitToPlacedSize(*in_view, width, height, !inst.partial, size)
          : fitUnmatchedToPlacedSize(*in_view, width, height,
                                     view.viewFromGround(centre + placed->reading.normalized()) -
                                         view.viewFromGround(centre),
                                     size);
  if (fit.verdict == PlacedSize::kRefused) {
    if (!inst.lexicon_match) return false;  // a fragment of the text it lies on
    inst.text.clear();
    inst.lexicon_match = inst.second_opinion = inst.partial = false;
    inst.recognition_score = 0.f;
    return inst.detection_score >= confident_box_score;
  }
  if (fit.verdict == PlacedSize::kTightened) {
    if (const auto in_raw = view.rawFromView(fit.quad)) {
      inst.polygon = *in_raw;
      inst.sized_by_map = true;
    }
  }
  return true;
}

ClassWeights floorClassWeights(const GroundView& view, const cv::Point2f& view_pixel,
                               const SpotRequest& request, const MapPriorOptions& options) {
  if (!narrowsToPlacedTexts(request)) return kFloorClasses;
  return floorClassWeightsNear(request.placed_floor_texts, view.groundFromView(view_pixel),
                               request.placement_radius_m, options.unplaced_class_weight);
}

bool narrowsToPlacedTexts(const SpotRequest& request) {
  return request.narrow_to_placed_texts && !request.placed_floor_texts.empty();
}

}  // namespace parkloc::ocr
