#pragma once
// The stitched top-down (AVM, around-view monitor) image many cars show their drivers: the
// floor around the vehicle seen from above, each part taken from the camera that sees it best,
// with the floor texts labelled in its pixels. The image is the vehicle's: forward is up, left
// is left; its scale is fixed, so a number's size in pixels is its size on the floor.
#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "geometry/pose.h"
#include "geometry/rig.h"
#include "io/labels.h"
#include "sim/garage.h"

namespace parkloc::sim {

struct BirdsEyeOptions {
  double metres_per_pixel = 0.02;
  double ahead_m = 7.0;       // of the rear axle (the vehicle origin)
  double behind_m = 4.2;      // of the rear axle
  double half_width_m = 5.6;  // to each side
};

class BirdsEyeStitcher {
 public:
  // Precomputes, per AVM pixel, the camera that shows it and where in that camera's image.
  explicit BirdsEyeStitcher(const geometry::Rig& rig, const BirdsEyeOptions& options = {});

  cv::Size size() const { return owner_.size(); }
  const BirdsEyeOptions& options() const { return options_; }
  // The AVM of one frame set (`images` in rig order): black where no camera sees the floor,
  // dark grey under the car.
  cv::Mat stitch(const std::vector<cv::Mat>& images) const;
  // Vehicle-frame ground point (x forward, y left) <-> AVM pixel (centres at integers).
  Eigen::Vector2d pixelFromVehicle(const Eigen::Vector2d& xy) const;
  Eigen::Vector2d vehicleFromPixel(const Eigen::Vector2d& pixel) const;
  // The camera (rig index) whose image fills the AVM at `pixel`; -1 where none sees the floor
  // or the car stands.
  int cameraAt(const Eigen::Vector2d& pixel) const;
  // Camera `camera`'s image pixel -> AVM pixel, through the floor; empty for a pixel whose ray
  // does not meet the floor.
  std::optional<Eigen::Vector2d> pixelFromCameraPixel(size_t camera,
                                                      const Eigen::Vector2d& pixel) const;
  size_t cameraCount() const { return map_x_.size(); }

 private:
  BirdsEyeOptions options_;
  geometry::Rig rig_;
  cv::Mat owner_;                       // CV_8S: camera index, -1 none, -2 the car
  std::vector<cv::Mat> map_x_, map_y_;  // per camera, CV_32F
};

// Labels of the AVM: the floor texts of `camera_labels` (one ImageLabels per rig camera, the
// same frame set), each taken from the camera that fills the AVM at the text's centre, its
// polygon the landmark's corners through the vehicle pose into AVM pixels; a text not wholly
// inside the AVM is left out. Legibility and occlusion are that camera's. Text above the floor
// that the stitching smears over it is labelled "not legible" (don't care).
io::ImageLabels birdsEyeLabels(const Garage& garage, int level, const BirdsEyeStitcher& stitcher,
                               const geometry::Pose2& map_from_vehicle,
                               const std::vector<io::ImageLabels>& camera_labels);

}  // namespace parkloc::sim
