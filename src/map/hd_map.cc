#include "map/hd_map.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "common/error.h"

namespace parkloc::map {
namespace {
// Packs two cell indices into one key. Shifts on unsigned values: left-shifting a negative
// signed value is undefined behaviour (UBSan flags it for cells at negative coordinates).
long long packCell(long long ix, long long iy) {
  return static_cast<long long>((static_cast<unsigned long long>(ix) << 32) ^
                                (static_cast<unsigned long long>(iy) & 0xffffffffULL));
}
// Grid index of one coordinate, clamped to 32 bits: the map accepts any finite position, and
// a far-out landmark or query then shares the outermost cell instead of overflowing the
// double-to-integer cast (undefined behaviour; found by fuzz/fuzz_map).
long long cellIndex(double coordinate, double cell_size) {
  return static_cast<long long>(
      std::clamp(std::floor(coordinate / cell_size), -2147483648.0, 2147483647.0));
}
}  // namespace

HdMap::HdMap(std::vector<Landmark> landmarks, std::string name, MapAccuracy accuracy,
             bool complete)
    : name_(std::move(name)),
      accuracy_(accuracy),
      complete_(complete),
      landmarks_(std::move(landmarks)) {
  const std::string who = "map " + (name_.empty() ? std::string("(unnamed)") : name_) + ": ";
  if (const std::string problem = accuracyProblem(accuracy_); !problem.empty())
    throw InputError(who + "map-wide " + problem);
  if (const std::string problem = validate(landmarks_); !problem.empty())
    throw InputError(who + problem);
  for (size_t i = 0; i < landmarks_.size(); ++i) {
    by_text_.emplace(landmarks_[i].text, i);
    by_id_.emplace(landmarks_[i].id, i);
    grid_[cellOf(landmarks_[i].position.head<2>())].push_back(i);
  }
}

std::string HdMap::validate(const std::vector<Landmark>& landmarks) {
  std::set<std::string> ids;
  std::set<std::pair<std::string, std::string>> numbers;  // (level, text)
  for (const auto& l : landmarks) {
    const std::string who = "landmark '" + l.id + "'";
    if (l.id.empty()) return "a landmark has an empty id";
    if (!ids.insert(l.id).second) return "duplicate id '" + l.id + "'";
    if (l.text.empty()) return who + ": empty text";
    if (!l.position.allFinite() || !std::isfinite(l.heading) || !std::isfinite(l.width) ||
        !std::isfinite(l.height) || !l.normal.allFinite())
      return who + ": non-finite value";
    if (l.width <= 0.0 || l.height <= 0.0) return who + ": width and height must be positive";
    if (const std::string problem = accuracyProblem(l.accuracy); !problem.empty())
      return who + ": " + problem;
    if (l.surface == Surface::kVertical && std::abs(l.normal.norm() - 1.0) > 1e-3)
      return who + ": vertical text needs a unit face normal";
    if (l.cls == TextClass::kParkingNumber && !numbers.insert({l.level, l.text}).second)
      return who + ": parking number '" + l.text + "' appears twice on level '" + l.level + "'";
  }
  return "";
}

std::vector<const Landmark*> HdMap::findByText(const std::string& text,
                                               const std::string& level) const {
  std::vector<const Landmark*> out;
  const auto [begin, end] = by_text_.equal_range(text);
  for (auto it = begin; it != end; ++it) {
    const Landmark& l = landmarks_[it->second];
    if (level.empty() || l.level == level) out.push_back(&l);
  }
  return out;
}

const Landmark* HdMap::findById(const std::string& id) const {
  const auto it = by_id_.find(id);
  return it == by_id_.end() ? nullptr : &landmarks_[it->second];
}

HdMap::CellKey HdMap::cellOf(const Eigen::Vector2d& p) const {
  return packCell(cellIndex(p.x(), cell_size_), cellIndex(p.y(), cell_size_));
}

std::vector<const Landmark*> HdMap::withinRadius(const Eigen::Vector2d& center, double radius,
                                                 const std::string& level) const {
  std::vector<const Landmark*> out;
  if (!(radius >= 0.0) || !center.allFinite()) return out;
  const auto matches = [&](const Landmark& l) {
    return (l.position.head<2>() - center).norm() <= radius && (level.empty() || l.level == level);
  };
  const long long x0 = cellIndex(center.x() - radius, cell_size_);
  const long long x1 = cellIndex(center.x() + radius, cell_size_);
  const long long y0 = cellIndex(center.y() - radius, cell_size_);
  const long long y1 = cellIndex(center.y() + radius, cell_size_);
  // A query wider than the map has landmarks (a huge or infinite radius) scans the landmarks
  // instead of up to 2^64 empty cells.
  if ((static_cast<double>(x1 - x0) + 1.0) * (static_cast<double>(y1 - y0) + 1.0) >
      static_cast<double>(landmarks_.size())) {
    for (const Landmark& l : landmarks_)
      if (matches(l)) out.push_back(&l);
    return out;
  }
  for (long long ix = x0; ix <= x1; ++ix) {
    for (long long iy = y0; iy <= y1; ++iy) {
      const auto it = grid_.find(packCell(ix, iy));
      if (it == grid_.end()) continue;
      for (const size_t i : it->second) {
        if (matches(landmarks_[i])) out.push_back(&landmarks_[i]);
      }
    }
  }
  return out;
}

std::vector<std::string> distinctTexts(const HdMap& map, bool floor_only) {
  std::set<std::string> texts;
  for (const Landmark& landmark : map.landmarks())
    if (!floor_only || landmark.surface == Surface::kGround) texts.insert(landmark.text);
  return {texts.begin(), texts.end()};
}

std::vector<std::string> distinctLevels(const HdMap& map) {
  std::set<std::string> levels;
  for (const Landmark& landmark : map.landmarks()) levels.insert(landmark.level);
  return {levels.begin(), levels.end()};
}

std::set<std::string> levelsWithText(const HdMap& map, const std::string& text) {
  std::set<std::string> levels;
  for (const Landmark* landmark : map.findByText(text)) levels.insert(landmark->level);
  return levels;
}

}  // namespace parkloc::map
