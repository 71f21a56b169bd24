#pragma once
// A tracked vehicle knows where it is to a few centimetres, so it knows which floor numbers
// can lie under each box it finds: the map's texts placed in the vehicle frame under a
// predicted pose. A box then decodes against the few texts placed near it instead of every
// text of the garage, which the recognizer would otherwise confuse across the garage (D007
// read as D002, five bays away). The "lexicon of the texts near a predicted pose".
#include <Eigen/Core>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/pose.h"
#include "map/hd_map.h"

namespace parkloc::map {

// A map text, where its centre lies on the floor and which way it reads, in the vehicle frame
// (metres; a unit vector), its class, and its size on the floor (metres; 0 when unknown).
struct PlacedText {
  std::string text;
  Eigen::Vector2d vehicle_xy = Eigen::Vector2d::Zero();
  Eigen::Vector2d reading = Eigen::Vector2d::UnitX();
  TextClass cls = TextClass::kParkingNumber;
  double width = 0.0;   // along the reading direction
  double height = 0.0;  // across it
};

// How far from the vehicle a text can still show in a camera's floor view (ocr::GroundView
// reaches 6 m ahead of and beside each camera), with room for the pose's error: the radius the
// callers of placeFloorTexts place texts within.
inline constexpr double kFloorViewReachM = 15.0;

// The texts painted on the floor of `level` (every level when empty) whose centre lies within
// `radius` metres of the vehicle at `map_from_vehicle`, placed in the vehicle frame.
std::vector<PlacedText> placeFloorTexts(const HdMap& map, const geometry::Pose2& map_from_vehicle,
                                        double radius, const std::string& level = "");

// The texts placed within `radius` metres of `vehicle_xy`, each once, nearest first.
std::vector<std::string> textsNear(const std::vector<PlacedText>& placed,
                                   const Eigen::Vector2d& vehicle_xy, double radius);

// The text placed nearest `vehicle_xy` within `radius` metres, of those that read `text`
// (empty: of all); null when there is none.
const PlacedText* nearestPlaced(const std::vector<PlacedText>& placed,
                                const Eigen::Vector2d& vehicle_xy, double radius,
                                std::string_view text = {});

// The text placed with `vehicle_xy` on its footprint on the floor (its width by its height,
// grown by `margin` metres on every side), the one whose centre is nearest when several are;
// null when there is none or no footprint is known.
const PlacedText* placedTextUnder(const std::vector<PlacedText>& placed,
                                  const Eigen::Vector2d& vehicle_xy, double margin);

// The way the texts placed within `radius` metres of `vehicle_xy` read, when there are some and
// they all read within `max_angle` radians of the nearest one (its direction); empty otherwise.
// A box found there can then be read that way round only: the two bays facing each other across
// an aisle read opposite ways, but lie an aisle apart.
std::optional<Eigen::Vector2d> readingDirectionNear(const std::vector<PlacedText>& placed,
                                                    const Eigen::Vector2d& vehicle_xy,
                                                    double radius, double max_angle);

}  // namespace parkloc::map
