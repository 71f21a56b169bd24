#include "sim/garage_appearance.h"

#include <random>

#include "sim/floor_finish.h"
#include "sim/floor_wear.h"
#include "sim/number_styles.h"

namespace parkloc::sim {

Garage withAppearance(const Garage& base, const AppearanceOptions& a) {
  Garage g = base;
  auto stream = [&](uint64_t salt) { return std::mt19937_64(base.seed ^ salt); };
  if (a.epoxy > 0.0f) {
    auto rng = stream(0x3e90c1a7ULL);
    coatWithEpoxy(g, a.epoxy, rng);
  }
  if (a.gloss > 0.0f) {
    auto rng = stream(0x61055f00ULL);
    makeFloorGlossy(g, a.gloss, rng);
  }
  if (a.floor_wear > 0.0f) {
    auto rng = stream(0x7eac0001ULL);
    for (GarageLevel& level : g.levels) level.floor_grime = floorGrime(g, level, a.floor_wear, rng);
  }
  if (a.stencil > 0.0f || a.outlined > 0.0f || a.boxed > 0.0f || a.faded > 0.0f) {
    auto rng = stream(0x57e4c115ULL);
    styleNumbers(g, a, rng);
  }
  return g;
}

}  // namespace parkloc::sim
