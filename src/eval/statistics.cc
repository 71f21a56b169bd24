#include "eval/statistics.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace parkloc::eval {
namespace {

// Percentile of an already sorted, non-empty sample.
double sortedPercentile(const std::vector<double>& sorted, double p) {
  const double rank = std::clamp(p, 0.0, 100.0) / 100.0 * static_cast<double>(sorted.size() - 1);
  const size_t lower = static_cast<size_t>(std::floor(rank));
  const size_t upper = std::min(lower + 1, sorted.size() - 1);
  const double fraction = rank - static_cast<double>(lower);
  return sorted[lower] + fraction * (sorted[upper] - sorted[lower]);
}

}  // namespace

double percentile(std::vector<double> values, double p) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  return sortedPercentile(values, p);
}

Summary summarize(const std::vector<double>& values) {
  Summary s;
  if (values.empty()) return s;
  std::vector<double> sorted = values;
  std::sort(sorted.begin(), sorted.end());
  const double n = static_cast<double>(sorted.size());
  s.count = sorted.size();
  s.mean = std::accumulate(sorted.begin(), sorted.end(), 0.0) / n;
  double squares = 0.0, deviations = 0.0;
  for (double v : sorted) {
    squares += v * v;
    deviations += (v - s.mean) * (v - s.mean);
  }
  s.rmse = std::sqrt(squares / n);
  s.std = std::sqrt(deviations / n);
  s.min = sorted.front();
  s.max = sorted.back();
  s.median = sortedPercentile(sorted, 50.0);
  s.p95 = sortedPercentile(sorted, 95.0);
  s.p99 = sortedPercentile(sorted, 99.0);
  return s;
}

}  // namespace parkloc::eval
