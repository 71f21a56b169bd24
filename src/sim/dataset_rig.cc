#include "sim/dataset_rig.h"

#include <fmt/format.h>

#include "common/error.h"
#include "io/calibration_yaml.h"

namespace parkloc::sim {

geometry::Rig datasetRig(const Scenario& scenario, const DatasetOptions& options) {
  const std::string source = options.rig ? std::string("the given rig")
                             : scenario.rig.empty() ? std::string("the default rig")
                                                    : scenario.rig;
  const geometry::Rig rig = options.rig          ? *options.rig
                            : scenario.rig.empty() ? geometry::defaultRig()
                                                   : io::loadCalibration(scenario.rig);
  // A surround view needs two cameras at least; production surround-view rigs have four to
  // six, and the range bounds the render time of a frame set.
  if (rig.cameras.size() < 2 || rig.cameras.size() > 6)
    throw InputError(fmt::format("simulate: {} has {} camera{}; the simulator renders 2 to 6",
                                 source, rig.cameras.size(), rig.cameras.size() == 1 ? "" : "s"));
  for (const auto& camera : rig.cameras) {
    const auto& m = camera.model;
    if (m.width < 64 || m.height < 64 || m.width > 4096 || m.height > 4096)
      throw InputError(fmt::format("simulate: {} camera '{}': image {}x{} outside 64 to 4096 px",
                                   source, camera.name, m.width, m.height));
  }
  return rig;
}

}  // namespace parkloc::sim
