#pragma once
// Corner refinement: DB's unclipped box is deliberately loose (the recognizer wants some
// background) and, being a rectangle in the raw fisheye image, cannot follow perspective or
// lens distortion. The localization uses the corners, so they are re-fitted to the text's
// ink:
//  - on the floor, with the camera known: the ink outline is cast onto the ground plane
//    (a bird's-eye view, where painted text is an undistorted rectangle), its minimum-area
//    rectangle is taken there and its corners are projected back into the raw image;
//  - otherwise: the ink's bounding box in the perspective-rectified crop, mapped back.
#include <opencv2/core.hpp>
#include <optional>

#include "geometry/rig.h"
#include "ocr/quad.h"

namespace parkloc::ocr {

struct CornerRefinementOptions {
  int crop_height = 64;  // rectified crop used to find the ink
  // The detected box is grown by these factors before looking for ink in it: DB's boxes
  // of PP-OCRv4 hug the glyphs and may cut them.
  float search_expand_x = 1.15f;
  float search_expand_y = 1.8f;
  double max_ground_height = 1.2;  // metres; taller text is not floor text
  double max_ground_width = 6.0;
  // Dim text (weak light): the crop is smoothed by this many raw-image pixels (sensor
  // noise is per raw pixel; the crop magnifies it) before it is thresholded, and ink and
  // background need only differ by min_contrast grey levels. The fit's size and place
  // checks, not a contrast floor, keep noise out.
  double denoise_sigma_raw_px = 1.0;
  double min_contrast = 8.0;
  // Where grey levels find no text (yellow paint on grey concrete beside a car's shadow), the
  // ink is looked for as the pixels whose colour lies far from the floor's.
  bool colour_fallback = true;
  // A fit shorter along the reading direction than this share of the box it refines has
  // lost part of the text (blurred glyphs whose ink breaks apart), not tightened the box,
  // which is then kept as it is: DB's boxes, unclipped, are about as long as the text.
  float min_length_share = 0.7f;
  // A number painted inside a frame or on a patch of colour: the glyphs inside, not the
  // backing's box (glyphsInsideBackings in corner_refinement.cc).
  bool frames = true;
  bool patches = true;
};

// Builds OpenCV's 8-bit Lab tables, which the colour fallback of the ink split needs. OpenCV
// builds them at the process's first BGR->Lab conversion, which takes about 150 ms: a spotter
// calls this when it is made, so that the cost does not fall on the first frame set whose ink
// split falls back on colour. Once per process; callers on other threads wait for the first.
void buildColourTables();

// Ink outline points (raw image pixels) of the text inside `quad`; empty when no clear ink
// is found.
std::vector<cv::Point2f> inkOutline(const cv::Mat& image, const Quad& quad,
                                    const CornerRefinementOptions& options = {});

// The ink's box in the rectified crop of `quad`, back in the image, reading order kept.
std::optional<Quad> refineInCrop(const cv::Mat& image, const Quad& quad,
                                 const CornerRefinementOptions& options = {});

// The ink's minimum-area rectangle on the ground plane (z = 0 of the vehicle frame), its
// corners projected into the camera's raw image, in the reading order of `quad`. Empty when
// the text does not fit floor text (above the horizon, too large).
std::optional<Quad> refineOnGround(const cv::Mat& image, const Quad& quad,
                                   const geometry::RigCamera& camera,
                                   const CornerRefinementOptions& options = {});

// Whether `refined` is a plausible fit of the box `detected`: every corner inside the box
// grown by a third along and a half across, and at least min_length_share of its length.
bool plausibleRefinement(const Quad& detected, const Quad& refined,
                         const CornerRefinementOptions& options = {});

}  // namespace parkloc::ocr
