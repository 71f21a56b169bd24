#pragma once
// The HD map as a GeoJSON FeatureCollection in a local metric frame (metres).
// See README "File formats" for the feature properties.
#include <string>

#include "map/hd_map.h"

namespace parkloc::io {

// Reads and validates a map. Throws InputError with one line naming the file, the feature
// and the problem: malformed JSON, missing property, duplicate id, a parking number twice
// on one level.
map::HdMap loadMap(const std::string& path);
map::HdMap parseMap(const std::string& geojson_text, const std::string& source_name);

// Writes the map; loadMap(saveMap(m)) gives back exactly the same landmarks.
void saveMap(const map::HdMap& map, const std::string& path);
std::string mapToGeoJson(const map::HdMap& map);

}  // namespace parkloc::io
