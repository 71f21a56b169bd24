#pragma once
// Each camera's pixels as unit rays, unprojected once per rig: the renderer turns them into
// the map every frame instead of unprojecting every pixel again.
#include <Eigen/Core>
#include <vector>

#include "geometry/camera_model.h"
#include "geometry/rig.h"

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

}  // namespace parkloc::sim
