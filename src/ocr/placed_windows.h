#pragma once
// Under a predicted pose the map says where floor texts lie beyond a camera's floor view: a
// side camera sees its own row of parking numbers 6-10 m along the aisle, outside the +-6 m
// view that the time budget affords (docs/OCR.md). Detecting small windows of a
// wider view around those texts finds them for a fraction of a wider view's cost.
#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "map/placed_texts.h"
#include "ocr/ground_view.h"

namespace parkloc::ocr {

struct PlacedWindowOptions {
  // Each text gets a square window of this side (metres) around its centre: a 0.45 m tall
  // number with its margin, and room for the pose's error.
  double side_m = 2.4;
  // A text whose centre lies this far (metres) inside the floor view is left to it.
  double inside_margin_m = 0.5;
  // A text that would show less than this many pixels tall in the raw image, were it
  // `text_height_m` tall (apparentHeightPx), gets no window: too small to find. Val split,
  // first 40 frame sets a drive, 10 / 20 / 25 / 30 px: parking-number detection F 0.953 /
  // 0.953 / 0.949 / 0.938 (0.936 without windows), images a second 8.3 / 11.5 / 13.3 / 10.6
  // on a noisy machine (docs/OCR.md). 0: every text.
  double min_height_px = 20.0;
  double text_height_m = 0.45;  // the garage's painted numbers
  // At most this many texts get a window, the tallest first (0: every text): each costs
  // detection and, where something shows, reading.
  int max_texts = 2;
};

// Windows of `reach` (a wider view of the same camera at the same resolution) around the
// texts of `placed` whose centre `reach` sees on the floor and lies outside `view` (less the
// margin), tall enough in the raw image: in `reach`'s pixels, overlapping windows merged, sides
// multiples of 32 (the detector's stride) where `reach` has room, inside `reach`.
std::vector<cv::Rect> windowsBeyondView(const GroundView& view, const GroundView& reach,
                                        const std::vector<map::PlacedText>& placed,
                                        const PlacedWindowOptions& options = {});

// Windows of a view side by side in one image, a black gap between them, so that the detector
// and the recognizer see them all in one run each.
struct WindowMosaic {
  cv::Mat image;
  std::vector<cv::Rect> tiles;      // each window's place in `image`
  std::vector<cv::Point2f> shifts;  // ... and what to add to its pixels to get view pixels
  // The shift for what lies at `image` pixel `p`: its tile's; empty in a gap.
  std::optional<cv::Point2f> shiftAt(const cv::Point2f& p) const;
};
WindowMosaic mosaicOf(const GroundView& view, const cv::Mat& raw,
                      const std::vector<cv::Rect>& windows, int gap_px = 32);

// How tall a text `height_m` metres tall (across its reading direction) at its place shows in
// the raw image, in pixels: the distance between the images of its top and bottom edges'
// midpoints. 0 when either is out of the lens' field.
double apparentHeightPx(const GroundView& view, const map::PlacedText& text, double height_m);

}  // namespace parkloc::ocr
