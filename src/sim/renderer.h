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
#include "sim/camera_rays.h"
#include "sim/garage.h"
#include "sim/lighting.h"

namespace parkloc::sim {

class Renderer {
 public:
  // A camera with a body (geometry::RigCamera::body) sees that body where its rays meet it.
  Renderer(const Garage& garage, int level, const geometry::Rig& rig,
           std::shared_ptr<const std::vector<CameraRays>> rays, const LightingOptions& light);
  // A level that is not one of the garage's (the ramp between two floors, sim/ramp_level.h)
  // inside the garage's shell; `level` must outlive the renderer and its decals index the
  // garage's textures.
  Renderer(const Garage& garage, const GarageLevel& level, const geometry::Rig& rig,
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
