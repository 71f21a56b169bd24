#pragma once
// The landmarks' first guess, from their sightings cast on the floor through the dead-reckoned
// poses: the median centre, width and height of the cast quadrilaterals and the mean of their
// reading directions. Medians, so that a sighting cast from a bad corner does not drag it.
#include <optional>
#include <vector>

#include "mapping/consensus.h"
#include "mapping/landmark_estimate.h"

namespace parkloc::mapping {

LandmarkEstimate seedLandmark(const TextTrack& track,
                              const std::vector<std::optional<CastSighting>>& cast);

}  // namespace parkloc::mapping
