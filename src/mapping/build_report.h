#pragma once
// What a map build did, as JSON for the report next to the map: per drive the reading's
// counts and time, the consensus's counts, the solver's summary, every landmark with its
// sightings, misreads, reprojection residual and sigmas (most sighted first), and the
// problems the build found.
#include <nlohmann/json.hpp>
#include <string>

#include "mapping/map_builder.h"

namespace parkloc::mapping {

nlohmann::json buildReportJson(const MapBuild& build, const std::string& level);

// Landmarks by number of frame sets that read them: "3-4": n, "5-9": n, "10+": n.
nlohmann::json sightingHistogram(const MapBuild& build);

}  // namespace parkloc::mapping
