#pragma once
// Comparing a built map with the true one (`parkloc eval map`): landmarks matched by text (on
// one level), the built map aligned to the true frame by the rigid SE(2) transform that
// minimises the squared position differences of the matches (refitted without those that stay
// beyond wrong_place_m), then per landmark the position, heading, width and height error.
// Completeness is over the true parking numbers a drive showed legibly in enough frame sets
// (legibleFrameSets); phantoms are built landmarks whose text the true level lacks or whose
// match stays beyond wrong_place_m (a wrong text at that place).
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "eval/statistics.h"
#include "geometry/planar_fit.h"
#include "io/sequence.h"
#include "map/hd_map.h"

namespace parkloc::eval {

struct MapComparisonOptions {
  // A matched landmark further than this after the alignment is at a wrong place (a phantom).
  double wrong_place_m = 0.5;
  // A true parking number counts for completeness when legible in this many frame sets.
  int legible_frame_sets = 3;
};

struct LandmarkError {
  std::string text;
  double position_m = 0.0;
  double heading_deg = 0.0;  // signed, wrapped
  double width_rel = 0.0;    // built / true - 1
  double height_rel = 0.0;
  bool wrong_place = false;
};

struct MapComparison {
  std::string level;
  std::optional<geometry::PlanarFit> fit;  // built -> true
  std::vector<LandmarkError> errors;       // matched landmarks, wrong places included
  Summary position_m;                      // over matches not at a wrong place
  Summary abs_heading_deg;
  Summary abs_width_rel;
  Summary abs_height_rel;
  int built = 0;
  int true_parking_numbers = 0;  // on the level
  int legible = 0;               // of them, legible enough (all when no drives are given)
  int legible_found = 0;
  double completeness = 0.0;          // legible_found / legible
  std::vector<std::string> missing;   // legible, not in the built map
  std::vector<std::string> phantoms;  // built, text not on the true level, or at a wrong place
};

// Per true landmark id, the frame sets of `drive` in which some camera shows it legibly (the
// label is legible and less than half hidden).
std::map<std::string, int> legibleFrameSets(const io::Sequence& drive);

// `level`: the true map's level to compare with (empty: the built map's level, else every
// level). `legible_frames` from the drives the map was built from (empty: every true parking
// number of the level counts).
MapComparison compareMaps(const map::HdMap& built, const map::HdMap& truth,
                          const std::string& level,
                          const std::map<std::string, int>& legible_frames,
                          const MapComparisonOptions& options);

}  // namespace parkloc::eval
