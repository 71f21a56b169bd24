#pragma once
// Which rig a dataset is recorded with: any calibration of 2 to 6 fisheye or pinhole cameras
// of any image size, named on the command line or in the scenario, else the default rig.
#include "geometry/rig.h"
#include "sim/dataset_writer.h"
#include "sim/scenario.h"

namespace parkloc::sim {

// `options.rig`, else the scenario's calibration file (Scenario::rig), else the default rig.
// Throws InputError for a rig the simulator does not render: fewer than 2 or more than 6
// cameras, or an image side outside 64 to 4096 pixels; IoError / InputError from the file.
geometry::Rig datasetRig(const Scenario& scenario, const DatasetOptions& options);

}  // namespace parkloc::sim
