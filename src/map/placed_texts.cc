#include "map/placed_texts.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace parkloc::map {

std::vector<PlacedText> placeFloorTexts(const HdMap& map, const geometry::Pose2& map_from_vehicle,
                                        double radius, const std::string& level) {
  const geometry::Pose2 vehicle_from_map = map_from_vehicle.inverse();
  std::vector<PlacedText> placed;
  for (const Landmark* l : map.withinRadius(map_from_vehicle.translation(), radius, level)) {
    if (l->surface != Surface::kGround) continue;
    const Eigen::Vector2d reading_in_map = l->readingDirection().head<2>();
    placed.push_back({l->text, vehicle_from_map * Eigen::Vector2d(l->position.head<2>()),
                      vehicle_from_map.rotation() * reading_in_map, l->cls, l->width, l->height});
  }
  return placed;
}

std::vector<std::string> textsNear(const std::vector<PlacedText>& placed,
                                   const Eigen::Vector2d& vehicle_xy, double radius) {
  std::vector<std::pair<double, const std::string*>> near;
  for (const PlacedText& p : placed) {
    const double d = (p.vehicle_xy - vehicle_xy).norm();
    if (d <= radius) near.emplace_back(d, &p.text);
  }
  std::stable_sort(near.begin(), near.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::string> texts;
  for (const auto& [d, text] : near)
    if (std::find(texts.begin(), texts.end(), *text) == texts.end()) texts.push_back(*text);
  return texts;
}

const PlacedText* nearestPlaced(const std::vector<PlacedText>& placed,
                                const Eigen::Vector2d& vehicle_xy, double radius,
                                std::string_view text) {
  const PlacedText* nearest = nullptr;
  double nearest_distance = radius;
  for (const PlacedText& p : placed) {
    const double d = (p.vehicle_xy - vehicle_xy).norm();
    if ((text.empty() || p.text == text) && d <= nearest_distance) {
      nearest = &p;
      nearest_distance = d;
    }
  }
  return nearest;
}

const PlacedText* placedTextUnder(const std::vector<PlacedText>& placed,
                                  const Eigen::Vector2d& vehicle_xy, double margin) {
  const PlacedText* under = nullptr;
  double under_distance = std::numeric_limits<double>::infinity();
  for (const PlacedText& p : placed) {
    if (p.width <= 0.0 || p.height <= 0.0) continue;
    const Eigen::Vector2d along = p.reading.normalized();
    const Eigen::Vector2d offset = vehicle_xy - p.vehicle_xy;
    const double x = offset.dot(along), y = offset.dot(Eigen::Vector2d(-along.y(), along.x()));
    if (std::abs(x) > 0.5 * p.width + margin || std::abs(y) > 0.5 * p.height + margin) continue;
    if (offset.norm() < under_distance) {
      under = &p;
      under_distance = offset.norm();
    }
  }
  return under;
}

std::optional<Eigen::Vector2d> readingDirectionNear(const std::vector<PlacedText>& placed,
                                                    const Eigen::Vector2d& vehicle_xy,
                                                    double radius, double max_angle) {
  const PlacedText* nearest = nearestPlaced(placed, vehicle_xy, radius);
  if (nearest == nullptr) return std::nullopt;
  const double min_cos = std::cos(max_angle);
  for (const PlacedText& p : placed)
    if ((p.vehicle_xy - vehicle_xy).norm() <= radius &&
        p.reading.normalized().dot(nearest->reading.normalized()) < min_cos)
      return std::nullopt;
  return nearest->reading.normalized();
}

}  // namespace parkloc::map
