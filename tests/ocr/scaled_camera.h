#pragma once
// The same lens imaged at `factor` times the resolution: every pixel length scaled, pixel
// centres kept at integer coordinates (OpenCV's convention).
#include "geometry/camera_model.h"

namespace parkloc::ocr::testing {

inline geometry::CameraModel scaledCamera(geometry::CameraModel m, int factor) {
  m.width *= factor;
  m.height *= factor;
  m.fx *= factor;
  m.fy *= factor;
  m.cx = (m.cx + 0.5) * factor - 0.5;
  m.cy = (m.cy + 0.5) * factor - 0.5;
  return m;
}

}  // namespace parkloc::ocr::testing
