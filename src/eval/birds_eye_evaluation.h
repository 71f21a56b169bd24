#pragma once
// Table 3 on stitched top-down (AVM) images: the simulator's bird's-eye renders
// (sim/birds_eye.h, <sequence>/birdseye/) spotted as they are and turned by a quarter, a half
// and three quarters, each orientation a subset ("avm_rot0" ... "avm_rot270"), so that the
// figures show whether text is read in any direction.
#include <functional>
#include <string>
#include <vector>

#include "eval/ocr_evaluation.h"
#include "eval/ocr_metrics.h"
#include "ocr/text_spotter.h"

namespace parkloc::eval {

// Spots the text of one top-down image (an engine's bird's-eye entry, with its scale).
using BirdsEyeSpotter =
    std::function<std::vector<ocr::TextInstance>(const cv::Mat& image, const ocr::SpotRequest&)>;

// The orientation subsets, in order.
const std::vector<std::string>& birdsEyeOrientations();

// `labels` of an image `width` x `height` turned clockwise by `quarter_turns` quarters (0-3):
// polygons, visible polygons, the image size and each text's rotation.
io::ImageLabels turnLabels(const io::ImageLabels& labels, int quarter_turns);

// Every bird's-eye image of the sequences (up to options.max_frames_per_sequence each),
// scored in the four orientations; the lexicon is each drive's map, as for Table 3.
OcrEvaluation evaluateBirdsEye(const std::vector<std::string>& sequences,
                               const BirdsEyeSpotter& spot, const OcrRunOptions& options = {});

}  // namespace parkloc::eval
