#include "eval/conditions.h"

#include <cmath>

namespace parkloc::eval {

std::string conditionTitle(const std::string& name) {
  if (name == "bright") return "Bright light";
  if (name == "weak_light") return "Weak light";
  if (name == "blur") return "Blur";
  if (name == "rot45") return "45 deg rotation";
  if (name == "rot90") return "90 deg rotation";
  if (name == "rot180") return "180 deg rotation";
  return name;
}

std::optional<std::string> rotationSubset(double rotation_deg) {
  double a = std::fabs(std::remainder(rotation_deg, 360.0));  // [0, 180]
  if (a >= 30.0 && a < 60.0) return "rot45";
  if (a >= 60.0 && a <= 120.0) return "rot90";
  if (a >= 150.0) return "rot180";
  return std::nullopt;
}

}  // namespace parkloc::eval
