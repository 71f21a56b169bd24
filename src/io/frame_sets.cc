#include "io/frame_sets.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

namespace parkloc::io {

double frameSetTolerance(const std::map<std::string, std::vector<double>>& times) {
  double smallest = std::numeric_limits<double>::infinity();
  for (const auto& [camera, t] : times) {
    if (t.size() < 2) continue;
    std::vector<double> intervals;
    for (size_t i = 1; i < t.size(); ++i) intervals.push_back(t[i] - t[i - 1]);
    std::nth_element(intervals.begin(), intervals.begin() + intervals.size() / 2, intervals.end());
    smallest = std::min(smallest, intervals[intervals.size() / 2]);
  }
  return std::isfinite(smallest) ? 0.45 * smallest : 1e-6;
}

std::vector<FrameSet> groupFrameSets(const std::map<std::string, std::vector<double>>& times,
                                     double tolerance) {
  // The pacing camera: the most images (the first by name on a tie).
  const std::string* pace = nullptr;
  for (const auto& [camera, t] : times)
    if (!pace || t.size() > times.at(*pace).size()) pace = &camera;
  if (!pace) return {};
  const std::vector<double>& pace_times = times.at(*pace);
  std::vector<FrameSet> sets(pace_times.size());
  for (size_t i = 0; i < pace_times.size(); ++i) sets[i].images[*pace] = i;

  // The others join the pacing set nearest in time (the nearer of two images of one camera).
  std::vector<std::tuple<double, std::string, size_t>> left_over;
  for (const auto& [camera, t] : times) {
    if (camera == *pace) continue;
    for (size_t k = 0; k < t.size(); ++k) {
      const auto after = std::lower_bound(pace_times.begin(), pace_times.end(), t[k]);
      size_t s = static_cast<size_t>(after - pace_times.begin());
      if (after == pace_times.end() ||
          (after != pace_times.begin() && t[k] - *(after - 1) < *after - t[k]))
        --s;
      if (std::abs(t[k] - pace_times[s]) > tolerance) {
        left_over.emplace_back(t[k], camera, k);
        continue;
      }
      const auto taken = sets[s].images.find(camera);
      if (taken == sets[s].images.end()) {
        sets[s].images[camera] = k;
      } else if (std::abs(t[k] - pace_times[s]) < std::abs(t[taken->second] - pace_times[s])) {
        left_over.emplace_back(t[taken->second], camera, taken->second);
        taken->second = k;
      } else {
        left_over.emplace_back(t[k], camera, k);
      }
    }
  }
  // Images that joined no set: sets among themselves, each spanning at most 2 x tolerance.
  std::sort(left_over.begin(), left_over.end());
  std::vector<FrameSet> extra;
  double start = 0.0;
  for (const auto& [t, camera, k] : left_over) {
    if (extra.empty() || t - start > 2.0 * tolerance || extra.back().images.count(camera)) {
      extra.emplace_back();
      start = t;
    }
    extra.back().images[camera] = k;
  }
  sets.insert(sets.end(), extra.begin(), extra.end());
  for (FrameSet& set : sets) {
    set.timestamp = std::numeric_limits<double>::infinity();
    for (const auto& [camera, k] : set.images)
      set.timestamp = std::min(set.timestamp, times.at(camera)[k]);
  }
  std::stable_sort(sets.begin(), sets.end(), [](const FrameSet& a, const FrameSet& b) {
    return a.timestamp < b.timestamp;
  });
  return sets;
}

}  // namespace parkloc::io
