// libFuzzer target: per-image text labels JSON (io::loadLabels). Polygons must be finite,
// and a save/load round trip must keep every instance.
#include <cmath>

#include "fuzz_support.h"
#include "io/labels.h"

// One input: parse, then check the result against the contract.
static void fuzzOne(const uint8_t* data, size_t size) {
  using parkloc::fuzz::check;
  static const parkloc::fuzz::ScratchFile input("labels.json");
  static const parkloc::fuzz::ScratchFile saved("labels-saved.json");
  static const parkloc::fuzz::ScratchFile icdar("labels-icdar.txt");
  const std::string& path = input.write(data, size);
  parkloc::io::ImageLabels labels;
  if (!parkloc::fuzz::acceptsOnlyInputError([&] { labels = parkloc::io::loadLabels(path); }))
    return;
  check(std::isfinite(labels.timestamp), "non-finite timestamp");
  for (const auto& inst : labels.instances) {
    for (const auto& p : inst.polygon) check(p.allFinite(), "non-finite polygon point");
    check(std::isfinite(inst.occluded_fraction) && std::isfinite(inst.rotation_deg),
          "non-finite instance field");
    check(inst.paint_wear >= 0.0 && inst.paint_wear <= 1.0, "paint wear outside [0, 1]");
  }
  parkloc::io::saveLabels(labels, saved.path());
  parkloc::io::saveIcdarLabels(labels, icdar.path());
  parkloc::io::ImageLabels again;
  if (!parkloc::fuzz::acceptsOnlyInputError([&] { again = parkloc::io::loadLabels(saved.path()); }))
    parkloc::fuzz::violation("saved labels do not load again");
  check(again.camera == labels.camera && again.width == labels.width &&
            again.height == labels.height && again.instances.size() == labels.instances.size(),
        "round trip changed the labels");
  for (size_t i = 0; i < labels.instances.size(); ++i)
    check(again.instances[i].text == labels.instances[i].text &&
              again.instances[i].polygon == labels.instances[i].polygon &&
              again.instances[i].paint_wear == labels.instances[i].paint_wear,
          "round trip changed an instance");
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  parkloc::fuzz::withoutDescriptorLeak([&] { fuzzOne(data, size); });
  return 0;
}
