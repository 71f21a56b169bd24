#pragma once
// Rig calibration as OpenCV FileStorage YAML (one file per rig). See README "File formats".
#include <string>

#include "geometry/rig.h"

namespace parkloc::io {

// Reads and validates a rig calibration. Throws InputError with one line naming the file,
// camera and field: missing field, wrong matrix size, non-finite value, unknown model,
// duplicate camera name.
geometry::Rig loadCalibration(const std::string& path);

void saveCalibration(const geometry::Rig& rig, const std::string& path);

}  // namespace parkloc::io
