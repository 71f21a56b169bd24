// `parkloc map check FILE`: load and validate a GeoJSON HD map, print what it holds.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>

#include "apps/parkloc/command.h"
#include "apps/parkloc/map_commands.h"
#include "io/map_geojson.h"

namespace {

using parkloc::map::Landmark;
using parkloc::map::TextClass;

// Distance from each parking number to the nearest other one on its level.
std::vector<double> nearestNumberSpacing(const parkloc::map::HdMap& map) {
  std::vector<double> spacing;
  for (const Landmark& a : map.landmarks()) {
    if (a.cls != TextClass::kParkingNumber) continue;
    double best = std::numeric_limits<double>::infinity();
    for (const Landmark& b : map.landmarks())
      if (&a != &b && b.cls == TextClass::kParkingNumber && b.level == a.level)
        best = std::min(best, (a.position.head<2>() - b.position.head<2>()).norm());
    if (std::isfinite(best)) spacing.push_back(best);
  }
  std::sort(spacing.begin(), spacing.end());
  return spacing;
}

std::string sigmaText(const std::optional<double>& sigma, bool angle) {
  if (!sigma) return "not stated";
  return angle ? fmt::format("{:.4f} rad ({:.2f} deg)", *sigma, *sigma * 180.0 / M_PI)
               : fmt::format("{:.3f} m", *sigma);
}

// The map-wide accuracy and the sigmas of the landmarks that state their own (a value other
// than the map-wide one).
void printAccuracy(const parkloc::map::HdMap& map) {
  const parkloc::map::MapAccuracy& fallback = map.accuracy();
  fmt::print("  map-wide accuracy: position_sigma {}, heading_sigma {}\n",
             sigmaText(fallback.position_sigma, false), sigmaText(fallback.heading_sigma, true));
  fmt::print("  complete: {}\n", map.complete() ? "yes, every text of the area it covers"
                                                 : "no, it holds what was read (a built map)");
  for (const bool heading : {false, true}) {
    std::vector<double> own;
    for (const Landmark& l : map.landmarks()) {
      const auto& sigma = heading ? l.accuracy.heading_sigma : l.accuracy.position_sigma;
      if (sigma && sigma != (heading ? fallback.heading_sigma : fallback.position_sigma))
        own.push_back(*sigma);
    }
    std::sort(own.begin(), own.end());
    const char* name = heading ? "heading_sigma" : "position_sigma";
    if (own.empty()) {
      fmt::print("  own {}: none of {} landmarks\n", name, map.size());
      continue;
    }
    fmt::print("  own {}: {} of {} landmarks, min {} / median {} / max {}\n", name, own.size(),
               map.size(), sigmaText(own.front(), heading), sigmaText(own[own.size() / 2], heading),
               sigmaText(own.back(), heading));
  }
}

void printMap(const std::string& path) {
  const parkloc::map::HdMap map = parkloc::io::loadMap(path);
  fmt::print("map {}: {} landmarks{}\n", path, map.size(),
             map.name().empty() ? "" : fmt::format(" ('{}')", map.name()));
  std::map<TextClass, int> per_class;
  std::map<std::string, int> per_level;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  for (const Landmark& l : map.landmarks()) {
    ++per_class[l.cls];
    ++per_level[l.level];
    lo = lo.cwiseMin(l.position);
    hi = hi.cwiseMax(l.position);
  }
  for (const TextClass cls : {TextClass::kParkingNumber, TextClass::kPillar, TextClass::kOther})
    fmt::print("  {:<15} {}\n", parkloc::map::toString(cls), per_class[cls]);
  for (const auto& [level, count] : per_level)
    fmt::print("  level '{}': {} landmarks\n", level, count);
  if (map.size() > 0)
    fmt::print("  extent x [{:.2f}, {:.2f}] m, y [{:.2f}, {:.2f}] m, z [{:.2f}, {:.2f}] m\n",
               lo.x(), hi.x(), lo.y(), hi.y(), lo.z(), hi.z());
  const std::vector<double> spacing = nearestNumberSpacing(map);
  if (spacing.empty())
    fmt::print("  parking-number spacing: n/a (fewer than two on any level)\n");
  else
    fmt::print(
        "  parking-number nearest-neighbour spacing: min {:.2f} m, median {:.2f} m, "
        "max {:.2f} m\n",
        spacing.front(), spacing[spacing.size() / 2], spacing.back());
  printAccuracy(map);
}

const bool registered = parkloc::app::registerCommand([](CLI::App& parent) {
  auto* map = parent.add_subcommand("map", "HD map files");
  map->require_subcommand(1);
  auto* check = map->add_subcommand("check", "Validate a GeoJSON map and summarise it");
  auto path = std::make_shared<std::string>();
  check->add_option("FILE", *path, "GeoJSON FeatureCollection of text landmarks")->required();
  check->callback([path] { printMap(*path); });
  parkloc::app::addMapBuild(*map);
});

}  // namespace
