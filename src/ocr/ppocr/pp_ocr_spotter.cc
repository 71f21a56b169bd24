#include "ocr/ppocr/pp_ocr_spotter.h"

#include <fmt/format.h>

#include <opencv2/imgproc.hpp>
#include <optional>

#include "common/error.h"
#include "ocr/corner_refinement.h"
#include "ocr/ppocr/dedup.h"
#include "ocr/ppocr/map_prior_rules.h"
#include "ocr/ppocr/pp_ocr_models.h"
#include "ocr/ppocr/read_jobs.h"

namespace parkloc::ocr {

void requireBgrImage(const cv::Mat& image, const std::string& what) {
  if (image.empty()) throw InputError(what + ": empty image");
  if (image.type() != CV_8UC3)
    throw InputError(what + ": expected an 8-bit 3-channel (BGR) image, got type " +
                     std::to_string(image.type()) + " with " + std::to_string(image.channels()) +
                     " channels");
}

PpOcrSpotter::PpOcrSpotter(const PpOcrOptions& options)
    : options_(options),
      models_(std::make_unique<PpOcrModels>(options.models, options.onnx, options.reading.alphabet,
                                            options.detection.band)),
      floor_views_(options.detection.floor_view, options.detection.placed_reach) {
  buildColourTables();
}

PpOcrSpotter::~PpOcrSpotter() = default;

std::vector<TextInstance> PpOcrSpotter::spot(const cv::Mat& image, const SpotRequest& request) {
  requireBgrImage(image);
  // SpotRequest::camera is the image's camera: an image of another size than its calibration
  // is another camera's, or resized:
  // the floor view and the corner fit on the ground plane would read garbage from it.
  if (request.camera != nullptr && (request.camera->model.width != image.cols ||
                                    request.camera->model.height != image.rows))
    throw InputError(fmt::format("camera '{}': image {}x{} differs from its calibration's {}x{}",
                                 request.camera->name, image.cols, image.rows,
                                 request.camera->model.width, request.camera->model.height));
  return request.regions.empty() ? spotFullFrame(image, request) : spotRegions(image, request);
}

std::vector<std::optional<TextInstance>> PpOcrSpotter::readInstances(
    const cv::Mat& image, const std::vector<ReadJob>& jobs, const geometry::RigCamera* camera,
    const CtcRecognizer* fallback) {
  const std::vector<JobReading> readings =
      readJobs(image, jobs, options_.reading, *models_, fallback);
  std::vector<std::optional<TextInstance>> out(jobs.size());
  for (size_t i = 0; i < jobs.size(); ++i) {
    out[i] = instanceOf(jobs[i], readings[i], options_.reading);
    if (!out[i]) continue;
    applyOneEndRule(*out[i], jobs[i], options_.map_prior);
    const std::optional<Quad> fit =
        inkFittedCorners(image, out[i]->polygon, options_.corners, camera);
    if (fit) out[i]->polygon = *fit;
    out[i]->box_only = !fit;
  }
  return out;
}

Quad PpOcrSpotter::unfittedFloorBox(const TextInstance& inst, double unclip_ratio) const {
  if (unclip_ratio <= 0.0 || inst.partial) return inst.polygon;
  return reunclipQuad(inst.polygon, options_.detection.floor_db.unclip_ratio, unclip_ratio);
}

std::vector<TextInstance> PpOcrSpotter::detectAndRead(const cv::Mat& image,
                                                      const SpotRequest& request,
                                                      const geometry::RigCamera* camera,
                                                      DetectorRole role, const FloorWindow* floor,
                                                      float role_scale,
                                                      const UnfittedFloorBoxes& unfitted) {
  const Detections found = detect(image, role, *models_, options_.detection,
                                  request.detection_scale * role_scale, request.max_reads);
  ReadJobSet jobs;
  addDetectedJobs(jobs, found, role, request, floor, options_.map_prior,
                  options_.detection.confident_box_score);
  const CtcRecognizer* fallback = models_->fallback_recognizer && request.second_opinions
                                      ? &*models_->fallback_recognizer
                                      : nullptr;
  std::vector<TextInstance> out;
  if (unfitted.boxes != nullptr) unfitted.boxes->clear();
  for (auto& read : readInstances(image, jobs.jobs, camera, fallback)) {
    if (!read) continue;
    TextInstance& inst = *read;
    // A floor box its ink did not fit: at the margin reported unfitted, now or (`boxes`)
    // after the caller's own fit.
    if (role == DetectorRole::kFloorView) {
      const Quad box = inst.box_only ? unfittedFloorBox(inst, unfitted.unclip_ratio) : inst.polygon;
      if (unfitted.boxes != nullptr)
        unfitted.boxes->push_back(box);
      else
        inst.polygon = box;
    }
    out.push_back(std::move(inst));
  }
  return out;
}

std::vector<TextInstance> PpOcrSpotter::spotFullFrame(const cv::Mat& image,
                                                      const SpotRequest& request) {
  const DetectionOptions& detection = options_.detection;
  const bool ground = detection.view != FisheyeView::kRaw && request.camera != nullptr;
  std::vector<TextInstance> out;
  size_t on_floor = 0;                      // out[0, on_floor) came from the floor view
  std::vector<ClassWeights> floor_classes;  // their class weights
  const bool placed_rules = narrowsToPlacedTexts(request);
  // Floor text found and read in a bird's-eye view (or a mosaic of its windows), its corners
  // mapped back to raw; with `skip_seen`, text whose centre lies in a polygon found before is
  // dropped.
  auto addFloorText = [&](const cv::Mat& rendered, const FloorWindow& window, bool skip_seen) {
    const size_t found_before = out.size();
    std::vector<Quad> unfitted_in_view;
    std::vector<TextInstance> found =
        detectAndRead(rendered, request, nullptr, DetectorRole::kFloorView, &window, 1.f,
                      {detection.floor_unfitted_unclip_ratio, &unfitted_in_view});
    for (size_t k = 0; k < found.size(); ++k) {
      TextInstance& inst = found[k];
      // A window reports the placed texts it was opened for, not what else it read.
      if (window.only_placed_texts && !inst.lexicon_match) continue;
      const std::optional<cv::Point2f> shift = window.shiftAt(quadCentre(inst.polygon));
      if (!shift) continue;
      const ClassWeights weights = floorClassWeights(
          *window.view, quadCentre(inst.polygon) + *shift, request, options_.map_prior);
      Quad in_view = inst.polygon, unfitted = unfitted_in_view[k];
      for (auto& p : in_view) p += *shift;
      for (auto& p : unfitted) p += *shift;
      const std::optional<Quad> in_raw = window.view->rawFromView(in_view);
      if (!in_raw) continue;
      inst.polygon = *in_raw;
      if (skip_seen && seenBefore(inst, out, found_before)) continue;
      // Final corner fit at the raw image's resolution, on the ground plane; without one, the
      // view's fit or the box at the margin reported unfitted.
      if (const std::optional<Quad> fit =
              inkFittedCorners(image, inst.polygon, options_.corners, request.camera)) {
        inst.polygon = *fit;
        inst.box_only = false;
      } else if (unfitted != in_view) {
        inst.polygon = window.view->rawFromView(unfitted).value_or(inst.polygon);
      }
      if (placed_rules && options_.map_prior.placed_size &&
          !holdToPlacedSize(inst, *window.view, request, *options_.map_prior.placed_size,
                            detection.confident_box_score))
        continue;
      out.push_back(std::move(inst));
      floor_classes.push_back(weights);
    }
  };
  if (ground) {
    const GroundView& view = floor_views_.view(*request.camera);
    addFloorText(view.render(image), {&view, nullptr, false}, false);
    if (request.look_beyond_the_view && !request.placed_floor_texts.empty() &&
        detection.placed_reach.half_width > 0) {
      const GroundView& reach = floor_views_.reach(*request.camera);
      const WindowMosaic mosaic = mosaicOf(
          reach, image,
          windowsBeyondView(view, reach, request.placed_floor_texts, detection.placed_windows));
      if (!mosaic.image.empty()) addFloorText(mosaic.image, {&reach, &mosaic, true}, true);
    }
    on_floor = out.size();
  }
  if (ground && models_->band_detector) {
    // The horizon band at full resolution; its crops are read from the band itself (a view
    // of the image, not a copy), corners fitted in the crop (pillar text is not on the floor).
    const cv::Rect rows = bandRect(detection.band, request.camera->model);
    std::vector<TextInstance> found =
        detectAndRead(image(rows), request, nullptr, DetectorRole::kRawBand, nullptr,
                      static_cast<float>(bandScale(detection.band, request.camera->model)));
    for (TextInstance& inst : found)
      for (auto& p : inst.polygon) p.y += static_cast<float>(rows.y);
    appendUnseen(out, std::move(found));
  }
  if (!ground || detection.view == FisheyeView::kGroundAndRaw)
    appendUnseen(out, detectAndRead(image, request, request.camera, DetectorRole::kScene));
  // Classification: a floor instance under its placed classes' weights.
  for (size_t i = 0; i < out.size(); ++i) {
    TextInstance& inst = out[i];
    const auto [cls, score] = models_->headFor(inst).classify(
        image, inst.polygon, inst.text, i < on_floor ? floor_classes[i] : kAnyClass);
    inst.cls = cls;
    inst.class_score = score;
  }
  return out;
}

std::vector<TextInstance> PpOcrSpotter::spotRegions(const cv::Mat& image,
                                                    const SpotRequest& request) {
  // Identified texts are only fitted; the others are detected and read.
  std::vector<TextInstance> out;
  SpotRequest to_read = request;
  to_read.regions.clear();
  for (const RegionOfInterest& region : request.regions) {
    if (region.read) {
      to_read.regions.push_back(region);
      continue;
    }
    if (region.expected_texts.empty()) continue;
    const auto fitted = fitTrackedText(image, region.predicted, request.camera,
                                       options_.regions.tracked_fit, options_.corners.fit);
    if (!fitted) continue;
    TextInstance inst;
    inst.polygon = *fitted;
    inst.text = region.expected_texts.front();
    inst.cls = region.expected_class;
    inst.read = false;
    out.push_back(std::move(inst));
  }
  if (to_read.regions.empty()) return out;
  for (TextInstance& inst : readRegions(image, to_read)) out.push_back(std::move(inst));
  return out;
}

std::vector<TextInstance> PpOcrSpotter::readRegions(const cv::Mat& image,
                                                    const SpotRequest& request) {
  // A region with the text's own predicted polygon is read right there (the lexicon must
  // vouch for it); the others are searched by the detector in a rectified patch.
  const std::vector<RegionPatch> patches = regionPatches(image, request.regions, options_.regions);
  std::vector<cv::Mat> patch_images;
  for (const RegionPatch& p : patches) patch_images.push_back(p.image);
  const auto maps =
      patch_images.empty() ? std::vector<cv::Mat>{} : models_->detector.probability(patch_images);
  std::vector<ReadJob> jobs = regionJobs(request.regions, options_.regions);
  for (size_t k = 0; k < patches.size(); ++k) {
    const std::optional<DbBox> chosen =
        boxAtPrediction(dbBoxesFromProbability(maps[k], options_.detection.scene_db),
                        options_.regions.patch, patches[k].text_width, patches[k].text_height);
    if (chosen) {
      ReadJob& job = jobs[patches[k].region];
      job.quad = transformQuad(chosen->quad, patches[k].patch_from_image.inv());
      job.detection_score = chosen->score;
    }
  }
  auto read = readInstances(image, jobs, request.camera, nullptr);
  std::vector<TextInstance> out;
  for (size_t r = 0; r < read.size(); ++r) {
    // A region where no text was detected counts only when the lexicon vouches for it.
    if (!read[r] || (jobs[r].detection_score == 0.f && !read[r]->lexicon_match)) continue;
    TextInstance& inst = *read[r];
    const auto [cls, score] = models_->classifier.classify(image, inst.polygon, inst.text);
    inst.cls = cls;
    inst.class_score = score;
    out.push_back(std::move(inst));
  }
  return out;
}

}  // namespace parkloc::ocr
