#pragma once
// Post-processing of a DB (Differentiable Binarization, Liao et al. 2020) probability map
// into text boxes, as PaddleOCR's DBPostProcess does it: threshold the map, take the outer
// contours, score each by the mean probability inside its minimum-area box, grow the box
// by the offset distance D = area * unclip_ratio / perimeter (the inverse of DB's shrink),
// and keep the minimum-area rectangle of the grown box.
#include <opencv2/core.hpp>
#include <vector>

#include "ocr/quad.h"

namespace parkloc::ocr {

struct DbOptions {
  float binary_threshold = 0.3f;  // pixel is text when probability > this
  float box_threshold = 0.6f;     // keep boxes whose mean probability reaches this
  double unclip_ratio = 1.5;
  int max_candidates = 1000;
  float min_size = 3.f;  // shorter side in map pixels, before and after unclip
  bool dilate = false;   // 2x2 dilation of the binary map (PaddleOCR use_dilation)
};

struct DbBox {
  Quad quad;          // in probability-map pixels, reading order as quadFromRotatedRect
  float score = 0.f;  // mean probability inside the box before unclipping
};

// `probability` is CV_32F, one channel.
std::vector<DbBox> dbBoxesFromProbability(const cv::Mat& probability, const DbOptions& options);

// The order in which to read boxes under a read budget: those scoring at least
// `confident_score` first, then the rest; the largest first within each (larger text reads
// better). Indices into `boxes`; stable for equal keys.
std::vector<size_t> readingPriority(const std::vector<DbBox>& boxes, float confident_score);

// Grows a rectangle by DB's offset distance: area * ratio / perimeter on every side.
cv::RotatedRect unclipRect(const cv::RotatedRect& rect, double unclip_ratio);

// The box that growing the same kernel by `to_ratio` would have given, from the box `grown`
// that growing it by `from_ratio` gave (unclipRect solved back for the kernel): the margin of a
// box already grown can be chosen again where it is used. `grown` is a rectangle in its own
// reading frame; a degenerate one is returned as it is.
Quad reunclipQuad(const Quad& grown, double from_ratio, double to_ratio);

}  // namespace parkloc::ocr
