#pragma once
// The PaddleOCR PP-OCRv4 engine on ONNX Runtime (paper section 3.2, with PP-OCRv4 mobile in
// place of ABCNet): DB detection, perspective-rectified crops, CTC recognition, lexicon
// decoding and the classification head. Full-frame spotting runs these stages:
//   detection (detection.h)       the floor view, its windows beyond, the horizon band, the raw
//                                 image, each with its detector;
//   read jobs (read_jobs.h)       what each box is read against, under the map's prior;
//   reading (reading_cascade.h)   first reads, direction, second recognizer, rereads;
//   map rules (map_prior_rules.h) the one-end rule, the placed size, the placed classes;
//   refinement (corners.h)        corners fitted to the ink;
//   dedup (dedup.h)               what a later detector finds again is dropped;
//   classification                the class head, under the placed classes' weights.
// With SpotRequest::regions, only those regions are processed (map-guided spotting,
// regions.h).
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ocr/onnx_model.h"
#include "ocr/ppocr/corners.h"
#include "ocr/ppocr/detection.h"
#include "ocr/ppocr/floor_views.h"
#include "ocr/ppocr/map_prior_options.h"
#include "ocr/ppocr/pp_ocr_model_paths.h"
#include "ocr/ppocr/reading_cascade.h"
#include "ocr/ppocr/regions.h"
#include "ocr/text_spotter.h"

namespace parkloc::ocr {

// The spotter's options, one section per stage.
struct PpOcrOptions {
  PpOcrModelPaths models;      // the network files
  OnnxOptions onnx;            // ONNX Runtime's threads
  DetectionOptions detection;  // which detector looks where, and its post-processing
  MapPriorOptions map_prior;   // what the map says about a floor box under a predicted pose
  ReadingOptions reading;      // the recognizers' cascade and lexicon decoding
  CornerOptions corners;       // the corner fit to the ink
  RegionOptions regions;       // map-guided regions
};

// What becomes of a floor-view box whose ink did not fit: grown from its kernel by
// `unclip_ratio` (0: DetectionOptions::floor_db's box), either reported so, or, with `boxes`
// given, kept at floor_db's box for the caller's own fit while `boxes` gets, per instance, the
// box to report when that fit fails too.
struct UnfittedFloorBoxes {
  double unclip_ratio = 0.0;
  std::vector<Quad>* boxes = nullptr;
};

class PpOcrSpotter : public TextSpotter {
 public:
  // Loads every model; throws InputError naming a missing or unreadable file.
  explicit PpOcrSpotter(const PpOcrOptions& options);
  ~PpOcrSpotter() override;

  std::string name() const override { return "ppocr-v4"; }
  std::vector<TextInstance> spot(const cv::Mat& image, const SpotRequest& request) override;

  const PpOcrOptions& options() const { return options_; }

  // Floor text in a stitched top-down image of the floor (an AVM, around-view monitor): the
  // floor detector and reading cascade of the floor view, run on the image as it is and
  // turned a quarter, so that text reads in any direction (birds_eye_spotting.cc). Given its
  // scale, the image is first resampled to the floor view's resolution, at which the floor
  // detector was trained. Polygons are in the image's pixels.
  std::vector<TextInstance> spotBirdsEye(const cv::Mat& image, const SpotRequest& request,
                                         std::optional<double> metres_per_pixel = std::nullopt);

 private:
  std::vector<TextInstance> spotFullFrame(const cv::Mat& image, const SpotRequest& request);
  std::vector<TextInstance> spotRegions(const cv::Mat& image, const SpotRequest& request);
  std::vector<TextInstance> readRegions(const cv::Mat& image, const SpotRequest& request);

  // Detection, read jobs, reading and refinement for one image of a detector role; `floor`:
  // where a floor-view image lies (ocr/ppocr/floor_views.h); `role_scale`: the role's own
  // scale of the image for its detector (bandScale), on top of the request's.
  std::vector<TextInstance> detectAndRead(const cv::Mat& image, const SpotRequest& request,
                                          const geometry::RigCamera* camera, DetectorRole role,
                                          const FloorWindow* floor = nullptr,
                                          float role_scale = 1.f,
                                          const UnfittedFloorBoxes& unfitted = {});
  // Reading, the one-end rule and refinement: an instance per reported job, in job order
  // (TextInstance::box_only where no ink fit was plausible).
  std::vector<std::optional<TextInstance>> readInstances(const cv::Mat& image,
                                                         const std::vector<ReadJob>& jobs,
                                                         const geometry::RigCamera* camera,
                                                         const CtcRecognizer* fallback);
  // A floor box with no ink fit, its kernel grown by `unclip_ratio` instead of floor_db's.
  Quad unfittedFloorBox(const TextInstance& inst, double unclip_ratio) const;

  PpOcrOptions options_;
  std::unique_ptr<PpOcrModels> models_;
  FloorViews floor_views_;
};

// Throws InputError unless `image` is a non-empty 8-bit 3-channel image.
void requireBgrImage(const cv::Mat& image, const std::string& what = "image");

}  // namespace parkloc::ocr
