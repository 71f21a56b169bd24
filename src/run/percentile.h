#pragma once
// A sample's percentile for the runner's figures (latency, pose age, error).
#include <vector>

namespace parkloc::run {

// Linear interpolation between the closest ranks (numpy's default), `fraction` in [0, 1];
// 0 for an empty sample.
double percentile(std::vector<double> values, double fraction);

}  // namespace parkloc::run
