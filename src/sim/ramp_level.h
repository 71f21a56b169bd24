#pragma once
// The ramp between two floors of a garage as the renderer draws it. A drive that changes level
// (DriveSpec::to_level) spends the ramp's seconds here: the garage's shell (floor, walls,
// ceiling and lamps) and the structural pillars, bare concrete, with no parked cars, no painted
// lines and no text. A real ramp has no parking slots, so no parking numbers and no pillar
// labels are in view; the levels of a simulated garage share their layout, so the car's x-y
// path runs on through it from one floor's aisles to the other's.
#include "sim/garage.h"

namespace parkloc::sim {

// The ramp leaving level `from_level` of the garage: its pillars and lamps, nothing else.
// Named "ramp"; its decals (none) and textures are the garage's, for
// Renderer(garage, level, ...).
GarageLevel rampLevel(const Garage& garage, int from_level);

}  // namespace parkloc::sim
