#pragma once
// Training data for fine-tuning the DB text detector on ground views (ocr/ground_view.h), the
// images the spotter feeds it when the camera is known, or on the raw image's horizon band
// (ocr/raw_band.h). From dataset sequences (`parkloc simulate` folders), for every n-th frame
// set and every camera, writes
//   OUT/images/<sequence>_<camera>_<stem>.png   the raw image's ground view or band (BGR)
//   OUT/labels/<sequence>_<camera>_<stem>.txt   x1,y1,x2,y2,x3,y3,x4,y4,care,class,text
//   OUT/index.txt                               <image> <labels> <conditions>, paths from OUT
// (conditions: io::sequenceConditions joined by "+", "none" when there are none)
// Label corners are view pixels in the labels' order (TL, TR, BR, BL of the text as it
// reads), one decimal; class is the dataset's id (0 pillar, 1 parking number, 2 other); commas
// in the text become spaces. care 1: floor text, legible and less than half occluded; text
// cut by the raw image's edge or the view's is labelled by the part the view shows (care when
// that part keeps enough of it); care 0 is a "don't care" region for the loss.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "ocr/ground_view.h"
#include "ocr/raw_band.h"

namespace parkloc::ocr {

// What the detector is to see: the floor view (floor text only), or the raw image's horizon
// band (every class: distant floor numbers, pillar text, plates), in raw pixels less the band's
// top. In the band, care is any text legible, less than half occluded, not truncated and
// wholly in the band; the rest that touches the band is don't-care.
enum class DetectorSource { kFloorView, kRawBand };

struct DetectorDataOptions {
  std::string out_dir;
  DetectorSource source = DetectorSource::kFloorView;
  GroundViewOptions view;
  RawBand band;
  size_t frame_stride = 1;             // use every n-th frame set
  size_t max_frames_per_sequence = 0;  // 0: all
  double max_occluded_fraction = 0.5;  // care only below this
  // Floor text cut by an edge is care when its seen part keeps at least these shares of its
  // length and height (the annotation labels text with 0.3 of it inside the image).
  double min_seen_length = 0.3;
  double min_seen_height = 0.75;
  // Called after each sequence.
  std::function<void(size_t done, size_t total)> progress;
};

struct DetectorDataStats {
  size_t images = 0;
  size_t care_instances = 0;
  size_t dont_care_instances = 0;
};

// Reads the sequences' images and labels (frames without a label file are left out); throws
// InputError for unreadable sequences and IoError for files that cannot be written.
DetectorDataStats writeDetectorTrainingData(const std::vector<std::string>& sequence_dirs,
                                            const DetectorDataOptions& options);

}  // namespace parkloc::ocr
