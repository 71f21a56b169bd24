#pragma once
// Ground-truth text labels of one rendered image: every text of the level (map landmarks
// and licence plates) projected through the vehicle pose and the camera, with truncation,
// occlusion by pillars, cars and the recording car itself (the camera's body), and the reading
// direction's angle in the image.
#include <functional>
#include <vector>

#include "geometry/pose.h"
#include "geometry/rig.h"
#include "io/labels.h"
#include "sim/garage.h"
#include "sim/legibility.h"

namespace parkloc::sim {

struct AnnotateOptions {
  // Text a reader could not read in this camera's image (sim/legibility.h: too thin, glyphs
  // squeezed along the reading direction, or smeared by `blur`) is labelled "not legible"
  // (don't care), down to an apparent height of min_labelled_height_px, and left out below,
  // so that a detector that still finds it is neither rewarded nor counted wrong.
  LegibilityOptions legibility;
  ImageBlur blur;  // the camera's, imageBlur(); none by default
  // Painted floor text must also stand out of the sensor's noise (inkStandsOut), when both
  // are given: the contrast of floor decal `decal` seen at image point `pixel`
  // (Renderer::floorInkContrast) and the noise per colour channel (LightingOptions::
  // noise_sigma). The label then carries the feature's SNR (io::LabelInstance::ink_snr).
  std::function<double(int decal, const Eigen::Vector2d& pixel)> floor_ink_contrast;
  double channel_noise = 0.0;
  // What the camera's processing and the codec make of that contrast at the text's image
  // polygon (sim/ink_through_camera.h), when set: the rule then weighs what the final image
  // carries, and the label's ink_snr is that image's.
  std::function<InkContrast(const InkContrast& scene, const geometry::TextPolygon& polygon)>
      through_camera;
  // Painted floor text that kept less than this share of its ink (Decal::ink_kept) is not
  // legible however large and sharp: with most of every glyph erased no reader makes out the
  // digits. 0: no such rule. The dataset writer sets it for drives whose appearance fades the
  // paint (sim/number_styles.h), which wears numbers that far.
  double min_ink_kept = 0.0;
  double min_labelled_height_px = 3.0;
  double max_distance = 30.0;        // metres from the camera
  double min_inside_fraction = 0.3;  // of the text's sample points inside the image
  int samples_u = 7, samples_v = 3;  // grid of points on the text for occlusion
};

std::vector<io::LabelInstance> annotateImage(const Garage& garage, int level,
                                             const geometry::RigCamera& camera,
                                             const geometry::Pose2& map_from_vehicle,
                                             const AnnotateOptions& options = {});

// True when the segment from `from` to `to` passes through one of the level's boxes
// (pillars, cars), excluding the last `end_margin` metres (the text's own surface).
bool segmentBlocked(const GarageLevel& level, const Eigen::Vector3d& from,
                    const Eigen::Vector3d& to, double end_margin = 0.01);

}  // namespace parkloc::sim
