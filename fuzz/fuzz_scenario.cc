// libFuzzer target: scenario YAML of `parkloc simulate` (sim::parseScenario, yaml-cpp).
// A parsed scenario must hold only values the generator accepts.
#include <cmath>

#include "fuzz_support.h"
#include "sim/scenario.h"

// One input: parse, then check the result against the contract.
static void fuzzOne(const uint8_t* data, size_t size) {
  using parkloc::fuzz::check;
  const std::string text(reinterpret_cast<const char*>(data), size);
  parkloc::sim::Scenario scenario;
  if (!parkloc::fuzz::acceptsOnlyInputError(
          [&] { scenario = parkloc::sim::parseScenario(text, "fuzz"); }))
    return;
  check(scenario.frame_rate >= 1.0 && scenario.frame_rate <= 60.0, "frame_rate out of range");
  check(scenario.odometry_rate >= scenario.frame_rate && scenario.odometry_rate <= 1000.0,
        "odometry_rate out of range");
  check(scenario.jpeg_quality >= 10 && scenario.jpeg_quality <= 100, "jpeg_quality out of range");
  check(!scenario.garages.empty(), "a scenario without garages");
  for (const auto& g : scenario.garages) {
    check(!g.levels.empty() && !g.fonts.empty() && !g.drives.empty(), "an empty garage list");
    check(g.aisles >= 1 && g.aisles <= 20 && g.slots_per_row >= 3 && g.slots_per_row <= 200 &&
              g.slots_per_pillar >= 1,
          "garage counts out of range");
    check(std::isfinite(g.slot_width) && std::isfinite(g.slot_depth) &&
              std::isfinite(g.aisle_width) && std::isfinite(g.ceiling_height),
          "garage size not finite");
    for (const auto& d : g.drives)
      check(d.duration_s > 0.0 && d.duration_s < 3600.0, "drive duration out of range");
  }
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  parkloc::fuzz::withoutDescriptorLeak([&] { fuzzOne(data, size); });
  return 0;
}
