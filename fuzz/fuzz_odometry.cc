// libFuzzer target: wheel odometry CSV (io::loadOdometry). Samples must be finite with
// strictly increasing timestamps, and a save/load round trip must give the same doubles.
#include <cmath>

#include "fuzz_support.h"
#include "io/odometry_csv.h"

// One input: parse, then check the result against the contract.
static void fuzzOne(const uint8_t* data, size_t size) {
  using parkloc::fuzz::check;
  static const parkloc::fuzz::ScratchFile input("odometry.csv");
  static const parkloc::fuzz::ScratchFile saved("odometry-saved.csv");
  const std::string& path = input.write(data, size);
  std::vector<parkloc::OdometrySample> samples;
  if (!parkloc::fuzz::acceptsOnlyInputError([&] { samples = parkloc::io::loadOdometry(path); }))
    return;
  for (size_t i = 0; i < samples.size(); ++i) {
    const auto& s = samples[i];
    check(std::isfinite(s.timestamp) && std::isfinite(s.speed) && std::isfinite(s.yaw_rate),
          "non-finite sample");
    check(i == 0 || s.timestamp > samples[i - 1].timestamp, "timestamps not increasing");
  }
  parkloc::io::saveOdometry(samples, saved.path());
  std::vector<parkloc::OdometrySample> again;
  if (!parkloc::fuzz::acceptsOnlyInputError(
          [&] { again = parkloc::io::loadOdometry(saved.path()); }))
    parkloc::fuzz::violation("saved odometry does not load again");
  check(again.size() == samples.size(), "round trip changed the number of samples");
  for (size_t i = 0; i < samples.size(); ++i)
    check(again[i].timestamp == samples[i].timestamp && again[i].speed == samples[i].speed &&
              again[i].yaw_rate == samples[i].yaw_rate,
          "round trip changed a sample");
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  parkloc::fuzz::withoutDescriptorLeak([&] { fuzzOne(data, size); });
  return 0;
}
