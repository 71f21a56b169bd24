// `parkloc calib check FILE`: load and validate a rig calibration, print what it describes.
#include <fmt/format.h>

#include <cmath>

#include "apps/parkloc/command.h"
#include "io/calibration_yaml.h"

namespace {

constexpr double kDeg = 180.0 / M_PI;

// Angle off the optical axis of the ray through `pixel`; NaN where the model cannot invert.
double offAxisAngle(const parkloc::geometry::CameraModel& m, double u, double v) {
  const auto ray = m.unproject({u, v});
  return ray ? std::acos(std::clamp(ray->z(), -1.0, 1.0)) : std::nan("");
}

std::string degrees(double radians) {
  return std::isfinite(radians) ? fmt::format("{:.1f}", radians * kDeg) : "n/a";
}

void printRig(const std::string& path) {
  const parkloc::geometry::Rig rig = parkloc::io::loadCalibration(path);
  fmt::print("calibration {}: {} camera{}\n", path, rig.cameras.size(),
             rig.cameras.size() == 1 ? "" : "s");
  for (const auto& camera : rig.cameras) {
    const auto& m = camera.model;
    // Field of view between the outer edges of the border pixels (pixel centres are integers).
    const double l = -0.5, r = m.width - 0.5, t = -0.5, b = m.height - 0.5;
    const double h_fov = offAxisAngle(m, l, m.cy) + offAxisAngle(m, r, m.cy);
    const double v_fov = offAxisAngle(m, m.cx, t) + offAxisAngle(m, m.cx, b);
    const double d_fov = offAxisAngle(m, l, t) + offAxisAngle(m, r, b);
    const Eigen::Vector3d p = camera.vehicle_from_camera.translation();
    const Eigen::Vector3d axis = camera.vehicle_from_camera.linear().col(2);
    fmt::print("  {:<8} {} {}x{}  f = ({:.2f}, {:.2f}) px  c = ({:.2f}, {:.2f}) px\n", camera.name,
               parkloc::geometry::toString(m.type), m.width, m.height, m.fx, m.fy, m.cx, m.cy);
    fmt::print("           position ({:.3f}, {:.3f}, {:.3f}) m in the vehicle frame\n", p.x(),
               p.y(), p.z());
    fmt::print("           looks at yaw {:.1f} deg, {:.1f} deg below the horizon\n",
               std::atan2(axis.y(), axis.x()) * kDeg, -std::asin(axis.z()) * kDeg);
    fmt::print("           field of view {} deg horizontal, {} deg vertical, {} deg diagonal\n",
               degrees(h_fov), degrees(v_fov), degrees(d_fov));
  }
}

const bool registered = parkloc::app::registerCommand([](CLI::App& parent) {
  auto* calib = parent.add_subcommand("calib", "Rig calibration files");
  calib->require_subcommand(1);
  auto* check = calib->add_subcommand("check", "Validate a calibration YAML and summarise it");
  auto path = std::make_shared<std::string>();
  check->add_option("FILE", *path, "calibration YAML (OpenCV FileStorage)")->required();
  check->callback([path] { printRig(*path); });
});

}  // namespace
