#pragma once
// Merging a built map into an existing one: the built landmarks are matched to the existing
// ones by text (on the built level) and the built map is moved into the existing frame by a
// rigid fit over the matches, refitted without those that stay far off (a landmark repainted
// elsewhere must not drag the frame). Then each matched landmark is either confirmed (within
// moved_threshold_m: the two estimates fused, weighted by their sigmas) or flagged as moved
// (it takes the built place, which is what the garage shows now); built landmarks the existing
// map lacks are added; existing ones the drive did not see are kept as they are.
#include <string>
#include <vector>

#include "geometry/planar_fit.h"
#include "map/hd_map.h"
#include "mapping/landmark_estimate.h"

namespace parkloc::mapping {

struct MergeOptions {
  // A matched landmark further than this from the existing one, after the fit, has moved:
  // several times the built map's position error, well under a parking bay.
  double moved_threshold_m = 0.15;
};

struct MapMerge {
  std::vector<map::Landmark> landmarks;
  geometry::PlanarFit fit;  // built -> existing frame
  int confirmed = 0;
  std::vector<std::string> moved;  // texts
  std::vector<std::string> added;
  int kept_unseen = 0;
};

// `built` is moved into the existing frame (its moved_m / added flags set). Throws InputError
// when fewer than two built texts are in the existing map at places that agree.
MapMerge mergeMaps(const map::HdMap& existing, std::vector<LandmarkEstimate>& built,
                   const std::string& level, const MergeOptions& options);

}  // namespace parkloc::mapping
