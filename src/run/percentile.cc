#include "run/percentile.h"

#include <algorithm>
#include <cstddef>

namespace parkloc::run {

double sortedPercentile(const std::vector<double>& sorted, double fraction) {
  const double position = std::clamp(fraction, 0.0, 1.0) * static_cast<double>(sorted.size() - 1);
  const size_t below = static_cast<size_t>(position);
  const size_t above = std::min(below + 1, sorted.size() - 1);
  return sorted[below] + (position - static_cast<double>(below)) * (sorted[above] - sorted[below]);
}

double percentile(std::vector<double> values, double fraction) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  return sortedPercentile(values, fraction);
}

}  // namespace parkloc::run
