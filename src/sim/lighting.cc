#include "sim/lighting.h"

#include <random>

namespace parkloc::sim {

LightingOptions lightingForCondition(const std::string& condition, uint64_t seed) {
  std::mt19937_64 rng(seed);
  auto u = [&](double a, double b) {
    return static_cast<float>(std::uniform_real_distribution<double>(a, b)(rng));
  };
  LightingOptions l;
  l.lamp_seed = seed ^ 0x5bd1e995ULL;
  if (condition == "weak") {
    l.ambient = u(0.02f, 0.05f);
    l.lamp_power = u(2.0f, 3.5f);
    l.lamps_on_share = u(0.4f, 0.7f);
    l.exposure = u(0.65f, 0.95f);
    l.noise_sigma = u(4.0f, 7.0f);
  } else {
    l.ambient = u(0.15f, 0.3f);
    l.lamp_power = u(5.0f, 8.0f);
    l.lamps_on_share = u(0.9f, 1.0f);
    l.exposure = u(0.85f, 1.1f);
    l.noise_sigma = u(1.0f, 2.0f);
    if (condition == "blur") {
      l.defocus_sigma = u(1.0f, 2.0f);
      l.motion_blur_px = u(4.0f, 9.0f);
    }
  }
  return l;
}

}  // namespace parkloc::sim
