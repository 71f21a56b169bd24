#pragma once
// Condition subsets of the paper's Table 8: bright light, weak light and blur are properties
// of a whole sequence (its meta.json), text rotation of about 45, 90 or 180 degrees is a
// property of each labelled instance.
#include <optional>
#include <string>
#include <vector>

#include "io/sequence_conditions.h"

namespace parkloc::eval {

// Subset names, in the order the paper's Table 8 lists them.
inline const std::vector<std::string>& conditionNames() {
  static const std::vector<std::string> names = {"bright", "weak_light", "blur",
                                                 "rot45",  "rot90",      "rot180"};
  return names;
}
std::string conditionTitle(const std::string& name);  // "weak_light" -> "Weak light"

// Sequence-level conditions of meta.json (io/sequence_conditions.h), in these names.
using io::sequenceConditions;

// The rotation subset of a text whose reading direction is at `rotation_deg` in the image,
// with the simulator's bins (sim/dataset_writer.h): |rotation| in [30, 60) is "rot45",
// [60, 120] "rot90", [150, 180] "rot180", anything else none.
std::optional<std::string> rotationSubset(double rotation_deg);

}  // namespace parkloc::eval
