#pragma once
// What a car camera's processing leaves of a painted text's contrast. The legibility rule
// (sim/legibility.h) weighs the ink's contrast against the sensor's noise in the scene the
// renderer draws; a real camera then veils it (flare, lens dirt), stretches or squeezes it
// (auto exposure, an HDR tone curve that crushes shadows and clips highlights) and blocks it
// (a video codec at a low bit rate). A reader gets that image, so the label's legibility must
// be judged on it: a number whose strokes the codec has turned into 8x8 blocks is not legible
// however well it stood out in the scene.
//
// The model, per text, from three images of one camera: the scene (rendered, noise
// included), the developed image (optics and image processor applied) and the final image
// (after the codec and the dataset's own JPEG).
//  - The processing maps a scene level to a developed level smoothly over one text, so its
//    local slope g (least squares of developed on scene luma over the text's pixels) scales
//    the ink's contrast and the sensor's noise alike.
//  - The codec keeps the strokes in proportion h, the slope of final on developed over the
//    text: where it turns them into flat 8x8 blocks h is near 0. What else it changes (the
//    residual of that fit) is noise the reader must see the strokes through; it comes in
//    blocks as large as a reading feature, so it is block noise (InkContrast::block_noise),
//    which summing over the feature does not average down. Part of the residual is the
//    sensor's noise the codec smoothed away, which harms no reading: up to the developed
//    noise's variance (g sigma)^2 is taken off it. The 8-bit rounding adds 1/12 of a level
//    squared to the white noise.
//  So the contrast is g h C, the white noise sqrt((g h sigma)^2 + 1/12) and the block noise
//  sqrt(max(0, residual - (g sigma)^2)).
// The result feeds the same Rose criterion (featureSnr) as the scene's contrast.
#include <opencv2/core.hpp>

#include "geometry/text_polygon.h"
#include "sim/legibility.h"

namespace parkloc::sim {

// The three stages of one camera's image (8-bit BGR, the same size).
struct CameraStages {
  cv::Mat scene;      // as rendered
  cv::Mat developed;  // CameraEffects::develop applied
  cv::Mat final;      // then CameraEffects::compress and the dataset's JPEG
};

// The slope, codec error and resulting contrast at one text.
struct InkThroughCamera {
  double gain = 1.0;        // g, developed luma levels per scene level
  double codec_kept = 1.0;  // h, final luma levels per developed level
  double codec_rms = 0.0;   // the codec's change not in proportion, luma levels
  InkContrast contrast;     // g h C, the white and the block noise (featureSnr's input)
  int pixels = 0;           // the text's pixels inside the image; 0: nothing measured
};

// The scene's ink contrast `scene` (Renderer::floorInkContrast, the lighting's channel noise)
// carried through the camera at the text whose image polygon is `polygon`. A text with fewer
// than 4 pixels in the image keeps the scene's contrast and noise; over pixels whose levels
// hardly spread a slope is not measured and taken as 1.
InkThroughCamera inkThroughCamera(const InkContrast& scene, const CameraStages& stages,
                                  const geometry::TextPolygon& polygon);

}  // namespace parkloc::sim
