// libFuzzer target: rig calibration YAML (io::loadCalibration, OpenCV FileStorage).
// A loaded rig must be one that the rest of the system can use, and must survive a
// save/load round trip.
#include <Eigen/Core>
#include <cmath>
#include <set>

#include "fuzz_support.h"
#include "io/calibration_yaml.h"

namespace {

using parkloc::fuzz::check;

void checkRig(const parkloc::geometry::Rig& rig) {
  check(!rig.cameras.empty(), "a rig without cameras");
  std::set<std::string> names;
  for (const auto& camera : rig.cameras) {
    check(names.insert(camera.name).second, "duplicate camera name");
    const auto& m = camera.model;
    check(m.width > 0 && m.height > 0, "non-positive image size");
    check(std::isfinite(m.fx) && std::isfinite(m.fy) && m.fx > 0.0 && m.fy > 0.0,
          "focal length not finite and positive");
    check(std::isfinite(m.cx) && std::isfinite(m.cy), "principal point not finite");
    for (const double k : m.distortion) check(std::isfinite(k), "distortion not finite");
    check(std::isfinite(m.max_theta) && m.max_theta > 0.0, "max_theta not finite and positive");
    const Eigen::Matrix3d R = camera.vehicle_from_camera.linear();
    check(R.allFinite() && camera.vehicle_from_camera.translation().allFinite(),
          "extrinsics not finite");
    check((R.transpose() * R - Eigen::Matrix3d::Identity()).norm() < 1e-5 && R.determinant() > 0,
          "extrinsic rotation not a rotation");
    if (camera.body)
      check(camera.body->lo.allFinite() && camera.body->hi.allFinite() &&
                (camera.body->lo.array() < camera.body->hi.array()).all(),
            "vehicle body not a finite box");
  }
}

}  // namespace

// One input: parse, then check the result against the contract.
static void fuzzOne(const uint8_t* data, size_t size) {
  static const parkloc::fuzz::ScratchFile input("calib.yaml");
  static const parkloc::fuzz::ScratchFile saved("calib-saved.yaml");
  const std::string& path = input.write(data, size);
  parkloc::geometry::Rig rig;
  if (!parkloc::fuzz::acceptsOnlyInputError([&] { rig = parkloc::io::loadCalibration(path); }))
    return;
  checkRig(rig);
  parkloc::io::saveCalibration(rig, saved.path());
  parkloc::geometry::Rig again;
  if (!parkloc::fuzz::acceptsOnlyInputError(
          [&] { again = parkloc::io::loadCalibration(saved.path()); }))
    parkloc::fuzz::violation("a saved calibration does not load again");
  check(again.cameras.size() == rig.cameras.size(), "round trip changed the number of cameras");
  for (size_t i = 0; i < rig.cameras.size(); ++i) {
    check(again.cameras[i].name == rig.cameras[i].name, "round trip changed a camera name");
    check(again.cameras[i].body.has_value() == rig.cameras[i].body.has_value(),
          "round trip lost or made a vehicle body");
  }
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  parkloc::fuzz::withoutDescriptorLeak([&] { fuzzOne(data, size); });
  return 0;
}
