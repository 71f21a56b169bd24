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

  // Unit vector along the reading direction and towards the top of the glyphs.
  Eigen::Vector3d readingDirection() const;
  Eigen::Vector3d upDirection() const;
  // Corners in reading order: top-left, top-right, bottom-right, bottom-left.
  std::array<Eigen::Vector3d, 4> corners() const;
};

}  // namespace parkloc::map
