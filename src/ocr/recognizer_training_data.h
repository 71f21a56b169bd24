#pragma once
// Training data for fine-tuning the CTC recognizer on what the spotter feeds it: crops of the
// raw fisheye image rectified from a text quad (rectifiedCrop, 48 px tall), labelled with the
// text. The spotter reads the detector's box, which is larger than the ink and a few pixels
// off; each labelled text is therefore written `variants` times from its true corners grown
// and shifted at random within the ranges below (seeded, so the export repeats exactly).
//   OUT/crops/<sequence>_<camera>_<stem>_<n>.png   upright BGR crop
//   OUT/index.tsv            <crop path from OUT> TAB <text> TAB <class id (0 pillar, 1 parking
//                            number, 2 other)>
// A text is used when it is legible, less than half occluded, not truncated, not squeezed
// along its reading direction (a pillar face seen edge on) and every character is in
// `alphabet` (empty: any).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace parkloc::ocr {

struct RecognizerDataOptions {
  std::string out_dir;
  size_t frame_stride = 1;             // use every n-th frame set
  size_t max_frames_per_sequence = 0;  // 0: all
  double max_occluded_fraction = 0.5;
  std::string alphabet = "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ-";
  int variants = 3;  // crops per parking number
  // Crops per pillar or other text: a few level signs ("B1") on every pillar would otherwise
  // outnumber the parking numbers.
  int other_class_variants = 1;
  // Reading width per character below this fraction of the text height: squeezed, left out.
  double min_width_per_char = 0.25;
  // Box growth along and across the reading direction, uniform in [1, max], and shift of
  // the centre and of each corner, uniform within +-fraction of the text height.
  double max_grow_x = 1.3, max_grow_y = 1.7;
  double max_shift = 0.15, max_corner_jitter = 0.08;
  std::uint64_t seed = 1;
  std::function<void(size_t done, size_t total)> progress;  // after each sequence
};

struct RecognizerDataStats {
  size_t texts = 0;  // labelled texts used
  size_t crops = 0;
};

// Throws InputError for unreadable sequences and IoError for files that cannot be written.
RecognizerDataStats writeRecognizerTrainingData(const std::vector<std::string>& sequence_dirs,
                                                const RecognizerDataOptions& options);

}  // namespace parkloc::ocr
