#pragma once
// A text landmark of the HD map: a painted parking number, pillar text or other sign.
// Map frame: metres, x east, y north, z up.
#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>

namespace parkloc::map {

// Class ids as in the dataset labels: 0 pillar, 1 parking number, 2 other.
enum class TextClass { kPillar = 0, kParkingNumber = 1, kOther = 2 };
enum class Surface { kGround, kVertical };

std::string toString(TextClass cls);
std::optional<TextClass> textClassFromString(const std::string& name);
std::string toString(Surface surface);
std::optional<Surface> surfaceFromString(const std::string& name);

// How well a map knows its landmarks (1 sigma): the horizontal position of a text's centre
// per axis (metres) and its heading (radians). Empty: the map does not say, and the localizer
// assumes its own figure (pipeline.measurement.assumed_map_*).
struct MapAccuracy {
  std::optional<double> position_sigma;
  std::optional<double> heading_sigma;
  bool operator==(const MapAccuracy& o) const {
    return position_sigma == o.position_sigma && heading_sigma == o.heading_sigma;
  }
  bool operator!=(const MapAccuracy& o) const { return !(*this == o); }
};

// Sigmas beyond these are not a map's accuracy but a broken file: a text whose place is
// unknown to 10 m cannot be told from its neighbours, and past 0.5 rad (29 degrees) of heading
// the solver's linearised model of the map error (pose_solver.h) no longer holds.
inline constexpr double kMaxPositionSigmaM = 10.0;
inline constexpr double kMaxHeadingSigmaRad = 0.5;

// Empty when both sigmas are absent or finite and within [0, the bound above], else the
// problem, naming the property ("position_sigma: ...").
std::string accuracyProblem(const MapAccuracy& accuracy);

struct Landmark {
  std::string id;
  std::string text;
  TextClass cls = TextClass::kParkingNumber;
  std::string level;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // centre of the text
  // Reading direction of the text in the map's x-y plane (radians from +x).
  double heading = 0.0;
  double width = 0.0;   // along the reading direction, metres
  double height = 0.0;  // along the text's up direction, metres
  Surface surface = Surface::kGround;
  // Outward face normal for vertical text (horizontal, perpendicular to the heading).
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  // What the map states of this landmark's accuracy: the feature's own sigmas, else the
  // map's default (resolved when the map is read).
  MapAccuracy accuracy;

  // Unit vector along the reading direction and towards the top of the glyphs.
  Eigen::Vector3d readingDirection() const;
  Eigen::Vector3d upDirection() const;
  // Corners in reading order: top-left, top-right, bottom-right, bottom-left.
  std::array<Eigen::Vector3d, 4> corners() const;
};

}  // namespace parkloc::map
