#pragma once
// A garage as a drive's appearance shows it: the floor's wear and finish and the styles of its
// painted numbers applied to the generated garage (sim/floor_wear.h, sim/floor_finish.h,
// sim/number_styles.h). The layout, the map and every text's box stay those of the garage, so
// the labels of a drive are the same whatever its look.
#include "sim/appearance.h"
#include "sim/garage.h"

namespace parkloc::sim {

// The garage with the garage factors of `appearance` applied; the camera factors are the
// dataset writer's (sim/camera_effects.h). Each factor draws from its own random stream
// seeded by the garage's seed, so switching one factor does not move another's marks.
Garage withAppearance(const Garage& garage, const AppearanceOptions& appearance);

}  // namespace parkloc::sim
