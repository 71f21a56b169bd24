#include "ocr/ppocr/read_jobs.h"

#include <optional>

#include "map/placed_texts.h"

namespace parkloc::ocr {

namespace {

// Narrows a floor box's job to what the map places near it (`ground`, in the vehicle frame):
// its lexicon and prior, its way round, and the parts a cut may leave. False: not read at all
// (a window's box with no text placed near it).
bool placeJob(ReadJob& job, ReadJobSet& set, const SpotRequest& request, const FloorWindow& floor,
              const cv::Point2f& shift, const MapPriorOptions& options) {
  const Eigen::Vector2d ground = floor.view->groundFromView(quadCentre(job.quad) + shift);
  const double radius = request.placement_radius_m;
  std::vector<std::string> near = map::textsNear(request.placed_floor_texts, ground, radius);
  // A window beyond the view looks for the texts placed in it, not at what lies around them
  // (a parked car's edges): nothing else there is read.
  if (floor.only_placed_texts && near.empty()) return false;
  if (request.narrow_to_placed_texts) {
    set.placed_lexicons.push_back(std::move(near));
    job.reading_lexicon = job.lexicon;
    job.lexicon = &set.placed_lexicons.back();
    job.placed = true;
    job.prior = &options.placed_lexicon;
    if (options.on_placed_text_margin_m >= 0.0 &&
        map::placedTextUnder(request.placed_floor_texts, ground, options.on_placed_text_margin_m) !=
            nullptr) {
      job.placed_near = job.lexicon;
      job.prior = &options.on_placed_text_lexicon;
    }
  }
  // The texts placed there say which way round the box reads.
  const auto reading = map::readingDirectionNear(request.placed_floor_texts, ground, radius,
                                                 options.placed_reading_max_angle);
  if (reading) {
    const cv::Point2f along =
        floor.view->viewFromGround(ground + *reading) - floor.view->viewFromGround(ground);
    if (const auto oriented = orientedAlong(job.quad, along, options.placed_reading_max_angle)) {
      job.quad = *oriented;
      job.try_both_directions = false;
    }
  }
  // A box that may be a number cut by the image border or the vehicle's body also decodes
  // against the parts of the texts placed there that the cut would leave (only when it reads
  // one way round: the cut end must be known).
  if (request.narrow_to_placed_texts && !job.try_both_directions &&
      options.min_cut_part_chars > 0 && !job.lexicon->empty()) {
    const auto [at_start, at_end] = floor.mayRunOutOfSight(job.quad, shift);
    if (at_start || at_end) {
      set.cut_lexicons.push_back(withCutParts(*job.lexicon, at_start, at_end,
                                              static_cast<size_t>(options.min_cut_part_chars)));
      job.cut = &set.cut_lexicons.back();
      job.lexicon = &job.cut->texts;
    }
  }
  return true;
}

}  // namespace

void addDetectedJobs(ReadJobSet& set, const Detections& found, DetectorRole role,
                     const SpotRequest& request, const FloorWindow* floor,
                     const MapPriorOptions& options, float confident_box_score) {
  // Under a predicted pose each floor box decodes against the texts placed near it.
  const FloorWindow* placing =
      role == DetectorRole::kFloorView && floor != nullptr && !request.placed_floor_texts.empty()
          ? floor
          : nullptr;
  for (const DbBox& box : found.boxes) {
    ReadJob job;
    job.quad = box.quad;
    job.detection_score = box.score;
    job.lexicon = role == DetectorRole::kFloorView && !request.floor_lexicon.empty()
                      ? &request.floor_lexicon
                      : &request.lexicon;
    if (placing != nullptr) {
      const std::optional<cv::Point2f> shift = placing->shiftAt(quadCentre(box.quad));
      if (!shift || !placeJob(job, set, request, *placing, *shift, options)) continue;
    }
    job.keep_unread = role == DetectorRole::kFloorView && box.score >= confident_box_score;
    job.read_expand_x = found.read_expand_x;
    job.read_expand_y = found.read_expand_y;
    job.fallback_only = placing != nullptr && placing->only_placed_texts;
    set.jobs.push_back(job);
  }
}

}  // namespace parkloc::ocr
