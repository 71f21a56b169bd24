#pragma once
// Detection, the first stage of full-frame spotting: which DB detector looks at which image,
// at which scale and with which post-processing, and which of its boxes a read budget keeps.
// Three detectors play three roles: PaddleOCR's on the raw fisheye image, parkloc's floor
// detector on a bird's-eye view of the floor (ocr/ground_view.h) or a mosaic of its windows
// beyond that view (ocr/placed_windows.h), and the band detector on the raw image's horizon
// band (ocr/raw_band.h). docs/OCR.md has the measurements behind each choice.
#include <opencv2/core.hpp>
#include <vector>

#include "ocr/db_postprocess.h"
#include "ocr/ground_view.h"
#include "ocr/placed_windows.h"
#include "ocr/ppocr/pp_ocr_models.h"
#include "ocr/raw_band.h"

namespace parkloc::ocr {

// Where full-frame detection runs on a fisheye image.
enum class FisheyeView {
  kRaw,           // the raw image
  kGround,        // a bird's-eye view of the floor (needs SpotRequest::camera; else raw)
  kGroundAndRaw,  // both; raw detections already found on the floor are dropped
};

// Which detector looks at an image: PaddleOCR's on a raw image (scaled to
// DetectionOptions::scene_max_side), the floor detector on a floor view (at the view's
// resolution), the band detector on a raw image's horizon band (at full resolution).
enum class DetectorRole { kScene, kFloorView, kRawBand };

struct DetectionOptions {
  FisheyeView view = FisheyeView::kGround;
  // A raw image is detected with its longer side scaled to this (a multiple of the detector's
  // stride): PaddleOCR's own input size.
  int scene_max_side = 960;
  // PaddleOCR's post-processing, for its detector wherever it runs: raw images, map-guided
  // patches, and the floor view or the band when no detector of their own is given.
  DbOptions scene_db;
  // A raw image's boxes are read from a crop grown by these (along, across the text):
  // PaddleOCR's boxes carry their margin (unclip 1.5) and are read as they are. Another
  // detector in the raw image's role (the floor or band detector on a photo, `parkloc eval
  // photos`) comes with its own post-processing and margins.
  float scene_read_expand_x = 1.f;
  float scene_read_expand_y = 1.f;
  // The bird's-eye view of the floor the floor detector looks at.
  GroundViewOptions floor_view;
  // The floor detector was trained on DB's shrunk kernels (r = 0.4,
  // tools/detector_tuning/db_targets.py), which an unclip ratio of 2 grows back to the whole
  // box of a text 3-4 times as long as high (PaddleOCR's 1.5 leaves it a fifth too low, and a
  // crop that cuts into the glyphs reads worse). Its thin kernels average less over their
  // rectangle than PaddleOCR's, so the box threshold is DB's binary threshold; a box under
  // confident_box_score is kept only when its reading names a text.
  DbOptions floor_db = [] {
    DbOptions o;
    o.unclip_ratio = 2.0;
    o.box_threshold = 0.3f;
    return o;
  }();
  // The floor detector's boxes are the text's own box, with no margin, and the recognizer
  // reads a crop with a margin better: floor-view crops are read from the box grown by these
  // factors (along, across the text); the box itself is what is reported. Chosen on the val
  // split among 1.05 x 1.15 to 1.2 x 1.7 (docs/OCR.md).
  float floor_read_expand_x = 1.1f;
  float floor_read_expand_y = 1.3f;
  // A floor box whose corners find no plausible ink fit (docs/OCR.md, "8. Corner refinement")
  // is reported as the detector's kernel grown by this ratio instead of floor_db's, which grows
  // it for the reading crop and the ink search: on the realistic look the kernel spreads over
  // stains and backings and floor_db's growth boxes a number at about twice its area. 0:
  // floor_db's box. On the fisheye floor view the localization measures with the box, and its
  // rules were chosen with floor_db's; on a bird's-eye image the box is what is reported.
  double floor_unfitted_unclip_ratio = 0.0;
  double birdseye_unfitted_unclip_ratio = 1.3;
  // Floor-view boxes scoring at least this (PaddleOCR's own box threshold) are text by the
  // detector's standard: under a read budget (SpotRequest::max_reads) they are read first, and
  // they are reported even when no reading is confident, as unread text (`text` empty): a
  // number in a font the recognizer misreads is still a number found.
  float confident_box_score = 0.6f;
  // The horizon band's rows, and the band detector's post-processing (trained as the floor
  // detector was; its box threshold stays DB's).
  RawBand band;
  DbOptions band_db = [] {
    DbOptions o;
    o.unclip_ratio = 2.0;
    return o;
  }();
  // Under a predicted pose (SpotRequest::look_beyond_the_view), the floor texts placed beyond
  // `floor_view` but within this wider view are looked for in windows around them, detected at
  // `floor_view`'s resolution (this one's is not used). A half width of 0: never. The side
  // cameras see their row of numbers 6-10 m along the aisle, which the +-6 m view misses and a
  // +-8 m view costs too much to detect whole.
  GroundViewOptions placed_reach = [] {
    GroundViewOptions o;
    o.half_width = 10.0;
    return o;
  }();
  PlacedWindowOptions placed_windows;
};

// What a detector found in an image.
struct Detections {
  std::vector<DbBox> boxes;  // in the image's pixels
  // Their crops are read from the box grown by these factors (along, across the text).
  float read_expand_x = 1.f, read_expand_y = 1.f;
};

// `options` with the raw image read by the post-processing (and reading margins) of the
// detector of `role` instead of PaddleOCR's: for that detector in PaddleOCR's place on a photo
// (`parkloc eval photos`). The floor and band detectors learned DB's thin shrunk kernels
// (r = 0.4), which PaddleOCR's box threshold and unclip ratio would drop or crop into the
// glyphs. kScene gives `options` back.
DetectionOptions withRawImagesReadAs(DetectorRole role, DetectionOptions options);

// Runs the detector of `role` on `image`, scaled by `detection_scale` (SpotRequest) on top of
// the role's own scale. With `max_reads` > 0 (SpotRequest::max_reads), at most that many boxes,
// the confident ones first (readingPriority).
Detections detect(const cv::Mat& image, DetectorRole role, const PpOcrModels& models,
                  const DetectionOptions& options, float detection_scale, int max_reads);

}  // namespace parkloc::ocr
