#pragma once
// TUM trajectory files: one pose per line, "timestamp tx ty tz qx qy qz qw", timestamps
// in seconds (parkloc uses seconds as double everywhere). Lines starting with '#' are
// comments. Loads in the evo tool.
#include <string>
#include <vector>

#include "geometry/pose.h"

namespace parkloc::io {

struct StampedPose {
  double timestamp = 0.0;
  geometry::Rigid3 pose = geometry::Rigid3::Identity();
};

std::vector<StampedPose> loadTum(const std::string& path);  // throws InputError
void saveTum(const std::vector<StampedPose>& poses, const std::string& path);

}  // namespace parkloc::io
