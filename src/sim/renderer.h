#pragma once
// Ray-casting renderer of one garage level through the rig's fisheye cameras. Each camera
// has a precomputed table of unit rays (unprojected once); per frame every pixel's ray is
// rotated into the map and intersected with the level: floor, ceiling, walls (the interior
// box), pillars and cars (slab tests against the boxes whose projection covers the pixel's
// 16x16 tile). Floor, paint and text are looked up in mip-mapped textures at the pixel's
// footprint, so near text is sharp and far text is not aliased.
#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "geometry/pose.h"
#include "geometry/rig.h"
#include "sim/garage.h"

namespace parkloc::sim {

// Per camera: unit rays in the camera frame (zero where the model has no ray), the angle
// a pixel subtends (radians) and the vignetting factor.
struct CameraRays {
  int width = 0, height = 0;
  std::vector<Eigen::Vector3f> rays;
  std::vector<float> pixel_angle;
  std::vector<float> vignette;
};
CameraRays buildCameraRays(const geometry::CameraModel& model, float vignetting = 0.35f);
std::vector<CameraRays> buildRigRays(const geometry::Rig& rig);

// Light and sensor of one drive. "bright": every lamp on, low noise; "weak": dim, a third of
// the lamps off, high gain noise; "blur": bright light with defocus and motion blur.
struct LightingOptions {
  float ambient = 0.22f;
  float lamp_power = 6.0f;  // irradiance x distance^2 of one lamp
  float lamps_on_share = 1.0f;
  float exposure = 1.0f;
  float noise_sigma = 1.5f;     // grey levels (8-bit) of Gaussian sensor noise
  float defocus_sigma = 0.0f;   // pixels
  float motion_blur_px = 0.0f;  // horizontal blur length on the side cameras
  uint64_t lamp_seed = 1;       // which lamps are off
};
LightingOptions lightingForCondition(const std::string& condition, uint64_t seed);

class Renderer {
 public:
  // A camera with a body (geometry::RigCamera::body) sees that body where its rays meet it.
  Renderer(const Garage& garage, int level, const geometry::Rig& rig,
           std::shared_ptr<const std::vector<CameraRays>> rays, const LightingOptions& light);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // The 8-bit BGR image of camera `camera` (index into the rig) at the vehicle pose.
  // Deterministic: the same pose and seed give the same image. Runs over rows with
  // cv::parallel_for_.
  cv::Mat renderCamera(size_t camera, const geometry::Pose2& map_from_vehicle,
                       uint64_t noise_seed) const;
  std::vector<cv::Mat> render(const geometry::Pose2& map_from_vehicle, uint64_t noise_seed) const;

  const GarageLevel& level() const;
  const LightingOptions& light() const;
  // The noise-free contrast, in 8-bit luma levels before the blur, between floor text
  // `decal` (index into level().floor_decals) at its mean ink (opacity times the share that
  // wear left) and the bare floor under it, at the text's centre under this drive's lamps,
  // exposure and tone curve, seen through `pixel` of `camera` (vignetting).
  double floorInkContrast(size_t camera, const Eigen::Vector2d& pixel, int decal) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace parkloc::sim
