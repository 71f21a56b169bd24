#pragma once
// Sightings as JSON lines, one a line: what the reading found, so that the estimation can run
// again with other options without reading the images again (map build --sightings).
#include <string>
#include <vector>

#include "mapping/sightings.h"

namespace parkloc::mapping {

void saveSightings(const std::vector<Sighting>& sightings, const std::string& path);
// Throws InputError naming the file and line for a malformed line.
std::vector<Sighting> loadSightings(const std::string& path);

}  // namespace parkloc::mapping
