#pragma once
// Places that several levels of a garage share. Levels are usually built to one plan: the
// same parking number is painted at the same x-y on B1 and on B2, the pillars stand in the
// same places. Such landmarks fix the vehicle's x, y and yaw alike whichever level it is on,
// so until the level is known they count as one place (the pose is reported, the level left
// undecided), and a text read at such a place says nothing about the level.
#include <set>
#include <string>
#include <vector>

#include "map/hd_map.h"

namespace parkloc::localize {

// Whether two landmarks are at one place: on the same kind of surface, centres within
// `tolerance_m` in x-y and reading directions within 20 degrees (a pillar's four faces are
// four places); where the map states their survey error (Landmark::accuracy), within what
// that error allows (3 sigmas of the difference) when it is more.
bool samePlace(const map::Landmark& a, const map::Landmark& b, double tolerance_m);

// Whether two landmarks at one place also agree in size (width and height within 10 %; where
// the map states an accuracy, within three sigmas of the difference of two nominal sizes each
// known to `surveyed_size_sigma`, SolverOptions::map_size_sigma: 21 % at 5 %): only then do
// their corners fix the pose alike (one level's numbers may be painted in a narrower font than
// another's at the same place).
bool interchangeable(const map::Landmark& a, const map::Landmark& b, double tolerance_m,
                     double surveyed_size_sigma);

// One landmark per interchangeable group with one text: the one on `preferred` level (else the
// first). Order is kept.
std::vector<const map::Landmark*> onePerPlace(const std::vector<const map::Landmark*>& landmarks,
                                              const std::string& preferred, double tolerance_m,
                                              double surveyed_size_sigma);

// The levels on which the map has `text` at the place of `at` (its own level included).
std::set<std::string> levelsWithTextAt(const map::HdMap& map, const std::string& text,
                                       const map::Landmark& at, double tolerance_m);

// A place and every text the landmarks there carry, on any level: where levels differ at one
// place (B1's pillar says "B1", B2's says "A-1") a read there is asked for either.
struct SharedPlace {
  const map::Landmark* landmark = nullptr;  // on `preferred` level where it has one
  std::vector<std::string> texts;           // the landmark's own first
};
std::vector<SharedPlace> sharedPlaces(const std::vector<const map::Landmark*>& landmarks,
                                      const std::string& preferred, double tolerance_m);

}  // namespace parkloc::localize
