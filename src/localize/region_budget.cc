#include "localize/region_budget.h"

#include <algorithm>
#include <tuple>

namespace parkloc::localize {

std::vector<std::vector<size_t>> selectRegionsWithinBudget(
    const std::vector<std::vector<RegionCandidate>>& per_camera,
    const std::map<std::string, int>& last_asked, int frame_index,
    const RegionBudgetOptions& options) {
  const size_t cameras = per_camera.size();
  std::vector<std::vector<size_t>> chosen(cameras);
  if (options.max_regions <= 0) {
    for (size_t c = 0; c < cameras; ++c)
      for (size_t i = 0; i < per_camera[c].size(); ++i) chosen[c].push_back(i);
    return chosen;
  }
  // Rank: a large (near) text measures the pose best; a landmark not asked for lately
  // gains weight with every frame it waits, so the budget goes round the landmarks.
  struct Ranked {
    double score;
    size_t camera;
    size_t index;
  };
  std::vector<std::vector<Ranked>> ranked(cameras);
  for (size_t c = 0; c < cameras; ++c) {
    for (size_t i = 0; i < per_camera[c].size(); ++i) {
      const RegionCandidate& r = per_camera[c][i];
      if (r.height_px < options.min_height_px) continue;
      int age = options.max_age_frames;
      if (const auto it = last_asked.find(r.landmark_id); it != last_asked.end())
        age = std::clamp(frame_index - it->second, 0, options.max_age_frames);
      const double size = std::min(r.size_px, options.max_rank_size_px);
      ranked[c].push_back({size * (1.0 + age), c, i});
    }
    std::stable_sort(ranked[c].begin(), ranked[c].end(),
                     [](const Ranked& a, const Ranked& b) { return a.score > b.score; });
  }
  // First pass: the best region of each camera that sees something, cameras in turn from
  // `first_camera`, so a small budget still rotates over the cameras.
  int left = options.max_regions;
  std::vector<Ranked> rest;
  const size_t first =
      cameras ? static_cast<size_t>(std::max(options.first_camera, 0)) % cameras : 0;
  for (size_t k = 0; k < cameras; ++k) {
    const size_t c = (first + k) % cameras;
    if (ranked[c].empty()) continue;
    if (left > 0) {
      chosen[c].push_back(ranked[c].front().index);
      --left;
      rest.insert(rest.end(), ranked[c].begin() + 1, ranked[c].end());
    } else {
      rest.insert(rest.end(), ranked[c].begin(), ranked[c].end());
    }
  }
  // Second pass: what is left of the budget to the best remaining regions, any camera.
  std::stable_sort(rest.begin(), rest.end(),
                   [](const Ranked& a, const Ranked& b) { return a.score > b.score; });
  for (size_t k = 0; k < rest.size() && left > 0; ++k, --left)
    chosen[rest[k].camera].push_back(rest[k].index);
  for (auto& c : chosen) std::sort(c.begin(), c.end());
  return chosen;
}

}  // namespace parkloc::localize
