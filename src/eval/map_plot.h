#pragma once
// The plan view of a map (SVG): its landmarks as dots labelled with their text, the drives'
// paths as lines, and optionally a second map under it (the true one, grey) to look at a
// built map against the truth.
#include <string>
#include <vector>

#include "geometry/pose.h"
#include "map/hd_map.h"

namespace parkloc::eval {

struct MapPath {
  std::string label;
  std::string color;
  std::vector<geometry::Pose2> poses;
};

std::string mapPlotSvg(const std::string& title, const map::HdMap& map,
                       const std::vector<MapPath>& paths, const map::HdMap* under = nullptr);

}  // namespace parkloc::eval
