#pragma once
// Wear of a used garage floor, over the concrete and its paint alike: dark tyre streaks along
// the driving lanes and arcs where cars turn into their slots, oil stains where engines stand,
// repair patches of fresher or older concrete, and hairline cracks. Real floors carry all four;
// streaks and cracks run across painted numbers as they do in a garage.
#include <opencv2/core.hpp>
#include <random>

#include "sim/garage.h"

namespace parkloc::sim {

// A multiplier on the floor's albedo (1: untouched) at garage.grime_texels_per_metre for
// level `level`; `strength` in (0, 1] scales how many marks there are and how dark.
cv::Mat floorGrime(const Garage& garage, const GarageLevel& level, float strength,
                   std::mt19937_64& rng);

}  // namespace parkloc::sim
