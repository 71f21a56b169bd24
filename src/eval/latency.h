#pragma once
// Latency statistics per pipeline stage and for the whole frame set, in milliseconds.
#include <chrono>
#include <map>
#include <string>
#include <vector>

#include "eval/statistics.h"

namespace parkloc::eval {

// One frame set's timings: milliseconds per named stage (e.g. "detect", "recognize",
// "localize") and the total wall time of the frame set.
struct FrameTiming {
  double total_ms = 0.0;
  std::map<std::string, double> stage_ms;
  // Off the critical path: the workers' time on the full frames and reads whose texts were
  // fused in this frame set (localize/search_worker.h); 0: none were.
  double worker_ms = 0.0;
};

struct LatencyReport {
  Summary total_ms;
  // A stage missing from a frame counts as 0 ms there (it did not run).
  std::map<std::string, Summary> stage_ms;
  std::map<std::string, std::vector<double>> samples_ms;  // for histograms; "total" included
  // The workers' time per frame set that fused their texts (empty: no worker).
  Summary worker_ms;
  std::vector<double> worker_samples_ms;
};

LatencyReport latencyReport(const std::vector<FrameTiming>& frames);

// Wall-clock milliseconds since `start`.
inline double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace parkloc::eval
