#pragma once
// What a real car camera adds to the light it receives: auto exposure that hunts from frame to
// frame and follows the scene's brightness, a white balance that leaves the lamps' colour cast,
// an HDR tone curve that clips highlights and crushes shadows, dirt on the lens that veils the
// image and glows near lamps, flare (veiling glare and a ghost mirrored through the image
// centre) from the lamps in view, and the blocks of a video codec at a low bit rate. Applied to
// the rendered 8-bit image of one camera; none of them moves any text, so the labels stand.
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "geometry/rig.h"
#include "sim/appearance.h"

namespace parkloc::sim {

class CameraEffects {
 public:
  // The drive's effects: its colour cast and each camera's lens dirt are drawn once from
  // `seed`, the exposure's hunting per frame.
  CameraEffects(const AppearanceOptions& appearance, const geometry::Rig& rig, uint64_t seed);

  // Whether any camera factor is on; apply() leaves images untouched otherwise.
  bool active() const { return active_; }
  // Applies the effects to camera `camera`'s image at drive time `t` seconds; `frame_seed`
  // makes the frame's draws reproducible.
  void apply(cv::Mat& bgr, size_t camera, double t, uint64_t frame_seed) const;
  // apply() in its two steps: the optics and the image processor (exposure, white balance,
  // tone curve), then the video codec. Between them the image is what the sensor's pipeline
  // made of the scene before any compression (sim/ink_through_camera.h compares the two).
  void develop(cv::Mat& bgr, size_t camera, double t) const;
  void compress(cv::Mat& bgr, size_t camera, uint64_t frame_seed) const;

  // The per-channel gains (B, G, R) of the drive's white balance for `camera`.
  cv::Vec3f whiteBalanceGains(size_t camera) const { return white_balance_.at(camera); }
  // The exposure gain of camera `camera` at time `t` before metering: its hunting alone.
  double huntingGain(size_t camera, double t) const;

 private:
  AppearanceOptions a_;
  bool active_ = false;
  std::vector<cv::Vec3f> white_balance_;  // per camera
  std::vector<cv::Mat> dirt_;             // per camera, CV_32F in [0, 1], a quarter size
  std::vector<double> phase_;             // per camera, of the exposure's hunting
};

}  // namespace parkloc::sim
