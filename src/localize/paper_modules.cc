#include "localize/paper_modules.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace parkloc::localize {
namespace {

// Shoelace formula: the area of a quad, pixels^2.
double polygonArea(const std::array<Eigen::Vector2d, 4>& q) {
  double a = 0.0;
  for (int i = 0; i < 4; ++i) {
    const auto& p = q[i];
    const auto& n = q[(i + 1) % 4];
    a += 0.5 * (p.x() * n.y() - p.y() * n.x());
  }
  return std::abs(a);
}

}  // namespace

BoxPlotFilterOptions afmOptions(const PaperModuleOptions& options) {
  BoxPlotFilterOptions afm;
  afm.queue_length = static_cast<size_t>(std::max(1, options.afm_queue_length));
  afm.iqr_factor = options.afm_iqr_factor;
  afm.reset_after_rejections = static_cast<size_t>(std::max(0, options.afm_reset_after_rejections));
  return afm;
}

std::vector<LandmarkObservation> selectForModules(std::vector<LandmarkObservation> obs,
                                                  const PaperModuleOptions& options) {
  if (!options.mcrp) {
    std::vector<LandmarkObservation> kept;
    for (const auto& o : obs) {
      bool seen = false;
      for (const auto& k : kept) seen = seen || k.landmark_id == o.landmark_id;
      if (!seen) kept.push_back(o);
    }
    obs = std::move(kept);
  }
  if (!options.mcap && !obs.empty()) {
    size_t best = 0;
    for (size_t i = 1; i < obs.size(); ++i)
      if (polygonArea(obs[i].pixels) > polygonArea(obs[best].pixels)) best = i;
    const std::string id = obs[best].landmark_id;
    std::vector<LandmarkObservation> kept;
    for (const auto& o : obs)
      if (o.landmark_id == id) kept.push_back(o);
    obs = std::move(kept);
  }
  return obs;
}

}  // namespace parkloc::localize
