#pragma once
// Shared fixtures of the sim tests: a half-resolution rig (fast), an empty garage level for
// single-marker renders, a small generated garage.
#include <memory>

#include "geometry/rig.h"
#include "sim/garage.h"
#include "sim/renderer.h"
#include "sim/scenario.h"

namespace parkloc::sim::testing {

inline geometry::Rig scaledRig(double s) {
  geometry::Rig rig = geometry::defaultRig();
  for (auto& c : rig.cameras) {
    auto& m = c.model;
    m.width = static_cast<int>(m.width * s);
    m.height = static_cast<int>(m.height * s);
    m.fx *= s;
    m.fy *= s;
    m.cx = (m.cx + 0.5) * s - 0.5;
    m.cy = (m.cy + 0.5) * s - 0.5;
  }
  return rig;
}

inline std::shared_ptr<const std::vector<CameraRays>> raysOf(const geometry::Rig& rig) {
  return std::make_shared<const std::vector<CameraRays>>(buildRigRays(rig));
}

// A 20 m x 20 m level with a uniform floor, no boxes, no paint, no lamps.
inline Garage emptyGarage() {
  Garage g;
  g.size = Eigen::Vector2d(20.0, 20.0);
  g.ceiling_height = 2.8;
  g.concrete = MipTexture(cv::Mat(64, 64, CV_8UC1, cv::Scalar(128)), true);
  g.levels.emplace_back();
  GarageLevel& L = g.levels.back();
  L.name = "B1";
  const cv::Mat no_paint(static_cast<int>(20 * g.paint_texels_per_metre),
                         static_cast<int>(20 * g.paint_texels_per_metre), CV_8UC1, cv::Scalar(0));
  L.paint_white = MipTexture(no_paint);
  L.paint_yellow = MipTexture(no_paint);
  L.floor_shade = cv::Mat(static_cast<int>(20 * g.shade_texels_per_metre),
                          static_cast<int>(20 * g.shade_texels_per_metre), CV_32F, cv::Scalar(1.0));
  return g;
}

inline LightingOptions flatLight() {
  LightingOptions l;
  l.ambient = 0.8f;
  l.noise_sigma = 0.0f;
  return l;
}

// One aisle, eight slots, no cars: fast to generate.
inline GarageSpec smallSpec() {
  GarageSpec s;
  s.name = "small";
  s.levels = {"B1"};
  s.aisles = 1;
  s.slots_per_row = 8;
  s.occupancy = 0.0;
  s.worn_share = 0.0;
  s.yellow_share = 0.0;
  s.fonts = {"DejaVuSans-Bold.ttf"};
  return s;
}

}  // namespace parkloc::sim::testing
