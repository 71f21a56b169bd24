#pragma once
// The HD map: text landmarks with lookup by exact text and a spatial index for radius
// queries. Pure in-memory data; reading and writing GeoJSON lives in io/.
#include <Eigen/Core>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include "map/landmark.h"

namespace parkloc::map {

class HdMap {
 public:
  HdMap() = default;
  // Checks the landmarks (see validate) and builds the indexes; throws InputError.
  // `accuracy` is the map-wide default the file states (its landmarks carry it already where
  // they state none of their own). `complete`: the map holds every text of the area it covers
  // (a survey, a CAD drawing); false for one built from drives, which holds what they read.
  explicit HdMap(std::vector<Landmark> landmarks, std::string name = "", MapAccuracy accuracy = {},
                 bool complete = true);

  const std::string& name() const { return name_; }
  const MapAccuracy& accuracy() const { return accuracy_; }
  bool complete() const { return complete_; }
  const std::vector<Landmark>& landmarks() const { return landmarks_; }
  size_t size() const { return landmarks_.size(); }

  // Landmarks whose text equals `text` exactly (on every level when `level` is empty).
  std::vector<const Landmark*> findByText(const std::string& text,
                                          const std::string& level = "") const;
  const Landmark* findById(const std::string& id) const;
  // Landmarks whose centre lies within `radius` metres (x-y distance) of `center`.
  std::vector<const Landmark*> withinRadius(const Eigen::Vector2d& center, double radius,
                                            const std::string& level = "") const;

  // Empty when valid, else the first problem: duplicate id, a parking number twice on one
  // level, non-finite or non-positive size, empty text, a sigma out of range.
  static std::string validate(const std::vector<Landmark>& landmarks);

 private:
  using CellKey = long long;
  CellKey cellOf(const Eigen::Vector2d& p) const;

  std::string name_;
  MapAccuracy accuracy_;
  bool complete_ = true;
  std::vector<Landmark> landmarks_;
  std::unordered_multimap<std::string, size_t> by_text_;
  std::unordered_map<std::string, size_t> by_id_;
  // Uniform grid over x-y: cell -> landmark indices.
  double cell_size_ = 4.0;
  std::unordered_map<CellKey, std::vector<size_t>> grid_;
};

// Every distinct text of the map's landmarks, sorted; with `floor_only`, only those painted
// on the floor. Text spotting decodes against these (its lexicons).
std::vector<std::string> distinctTexts(const HdMap& map, bool floor_only = false);

// Every distinct level of the map's landmarks, sorted.
std::vector<std::string> distinctLevels(const HdMap& map);
// The levels on which the map has `text` (empty: on none).
std::set<std::string> levelsWithText(const HdMap& map, const std::string& text);

}  // namespace parkloc::map
