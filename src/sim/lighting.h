#pragma once
// The light and the sensor of one drive, drawn per recording condition.
#include <cstdint>
#include <string>

namespace parkloc::sim {

// Light and sensor of one drive. "bright": every lamp on, low noise; "weak": dim, a third of
// the lamps off, high gain noise; "blur": bright light with defocus and motion blur.
struct LightingOptions {
  float ambient = 0.22f;
  float lamp_power = 6.0f;  // irradiance x distance^2 of one lamp
  float lamps_on_share = 1.0f;
  float exposure = 1.0f;
  float noise_sigma = 1.5f;     // grey levels (8-bit) of Gaussian sensor noise
  float defocus_sigma = 0.0f;   // pixels
  float motion_blur_px = 0.0f;  // horizontal blur length on the side cameras
  uint64_t lamp_seed = 1;       // which lamps are off
};
LightingOptions lightingForCondition(const std::string& condition, uint64_t seed);

}  // namespace parkloc::sim
