#include "map/landmark.h"

#include <cmath>
#include <sstream>

namespace parkloc::map {

std::string toString(TextClass cls) {
  switch (cls) {
    case TextClass::kPillar:
      return "pillar";
    case TextClass::kParkingNumber:
      return "parking_number";
    case TextClass::kOther:
      return "other";
  }
  return "other";
}

std::optional<TextClass> textClassFromString(const std::string& name) {
  if (name == "pillar") return TextClass::kPillar;
  if (name == "parking_number") return TextClass::kParkingNumber;
  if (name == "other") return TextClass::kOther;
  return std::nullopt;
}

std::string toString(Surface surface) {
  return surface == Surface::kGround ? "ground" : "vertical";
}

std::optional<Surface> surfaceFromString(const std::string& name) {
  if (name == "ground") return Surface::kGround;
  if (name == "vertical") return Surface::kVertical;
  return std::nullopt;
}

Eigen::Vector3d Landmark::readingDirection() const {
  return {std::cos(heading), std::sin(heading), 0.0};
}

Eigen::Vector3d Landmark::upDirection() const {
  // Seen from above, the top of ground text lies 90 degrees counter-clockwise of its
  // reading direction; vertical text reads upright.
  if (surface == Surface::kGround) return {-std::sin(heading), std::cos(heading), 0.0};
  return Eigen::Vector3d::UnitZ();
}

std::array<Eigen::Vector3d, 4> Landmark::corners() const {
  const Eigen::Vector3d r = 0.5 * width * readingDirection();
  const Eigen::Vector3d u = 0.5 * height * upDirection();
  return {position - r + u, position + r + u, position + r - u, position - r - u};
}

namespace {
std::string sigmaProblem(const char* name, const std::optional<double>& sigma, double bound,
                         const char* unit) {
  if (!sigma) return "";
  if (!std::isfinite(*sigma) || *sigma < 0.0 || *sigma > bound) {
    std::ostringstream out;
    out << name << ": " << *sigma << " is not a sigma in [0, " << bound << "] " << unit;
    return out.str();
  }
  return "";
}
}  // namespace

std::string accuracyProblem(const MapAccuracy& accuracy) {
  if (std::string p = sigmaProblem("position_sigma", accuracy.position_sigma, kMaxPositionSigmaM,
                                   "m");
      !p.empty())
    return p;
  return sigmaProblem("heading_sigma", accuracy.heading_sigma, kMaxHeadingSigmaRad, "rad");
}

}  // namespace parkloc::map
