// libFuzzer target: GeoJSON HD map (io::parseMap, nlohmann-json). A parsed map must survive
// a write/read round trip with the same landmarks, and its lookups must not misbehave.
#include <cmath>

#include "fuzz_support.h"
#include "io/map_geojson.h"

// One input: parse, then check the result against the contract.
static void fuzzOne(const uint8_t* data, size_t size) {
  using parkloc::fuzz::check;
  const std::string text(reinterpret_cast<const char*>(data), size);
  parkloc::map::HdMap map;
  if (!parkloc::fuzz::acceptsOnlyInputError([&] { map = parkloc::io::parseMap(text, "fuzz"); }))
    return;
  check(parkloc::map::HdMap::validate(map.landmarks()).empty(), "parsed map does not validate");
  for (const auto& l : map.landmarks()) {
    check(map.findById(l.id) == &l, "findById misses a landmark");
    check(!map.findByText(l.text, l.level).empty(), "findByText misses a landmark");
    check(!map.withinRadius(l.position.head<2>(), 0.5, l.level).empty(),
          "withinRadius misses a landmark at its own position");
  }
  parkloc::map::HdMap again;
  if (!parkloc::fuzz::acceptsOnlyInputError(
          [&] { again = parkloc::io::parseMap(parkloc::io::mapToGeoJson(map), "fuzz-again"); }))
    parkloc::fuzz::violation("a written map does not parse again");
  check(again.size() == map.size() && again.name() == map.name(), "round trip changed the map");
  for (size_t i = 0; i < map.size(); ++i) {
    const auto& a = map.landmarks()[i];
    const auto& b = again.landmarks()[i];
    check(a.id == b.id && a.text == b.text && a.level == b.level && a.cls == b.cls &&
              a.surface == b.surface && a.position == b.position && a.heading == b.heading &&
              a.width == b.width && a.height == b.height && a.normal == b.normal,
          "round trip changed a landmark");
  }
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  parkloc::fuzz::withoutDescriptorLeak([&] { fuzzOne(data, size); });
  return 0;
}
