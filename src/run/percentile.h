#pragma once
// A sample's percentile, for the runner's figures (latency, pose age, error) and the
// evaluation's (eval/statistics.h).
#include <vector>

namespace parkloc::run {

// Linear interpolation between the closest ranks (numpy's default), `fraction` clamped to
// [0, 1], of an already sorted, non-empty sample.
double sortedPercentile(const std::vector<double>& sorted, double fraction);

// The same of any sample; 0 for an empty one.
double percentile(std::vector<double> values, double fraction);

}  // namespace parkloc::run
