#pragma once
// Summary statistics of a sample (errors, latencies), as the evo tool reports them for the
// absolute pose error (mean, median, RMSE, std, min, max) plus the 95th and 99th percentiles.
#include <cstddef>
#include <vector>

namespace parkloc::eval {

struct Summary {
  size_t count = 0;
  double mean = 0.0;
  double median = 0.0;
  double rmse = 0.0;
  double std = 0.0;  // population standard deviation, as numpy (and evo) compute it
  double min = 0.0;
  double max = 0.0;
  double p95 = 0.0;
  double p99 = 0.0;
};

// Percentile with linear interpolation between the closest ranks (numpy's default), `p` in
// [0, 100]. Returns 0 for an empty sample.
double percentile(std::vector<double> values, double p);

// All zeros for an empty sample.
Summary summarize(const std::vector<double>& values);

}  // namespace parkloc::eval
