// libFuzzer target: TUM trajectory files (io::loadTum). Every pose must be finite with a
// proper rotation, and a save/load round trip must keep the poses.
#include <cmath>

#include "fuzz_support.h"
#include "io/tum.h"

// One input: parse, then check the result against the contract.
static void fuzzOne(const uint8_t* data, size_t size) {
  using parkloc::fuzz::check;
  static const parkloc::fuzz::ScratchFile input("poses.tum");
  static const parkloc::fuzz::ScratchFile saved("poses-saved.tum");
  const std::string& path = input.write(data, size);
  std::vector<parkloc::io::StampedPose> poses;
  if (!parkloc::fuzz::acceptsOnlyInputError([&] { poses = parkloc::io::loadTum(path); })) return;
  for (const auto& p : poses) {
    check(std::isfinite(p.timestamp), "non-finite timestamp");
    check(p.pose.matrix().allFinite(), "non-finite pose");
    const Eigen::Matrix3d R = p.pose.linear();
    check((R.transpose() * R - Eigen::Matrix3d::Identity()).norm() < 1e-9 && R.determinant() > 0,
          "pose rotation not a rotation");
  }
  parkloc::io::saveTum(poses, saved.path());
  std::vector<parkloc::io::StampedPose> again;
  if (!parkloc::fuzz::acceptsOnlyInputError([&] { again = parkloc::io::loadTum(saved.path()); }))
    parkloc::fuzz::violation("a saved trajectory does not load again");
  check(again.size() == poses.size(), "round trip changed the number of poses");
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  parkloc::fuzz::withoutDescriptorLeak([&] { fuzzOne(data, size); });
  return 0;
}
