#include "localize/shared_places.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace parkloc::localize {
namespace {

// Reading directions within 20 degrees are one direction.
constexpr double kSameDirectionRad = 20.0 * M_PI / 180.0;
// Sizes this close (share of the larger) are one size: the sizes of one text in a map differ by
// its survey, not by its font. A map that states its accuracy is a survey whose sizes are the
// nominal painted ones, each off by some per cent: two of them differ by up to three sigmas of
// their difference.
constexpr double kSameSizeShare = 0.10;
// Two surveys of one place differ by N(0, sa^2 + sb^2) per axis; 99 % of such horizontal
// differences lie within 3.03 sigmas (the Rayleigh distribution's 99th percentile).
constexpr double kSamePlaceSigmas = 3.03;

double squared(const std::optional<double>& sigma) { return sigma ? *sigma * *sigma : 0.0; }

}  // namespace

bool samePlace(const map::Landmark& a, const map::Landmark& b, double tolerance_m) {
  if (a.surface != b.surface) return false;
  // Where the map states its landmarks' survey error, one place surveyed on two levels may
  // differ by that much: the tolerance grows to what the errors allow.
  const double position_sigma =
      std::sqrt(squared(a.accuracy.position_sigma) + squared(b.accuracy.position_sigma));
  const double within = std::max(tolerance_m, kSamePlaceSigmas * position_sigma);
  if ((a.position.head<2>() - b.position.head<2>()).norm() > within) return false;
  const double heading_sigma =
      std::sqrt(squared(a.accuracy.heading_sigma) + squared(b.accuracy.heading_sigma));
  const double cos_within = std::cos(std::min(M_PI / 2, kSameDirectionRad + 3.0 * heading_sigma));
  return a.readingDirection().head<2>().dot(b.readingDirection().head<2>()) >= cos_within;
}

bool interchangeable(const map::Landmark& a, const map::Landmark& b, double tolerance_m,
                     double surveyed_size_sigma) {
  const bool surveyed = a.accuracy.position_sigma || b.accuracy.position_sigma;
  const double share =
      surveyed ? std::max(kSameSizeShare, 3.0 * std::sqrt(2.0) * surveyed_size_sigma)
               : kSameSizeShare;
  const auto close = [&](double u, double v) { return std::abs(u - v) <= share * std::max(u, v); };
  return samePlace(a, b, tolerance_m) && close(a.width, b.width) && close(a.height, b.height);
}

std::vector<const map::Landmark*> onePerPlace(const std::vector<const map::Landmark*>& landmarks,
                                              const std::string& preferred, double tolerance_m,
                                              double surveyed_size_sigma) {
  std::vector<const map::Landmark*> kept;
  for (const map::Landmark* l : landmarks) {
    const auto same = std::find_if(kept.begin(), kept.end(), [&](const map::Landmark* k) {
      return k->text == l->text && interchangeable(*k, *l, tolerance_m, surveyed_size_sigma);
    });
    if (same == kept.end())
      kept.push_back(l);
    else if (l->level == preferred && (*same)->level != preferred)
      *same = l;
  }
  return kept;
}

std::set<std::string> levelsWithTextAt(const map::HdMap& map, const std::string& text,
                                       const map::Landmark& at, double tolerance_m) {
  std::set<std::string> levels{at.level};
  for (const map::Landmark* l : map.findByText(text))
    if (samePlace(*l, at, tolerance_m)) levels.insert(l->level);
  return levels;
}

std::vector<SharedPlace> sharedPlaces(const std::vector<const map::Landmark*>& landmarks,
                                      const std::string& preferred, double tolerance_m) {
  std::vector<SharedPlace> places;
  for (const map::Landmark* l : landmarks) {
    const auto same = std::find_if(places.begin(), places.end(), [&](const SharedPlace& p) {
      return samePlace(*p.landmark, *l, tolerance_m);
    });
    if (same == places.end()) {
      places.push_back({l, {l->text}});
      continue;
    }
    if (std::find(same->texts.begin(), same->texts.end(), l->text) == same->texts.end())
      same->texts.push_back(l->text);
    if (l->level == preferred && same->landmark->level != preferred) {
      same->landmark = l;
      std::stable_partition(same->texts.begin(), same->texts.end(),
                            [&](const std::string& t) { return t == l->text; });
    }
  }
  return places;
}

}  // namespace parkloc::localize
