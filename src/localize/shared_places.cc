#include "localize/shared_places.h"

#include <algorithm>
#include <cmath>

namespace parkloc::localize {
namespace {

// Reading directions this close (cosine of 20 degrees) are one direction.
constexpr double kSameDirectionCos = 0.94;
// Sizes this close (share of the larger) are one size: the sizes of one text in a map differ by
// its survey, not by its font.
constexpr double kSameSizeShare = 0.10;

}  // namespace

bool samePlace(const map::Landmark& a, const map::Landmark& b, double tolerance_m) {
  if (a.surface != b.surface) return false;
  if ((a.position.head<2>() - b.position.head<2>()).norm() > tolerance_m) return false;
  return a.readingDirection().head<2>().dot(b.readingDirection().head<2>()) >= kSameDirectionCos;
}

bool interchangeable(const map::Landmark& a, const map::Landmark& b, double tolerance_m) {
  const auto close = [](double u, double v) {
    return std::abs(u - v) <= kSameSizeShare * std::max(u, v);
  };
  return samePlace(a, b, tolerance_m) && close(a.width, b.width) && close(a.height, b.height);
}

std::vector<const map::Landmark*> onePerPlace(const std::vector<const map::Landmark*>& landmarks,
                                              const std::string& preferred, double tolerance_m) {
  std::vector<const map::Landmark*> kept;
  for (const map::Landmark* l : landmarks) {
    const auto same = std::find_if(kept.begin(), kept.end(), [&](const map::Landmark* k) {
      return k->text == l->text && interchangeable(*k, *l, tolerance_m);
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
