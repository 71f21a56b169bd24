#include "eval/statistics.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

#include "run/percentile.h"

namespace parkloc::eval {
namespace {

// Percentile `p` in [0, 100] of an already sorted, non-empty sample.
double sortedPercentile(const std::vector<double>& sorted, double p) {
  return run::sortedPercentile(sorted, p / 100.0);
}

}  // namespace

double percentile(std::vector<double> values, double p) {
  return run::percentile(std::move(values), p / 100.0);
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
