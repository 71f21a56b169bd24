#pragma once
// Map-guided spotting (SpotRequest::regions): the map predicts where a text shows, so a region
// is read right at its predicted polygon, or searched by the detector in a small rectified
// patch around it, and its job's lexicon is the texts expected there.
#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "ocr/db_postprocess.h"
#include "ocr/ppocr/read_jobs.h"
#include "ocr/text_spotter.h"
#include "ocr/tracked_text_fit.h"

namespace parkloc::ocr {

struct RegionOptions {
  // A region searched by the detector is expanded to at least these multiples of its text
  // size (along, across) and warped to a patch of this size, which keeps the text's aspect
  // ratio: room for the prediction's error around the text.
  float expand_x = 1.4f;
  float expand_y = 2.2f;
  cv::Size patch{256, 64};
  // Regions with a predicted text polygon (RegionOfInterest::predicted) are read at the
  // prediction grown by these factors, without detection: the map tracks them to a few
  // pixels, and the lexicon must match. False: every region goes through the detector.
  bool read_at_prediction = true;
  float prediction_expand_x = 1.1f;
  float prediction_expand_y = 1.4f;
  // Regions with RegionOfInterest::read == false: corner fit only.
  TrackedFitOptions tracked_fit;
};

// Whether a region is read at its predicted polygon, without detection.
bool readAtPrediction(const RegionOfInterest& region, const RegionOptions& options);

// A region's rectified patch for the detector.
struct RegionPatch {
  size_t region = 0;  // index into the request's regions
  cv::Mat image;
  cv::Mat patch_from_image;                   // homography
  float text_width = 0.f, text_height = 0.f;  // the predicted text's size in patch pixels
};
// The patches of the regions not read at their prediction.
std::vector<RegionPatch> regionPatches(const cv::Mat& image,
                                       const std::vector<RegionOfInterest>& regions,
                                       const RegionOptions& options);

// The detected box nearest the patch centre, where the map predicts the text, within
// kMaxOffsetAlong text widths along and kMaxOffsetAcross text heights across; empty: none.
// A box centred farther out is not the predicted text but something the patch's margin shows
// beside it (a neighbouring text, a marking).
inline constexpr float kMaxOffsetAlong = 0.75f;
inline constexpr float kMaxOffsetAcross = 1.0f;
std::optional<DbBox> boxAtPrediction(const std::vector<DbBox>& boxes, const cv::Size& patch,
                                     float text_width, float text_height);

// A job per region, its lexicon the texts expected there, read the way round the map predicts:
// at the prediction (grown) where readAtPrediction, else at the region's polygon with
// detection score 0 until a detected box replaces it.
std::vector<ReadJob> regionJobs(const std::vector<RegionOfInterest>& regions,
                                const RegionOptions& options);

}  // namespace parkloc::ocr
