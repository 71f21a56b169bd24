#include "mapping/stencil_height.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace parkloc::mapping {

std::vector<std::string> applyStencilHeight(std::vector<LandmarkEstimate>& landmarks,
                                            const StencilOptions& options) {
  std::vector<std::string> set;
  if (!(options.tolerance > 0.0)) return set;
  std::map<map::TextClass, std::vector<double>> heights;
  for (const LandmarkEstimate& l : landmarks) heights[l.cls].push_back(l.parameters[kHeight]);
  for (auto& [cls, h] : heights) {
    if (h.size() < static_cast<size_t>(std::max(1, options.min_landmarks))) continue;
    const size_t mid = h.size() / 2;
    std::nth_element(h.begin(), h.begin() + mid, h.end());
    double median = h[mid];
    if (h.size() % 2 == 0) median = 0.5 * (median + *std::max_element(h.begin(), h.begin() + mid));
    for (LandmarkEstimate& l : landmarks) {
      if (l.cls != cls) continue;
      if (std::fabs(l.parameters[kHeight] / median - 1.0) <= options.tolerance) continue;
      l.parameters[kHeight] = median;
      set.push_back(l.text);
    }
  }
  return set;
}

}  // namespace parkloc::mapping
