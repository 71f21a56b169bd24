#pragma once
// "Oracle OCR": text instances straight from the ground-truth labels, the geometric limit
// of the pipeline (the gap to the real OCR is the OCR's share of the error).
#include <vector>

#include "io/labels.h"
#include "ocr/text_spotter.h"

namespace parkloc::run {

struct OracleOptions {
  // Labels this occluded are left out, as a spotter could not read them (the dataset marks
  // them '###').
  double max_occluded_fraction = 0.5;
  // A truncated polygon is clipped at the image border: its corners are not the text's.
  bool skip_truncated = true;
};

std::vector<ocr::TextInstance> oracleInstances(const io::ImageLabels& labels,
                                               const OracleOptions& options = {});

}  // namespace parkloc::run
