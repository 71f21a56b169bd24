#include "mapping/map_merge.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>

#include "common/error.h"
#include "mapping/anchor_fit.h"

namespace parkloc::mapping {
namespace {

// Inverse-variance mean of two estimates of one value; `a` alone when either has no sigma.
double fuse(double a, const std::optional<double>& sa, double b, const std::optional<double>& sb) {
  if (!sa || !sb || *sa <= 0.0 || *sb <= 0.0) return a;
  const double wa = 1.0 / (*sa * *sa), wb = 1.0 / (*sb * *sb);
  return (wa * a + wb * b) / (wa + wb);
}

}  // namespace

MapMerge mergeMaps(const map::HdMap& existing, std::vector<LandmarkEstimate>& built,
                   const std::string& level, const MergeOptions& options) {
  // Matches by text: built index -> existing landmark.
  std::vector<std::pair<size_t, const map::Landmark*>> matches;
  for (size_t i = 0; i < built.size(); ++i) {
    const auto found = existing.findByText(built[i].text, level);
    if (found.size() == 1) matches.emplace_back(i, found.front());
  }
  std::vector<bool> inlier(matches.size(), true);
  std::optional<geometry::PlanarFit> fit;
  // Fit, then refit without the matches that stay beyond the threshold, until none drops.
  for (int round = 0; round < 5; ++round) {
    std::vector<Eigen::Vector2d> from, to;
    for (size_t m = 0; m < matches.size(); ++m)
      if (inlier[m]) {
        from.emplace_back(built[matches[m].first].parameters[kX],
                          built[matches[m].first].parameters[kY]);
        to.push_back(matches[m].second->position.head<2>());
      }
    fit = geometry::fitPlanar(from, to, /*with_scale=*/false);
    if (!fit) break;
    // Drop the worst match beyond the threshold, one a round: a moved landmark pulls the
    // fit towards itself, so its neighbours may look off until it is gone.
    double worst = options.moved_threshold_m;
    std::optional<size_t> drop;
    for (size_t m = 0; m < matches.size(); ++m) {
      if (!inlier[m]) continue;
      const LandmarkEstimate& b = built[matches[m].first];
      const double d =
          (fit->apply({b.parameters[kX], b.parameters[kY]}) - matches[m].second->position.head<2>())
              .norm();
      if (d > worst) {
        worst = d;
        drop = m;
      }
    }
    if (!drop) break;
    inlier[*drop] = false;
  }
  if (!fit)
    throw InputError(fmt::format(
        "merge: {} built landmark(s) are in the existing map at places that agree, 2 are needed",
        std::count(inlier.begin(), inlier.end(), true)));

  MapMerge out;
  out.fit = *fit;
  for (LandmarkEstimate& b : built) applyFit(out.fit, b);
  std::map<std::string, size_t> matched_by_id;  // existing id -> built index
  for (const auto& [i, existing_landmark] : matches) matched_by_id[existing_landmark->id] = i;
  for (const map::Landmark& e : existing.landmarks()) {
    const auto it = matched_by_id.find(e.id);
    if (it == matched_by_id.end()) {
      ++out.kept_unseen;
      out.landmarks.push_back(e);
      continue;
    }
    LandmarkEstimate& b = built[it->second];
    const double d =
        (Eigen::Vector2d(b.parameters[kX], b.parameters[kY]) - e.position.head<2>()).norm();
    map::Landmark merged = e;
    if (d > options.moved_threshold_m) {
      b.moved_m = d;
      out.moved.push_back(b.text);
      const map::Landmark seen = b.toLandmark(e.level);
      merged.position.head<2>() = seen.position.head<2>();
      merged.heading = seen.heading;
      merged.accuracy = seen.accuracy;
    } else {
      ++out.confirmed;
      for (int k = 0; k < 2; ++k)
        merged.position[k] =
            fuse(e.position[k], e.accuracy.position_sigma, b.parameters[k], b.position_sigma);
    }
    out.landmarks.push_back(merged);
  }
  for (LandmarkEstimate& b : built) {
    if (!existing.findByText(b.text, level).empty()) continue;
    b.added = true;
    out.added.push_back(b.text);
    out.landmarks.push_back(b.toLandmark(level));
  }
  return out;
}

}  // namespace parkloc::mapping
