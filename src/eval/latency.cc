#include "eval/latency.h"

#include <set>

namespace parkloc::eval {

LatencyReport latencyReport(const std::vector<FrameTiming>& frames) {
  std::set<std::string> stages;
  for (const FrameTiming& f : frames) {
    for (const auto& [stage, ms] : f.stage_ms) stages.insert(stage);
  }
  LatencyReport report;
  std::vector<double>& total = report.samples_ms["total"];
  for (const FrameTiming& f : frames) {
    total.push_back(f.total_ms);
    for (const std::string& stage : stages) {
      const auto it = f.stage_ms.find(stage);
      report.samples_ms[stage].push_back(it == f.stage_ms.end() ? 0.0 : it->second);
    }
  }
  report.total_ms = summarize(total);
  for (const FrameTiming& f : frames)
    if (f.worker_ms > 0.0) report.worker_samples_ms.push_back(f.worker_ms);
  if (!report.worker_samples_ms.empty()) report.worker_ms = summarize(report.worker_samples_ms);
  for (const std::string& stage : stages) {
    report.stage_ms[stage] = summarize(report.samples_ms[stage]);
  }
  return report;
}

}  // namespace parkloc::eval
